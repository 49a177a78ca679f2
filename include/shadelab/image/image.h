// Images: 8-bit RGBA (what a PNG holds) and float RGBA (what stress tests and the reference produce),
// PNG I/O that never leaves a half-written file, and the comparison used by the image tests.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace shadelab {

// Rows top to bottom, 4 bytes per pixel (R, G, B, A). Alpha is coverage: 255 where an object was drawn,
// 0 on the background.
struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;

    Image() = default;
    Image(int w, int h);
    std::uint8_t* pixel(int x, int y) { return &rgba[(std::size_t(y) * width + x) * 4]; }
    const std::uint8_t* pixel(int x, int y) const { return &rgba[(std::size_t(y) * width + x) * 4]; }
};

// Rows top to bottom, linear colour, 4 floats per pixel.
struct ImageF {
    int width = 0, height = 0;
    std::vector<float> rgba;

    ImageF() = default;
    ImageF(int w, int h);
    float* pixel(int x, int y) { return &rgba[(std::size_t(y) * width + x) * 4]; }
    const float* pixel(int x, int y) const { return &rgba[(std::size_t(y) * width + x) * 4]; }
};

// round(clamp(c, 0, 1)·255), NaN → 0: the one float → 8-bit conversion (GL's unorm rule).
std::uint8_t toUnorm8(double c);
Image toImage8(const ImageF& image);

// The PNG file writePng writes, as bytes in memory.
std::string encodePng(const Image& image);
// Decodes a complete PNG held in memory (signature, every row, and the closing IEND chunk) as readPng does.
// Throws RuntimeError "<what>: <reason>" for anything truncated or corrupt.
Image decodePng(std::string_view bytes, std::string_view what);
// The width and height a PNG's header (IHDR) claims, read without decoding anything; nullopt if the bytes
// do not start as a PNG.
struct PngSize {
    std::uint32_t width = 0, height = 0;
};
std::optional<PngSize> pngSize(std::string_view bytes);

// Counts the non-finite values and the values outside [lo, hi] in a float image.
struct ValueScan {
    std::size_t nonFinite = 0, outOfRange = 0;
};
ValueScan scanValues(const ImageF& image, float lo = 0.0f, float hi = 1.0f);

// Regression comparison of two 8-bit images of the same size.
struct Tolerance {
    int maxDelta = 0;      // largest per-channel difference allowed outside the outlier budget
    double meanDelta = 0;  // largest mean per-channel difference over the whole image
    int outlierBudget = 0; // pixels allowed to exceed maxDelta (silhouette pixels)
    // Alpha's difference joins each pixel's largest difference (so --max and the outliers), while the mean
    // stays the colour channels' (an opaque pair's figures are the same either way). Off for the image
    // tests: a GL read-back's alpha is coverage and their references are RGB; on for `shadelab compare`,
    // where a transparent image must not pass for an opaque one.
    bool compareAlpha = false;
};
struct Comparison {
    bool sizeMatches = true;
    int actualWidth = 0, actualHeight = 0, expectedWidth = 0, expectedHeight = 0;
    int maxDelta = 0;
    double meanDelta = 0;                       // over the compared pixels
    int outliers = 0;                           // pixels with a channel difference > tolerance.maxDelta
    std::size_t comparedPixels = 0, pixels = 0; // fewer compared than there are when a mask leaves some out
    bool passed = false;
    Tolerance tolerance; // the limits this was judged against, for summary()
    std::string summary() const;
};
// Per-channel differences of the colour channels (alpha in the max with tolerance.compareAlpha). With a
// `mask` of the same size, pixels that are black in it are not compared: they count in no figure, the mean
// included.
Comparison compareImages(const Image& actual, const Image& expected, const Tolerance& tolerance,
                         const Image* mask = nullptr);
// |actual − expected| per channel, amplified ×8 and clamped, opaque; for looking at a failure. With
// `withAlpha`, each colour channel shows the larger of its own and alpha's difference (an alpha-only
// difference is then seen). Pixels black in `mask` (same size as both images) were not compared: they are
// drawn dark grey (kDiffLeftOut), so a difference there does not look like a failure.
inline constexpr glm::u8vec4 kDiffLeftOut{64, 64, 64, 255};
Image diffImage(const Image& actual, const Image& expected, const Image* mask = nullptr,
                bool withAlpha = false);

// Places `tile` into `canvas` with its top-left corner at (x, y), clipped to the canvas.
void blit(Image& canvas, const Image& tile, int x, int y);
void fillRect(Image& canvas, int x, int y, int w, int h, glm::u8vec4 color);
// Draws UTF-8 text (DejaVu Sans Mono Bold through stb_truetype, antialiased, blended over the canvas) in
// a line textLineHeight(scale) pixels high whose top is at y; clipped to the canvas. `scale` 1 is a
// line of 11 px; larger scales are clamped to kMaxTextScale. A character the font lacks draws its box.
inline constexpr int kMaxTextScale = 64;
void drawText(Image& canvas, int x, int y, std::string_view text, int scale, glm::u8vec4 color);
int textWidth(std::string_view text, int scale); // the pen's advance over the text, in pixels
// The characters of UTF-8 `text` the font has no glyph for (drawText draws each as the font's empty box),
// each once, in order; line breaks are no glyphs and never missing.
std::vector<char32_t> missingGlyphs(std::string_view text);
std::string fontName(); // the embedded font's name, for a message
int textLineHeight(int scale);

} // namespace shadelab
