// What a picture shows over it for a class (docs/lecturers.md "Presenting"): presentation mode's label and a
// lesson step's band, as images. The window, the page and `shadelab slides` draw the same images, so the
// three look alike; nothing here knows the demo's state (the label's facts come from the drawn scene).
#pragma once

#include <optional>
#include <string>

#include "shadelab/image/image.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app {

// What the label says, as values: the window remakes its label only when these change.
struct PresentationFacts {
    ShadingMode shading = ShadingMode::Phong;
    bool normalsByM = false, unnegated = false;
    LightingModel lighting = LightingModel::BlinnPhong;
    LightingTerm term = LightingTerm::All;
    int level = 0;
    std::optional<double> shininess; // the first object's; none without objects
    bool operator==(const PresentationFacts&) const = default;
};
PresentationFacts presentationFacts(const Scene& drawn); // drawn: DemoState::drawn()
// Presentation mode's label, large enough for the back of a classroom: "PHONG SHADING", "BLINN-PHONG
// LIGHTING" and "LEVEL 5 | BETA = 96" on three lines (ALPHA under Phong lighting; the first object's
// exponent; RAY-CAST instead of the level in exact mode). ASCII, upper case, as it has always read.
std::string presentationLabel(const PresentationFacts& facts);
// The label as the window and the page both draw it over the bottom left of a picture of width × height:
// DejaVu Sans Mono Bold on a translucent dark box, its lines as tall as a twelfth of the picture's height
// (55 px at 720) or smaller where the widest line would not fit the width, so it is never clipped; the
// same picture size always gives the same image. `margin` is the gap to the picture's left and bottom.
struct PresentationLabelImage {
    Image image;
    int margin = 0;
};
PresentationLabelImage presentationLabelImage(const std::string& label, int width, int height);
// A lesson step's title and caption as the window, the page and `shadelab slides` draw them across the bottom
// of a picture of width × height: a translucent dark band as wide as the picture, the title in lines an
// eighteenth of the height and the caption's a thirtieth, each to the nearest 11 px (55 and 33 px at 1080,
// 44 and 22 at 720), the caption's lines as written and wrapped at spaces to the width (a word too long for
// a line is cut between characters). Both sizes step down until the band is at most 40 % of the height; the
// same text and size give the same image.
// Drawn at (0, height − image.height); an empty image for a width or height under 1.
Image lessonBandImage(const std::string& title, const std::string& caption, int width, int height);

} // namespace shadelab::app
