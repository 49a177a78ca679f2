// The heatmap (compare/metrics.h): viridis's colours, a lightness that rises with the value, the scale under
// the picture, left-out pixels grey, and no NaN or infinity reaching a pixel.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "shadelab/compare/judge.h"
#include "shadelab/compare/metrics.h"

namespace shadelab {
namespace {

// matplotlib's viridis at 0, 0.5 and 1 (cm.viridis, 8-bit).
TEST(Heatmap, ColoursAreViridis) {
    EXPECT_EQ(heatmapColour(0.0), glm::u8vec4(68, 1, 84, 255));
    EXPECT_EQ(heatmapColour(0.5), glm::u8vec4(33, 145, 140, 255));
    EXPECT_EQ(heatmapColour(1.0), glm::u8vec4(253, 231, 37, 255));
    EXPECT_EQ(heatmapColour(0.25), glm::u8vec4(59, 82, 139, 255));
    EXPECT_EQ(heatmapColour(0.75), glm::u8vec4(94, 201, 98, 255));
    EXPECT_EQ(heatmapColour(std::numeric_limits<double>::quiet_NaN()), heatmapColour(0.0));
    EXPECT_EQ(heatmapColour(std::numeric_limits<double>::infinity()), heatmapColour(1.0));
    EXPECT_EQ(heatmapColour(-3.0), heatmapColour(0.0));
}

// Between its stops the table is interpolated: within 5 levels of matplotlib's 256 entries
// (_viridis_data in matplotlib 3.6.3's _cm_listed.py, entry n at n/255, rounded to 8 bits).
TEST(Heatmap, BetweenTheStopsNearMatplotlibsTable) {
    const struct {
        int n;
        glm::ivec3 rgb;
    } entries[] = {{40, {69, 55, 129}}, {100, {42, 118, 142}}, {170, {53, 183, 121}}, {230, {189, 223, 38}}};
    for (const auto& e : entries) {
        const glm::u8vec4 c = heatmapColour(e.n / 255.0);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(int(c[k]), e.rgb[k], 5) << "entry " << e.n << " channel " << k;
    }
}

// What makes it readable without colour: the luma rises with the value over the whole range.
TEST(Heatmap, LightnessRisesWithTheValue) {
    double previous = -1;
    for (int i = 0; i <= 100; ++i) {
        const glm::u8vec4 c = heatmapColour(i / 100.0);
        const double luma = 0.299 * c.x + 0.587 * c.y + 0.114 * c.z;
        EXPECT_GT(luma, previous) << "at " << i / 100.0;
        previous = luma;
    }
}

TEST(Heatmap, MapAboveItsScaleLeftOutPixelsGrey) {
    MetricMap map{40, 30, std::vector<float>(40 * 30, 0.25f)};
    map.values[0] = std::numeric_limits<float>::quiet_NaN();
    map.values[1] = std::numeric_limits<float>::infinity();
    const std::optional<PixelSelection> selection =
        makeSelection(40, 30, nullptr, {IgnoreRect{10, 10, 5, 5}});
    ASSERT_TRUE(selection);
    const Image out = heatmap(map, 0.0f, 1.0f, "1 - SSIM", &*selection);
    EXPECT_GE(out.width, 40);
    EXPECT_GT(out.height, 30 + 10) << "the scale bar and its labels under the picture";
    const auto at = [&](int x, int y) {
        const std::uint8_t* p = out.pixel(x, y);
        return glm::u8vec4(p[0], p[1], p[2], p[3]);
    };
    EXPECT_EQ(at(5, 5), heatmapColour(0.25));
    EXPECT_EQ(at(0, 0), heatmapColour(0.0)) << "NaN drawn as the low end";
    EXPECT_EQ(at(1, 0), heatmapColour(1.0)) << "infinity drawn as the high end";
    EXPECT_EQ(at(12, 12), glm::u8vec4(128, 128, 128, 255)) << "left out by --ignore";
    // The bar runs from the low end's colour at its left to the high end's at its right.
    EXPECT_EQ(at(4, 34), heatmapColour(0.0));
    EXPECT_EQ(at(out.width - 5, 34), heatmapColour(1.0));
}

} // namespace
} // namespace shadelab
