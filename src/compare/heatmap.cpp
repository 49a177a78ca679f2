// A per-pixel map drawn for people: viridis (van der Walt & Smith, matplotlib 2.0's default colour map),
// whose lightness rises steadily from low to high and which reads the same under the common colour-vision
// deficiencies and in greyscale, under the picture a scale bar with its label and the values at its ends.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "shadelab/compare/metrics.h"

namespace shadelab {

namespace {

// viridis at 17 evenly spaced points, rounded to 8 bits (matplotlib 3.6's cm.viridis at i/16); interpolated
// linearly between them, which stays within 5 levels of its 256-entry table.
constexpr std::array<std::array<int, 3>, 17> kViridisStops{{
    {68, 1, 84},
    {72, 24, 106},
    {71, 45, 123},
    {66, 64, 134},
    {59, 82, 139},
    {51, 99, 141},
    {44, 114, 142},
    {38, 130, 142},
    {33, 145, 140},
    {31, 160, 136},
    {40, 174, 128},
    {63, 188, 115},
    {94, 201, 98},
    {132, 212, 75},
    {173, 220, 48},
    {216, 226, 25},
    {253, 231, 37},
}};
constexpr glm::u8vec4 kHeatmapLeftOut{128, 128, 128, 255}; // a pixel the comparison left out
constexpr glm::u8vec4 kHeatmapPanel{32, 32, 32, 255};      // behind the scale
constexpr glm::u8vec4 kHeatmapText{235, 235, 235, 255};
constexpr int kHeatmapGap = 4, kHeatmapBarHeight = 10;

std::string heatmapNumber(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", double(value));
    return text;
}

} // namespace

glm::u8vec4 heatmapColour(double t) {
    if (!(t > 0)) t = 0; // NaN and below the range
    t = std::min(t, 1.0);
    const double position = t * double(kViridisStops.size() - 1);
    const auto below = std::min(std::size_t(position), kViridisStops.size() - 2);
    const double f = position - double(below);
    glm::u8vec4 colour{0, 0, 0, 255};
    for (int c = 0; c < 3; ++c)
        colour[c] = std::uint8_t(std::lround((1 - f) * kViridisStops[below][std::size_t(c)] +
                                             f * kViridisStops[below + 1][std::size_t(c)]));
    return colour;
}

Image heatmap(const MetricMap& map, float low, float high, std::string_view label,
              const PixelSelection* selection) {
    const std::string lowText = heatmapNumber(low), highText = heatmapNumber(high);
    const int line = textLineHeight(1);
    const int scaleWidth =
        std::max(textWidth(label, 1), textWidth(lowText + "  " + highText, 1)) + 2 * kHeatmapGap;
    const int width = std::max(map.width, scaleWidth);
    const int barTop = map.height + kHeatmapGap;
    Image out(width, barTop + kHeatmapBarHeight + 2 * line + 2 * kHeatmapGap);
    fillRect(out, 0, 0, out.width, out.height, kHeatmapPanel);

    const double span = double(high) - double(low);
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x) {
            const glm::u8vec4 colour =
                selection && !selection->isCounted(x, y)
                    ? kHeatmapLeftOut
                    : heatmapColour(span > 0 ? (double(map.at(x, y)) - double(low)) / span : 0.0);
            std::copy_n(&colour[0], 4, out.pixel(x, y));
        }
    // The scale: low at the left end, high at the right, under it the two values and the label.
    const int barWidth = width - 2 * kHeatmapGap;
    for (int x = 0; x < barWidth; ++x)
        fillRect(out, kHeatmapGap + x, barTop, 1, kHeatmapBarHeight,
                 heatmapColour(barWidth > 1 ? double(x) / double(barWidth - 1) : 0.0));
    const int valuesTop = barTop + kHeatmapBarHeight + 2;
    drawText(out, kHeatmapGap, valuesTop, lowText, 1, kHeatmapText);
    drawText(out, width - kHeatmapGap - textWidth(highText, 1), valuesTop, highText, 1, kHeatmapText);
    drawText(out, kHeatmapGap, valuesTop + line, label, 1, kHeatmapText);
    return out;
}

} // namespace shadelab
