// One way in for every value: each scene value that a command-line flag can also set has one
// range and one function that checks it, and every door calls that function — the scene's JSON
// (parseScene), a scene built or changed in code (validateScene) and the flags (src/scene/scene_flags.cpp,
// and through them the demo and the page). A door parses only its own syntax (a JSON number, "WxH", a
// decimal) and names the field: a JSON path ("image.width") or a flag ("--size width"). A refusal is an
// InputError "<field>: must be ..., got <value>", in the same words whichever door the value came through.
//
//   scene file                         flag                                 the one check
//   image.width, image.height          --size WxH                           checkImageSize
//   objects[i].subdivisions            --subdivisions                       checkSubdivisionLevel (sphere.h)
//   tolerance_px                       --tolerance-px                       checkTolerancePx
//   view                               --view                               parseViewOrThrow
//   shading, lighting, depth, overlay  --shading, --lighting, ...           parseNameOrThrow (vocabulary.h)
#pragma once

#include <string>
#include <string_view>

#include "shadelab/geometry/sphere.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/view.h"

namespace shadelab {

struct IntRange {
    int lo, hi; // inclusive
};
inline constexpr IntRange kImageSizeRange{1, kMaxImageSize};
inline constexpr IntRange kSubdivisionRange{0, kMaxSubdivisions}; // "auto" is a word, not a level
// "1..16384": the range as a syntax message quotes it ("--size: expected WxH with W and H in 1..16384").
std::string toString(IntRange range);

// One side of the image in pixels: "image.width: must be between 1 and 16384, got 0".
void checkImageSize(int pixels, std::string_view field);
// The silhouette error "auto" subdivision allows, in pixels: finite and > 0.
void checkTolerancePx(double pixels, std::string_view field);
// parseView (view.h), refused as `<field>: "<text>": <reason>` with the text quoted by quotedValue.
View parseViewOrThrow(std::string_view text, std::string_view field);
// A number written too large for a double ("1e400"), which would be infinite: "<field>: must be finite, got
// 1e400", `written` cut at kMaxQuotedChars. Parsing the number is the door's part; the refusal is shared.
[[noreturn]] void failNotFinite(std::string_view field, std::string_view written);

} // namespace shadelab
