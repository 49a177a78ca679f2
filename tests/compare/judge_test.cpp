// compare/judge.h: one judgement of a pair against every limit. Which pixels a mask and --ignore leave out,
// alpha as a compared channel unless ignored, each limit failing with its figure and flag, bad limit
// values refused by name. The metrics themselves are held to their independent implementations elsewhere
// (tests/compare/): here only that the judgement reads them.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "shadelab/compare/judge.h"
#include "shadelab/errors.h"

namespace {

using namespace shadelab;

Image judgeFilled(int width, int height, glm::u8vec4 colour) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) std::copy_n(&colour.x, 4, image.pixel(x, y));
    return image;
}

// A square of `colour` at (x, y), `size` pixels wide, over `image`.
Image withSquare(Image image, int x, int y, int size, glm::u8vec4 colour) {
    fillRect(image, x, y, size, size, colour);
    return image;
}

bool failureNames(const Judgement& j, const std::string& flag) {
    for (const std::string& f : j.failures)
        if (f.find(flag) != std::string::npos) return true;
    return false;
}

std::string failuresText(const Judgement& j) {
    std::string text;
    for (const std::string& f : j.failures) text += f + "\n";
    return text;
}

TEST(Judge, SelectionOfNothingLeftOutIsNone) {
    EXPECT_FALSE(makeSelection(8, 8, nullptr, {}));
    const Image white = judgeFilled(8, 8, {255, 255, 255, 255});
    EXPECT_FALSE(makeSelection(8, 8, &white, {})) << "a mask that leaves nothing out selects everything";
}

TEST(Judge, SelectionLeavesOutTheMasksBlackAndEachRectangle) {
    Image mask = judgeFilled(8, 6, {255, 255, 255, 255});
    mask.pixel(7, 5)[0] = mask.pixel(7, 5)[1] = mask.pixel(7, 5)[2] = 0;
    const std::optional<PixelSelection> s = makeSelection(8, 6, &mask, {{1, 2, 3, 2}});
    ASSERT_TRUE(s);
    int leftOut = 0;
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) {
            const bool inRect = x >= 1 && x < 4 && y >= 2 && y < 4;
            EXPECT_EQ(s->isCounted(x, y), !inRect && !(x == 7 && y == 5)) << x << "," << y;
            leftOut += s->isCounted(x, y) ? 0 : 1;
        }
    EXPECT_EQ(leftOut, 3 * 2 + 1);
}

TEST(Judge, SelectionRefusesWhatDoesNotFit) {
    const Image small(4, 4);
    const auto message = [](auto&& call) {
        try {
            call();
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("(no InputError)");
    };
    EXPECT_NE(message([&] { makeSelection(8, 8, &small, {}); }).find("--mask"), std::string::npos);
    EXPECT_NE(message([] {
                  makeSelection(8, 8, nullptr, {{6, 0, 3, 1}});
              }).find("--ignore: got 6,0,3,1"),
              std::string::npos)
        << "a rectangle past the right edge";
    EXPECT_NE(message([] {
                  makeSelection(8, 8, nullptr, {{-1, 0, 2, 2}});
              }).find("--ignore"),
              std::string::npos);
    EXPECT_NE(message([] {
                  makeSelection(8, 8, nullptr, {{0, 0, 0, 2}});
              }).find("--ignore"),
              std::string::npos);
    EXPECT_NE(message([] {
                  makeSelection(8, 8, nullptr, {{std::numeric_limits<int>::max(), 0, 2, 2}});
              }).find("--ignore"),
              std::string::npos)
        << "x + w past INT_MAX must not wrap into the image";
}

// The CLI's default: a fully transparent picture is not an opaque one of the same colour.
TEST(Judge, AlphaIsComparedUnlessIgnored) {
    const Image opaque = judgeFilled(16, 16, {200, 100, 50, 255});
    const Image transparent = judgeFilled(16, 16, {200, 100, 50, 0});
    const Judgement compared = judgeImages(transparent, opaque, CheckLimits{});
    EXPECT_FALSE(compared.passed);
    EXPECT_EQ(compared.comparison.maxDelta, 255);
    EXPECT_EQ(compared.comparison.outliers, 16 * 16) << "every pixel's alpha is over --max 0";
    EXPECT_DOUBLE_EQ(compared.comparison.meanDelta, 0.0) << "the mean stays the colour channels'";
    CheckLimits ignoring;
    ignoring.ignoreAlpha = true;
    const Judgement ignored = judgeImages(transparent, opaque, ignoring);
    EXPECT_TRUE(ignored.passed) << failuresText(ignored);
    EXPECT_EQ(ignored.comparison.maxDelta, 0);
    ASSERT_TRUE(ignored.perceptual);
    EXPECT_EQ(ignored.perceptual->differingPixels, 0) << "the perceptual delta ignores alpha too";
}

TEST(Judge, IgnoredRectangleLeavesItsDifferenceOut) {
    const Image expected = judgeFilled(32, 32, {40, 40, 40, 255});
    const Image actual = withSquare(expected, 10, 12, 4, {250, 250, 250, 255});
    const Judgement whole = judgeImages(actual, expected, CheckLimits{});
    EXPECT_FALSE(whole.passed);
    EXPECT_TRUE(failureNames(whole, "--max")) << failuresText(whole);
    EXPECT_TRUE(failureNames(whole, "--mean")) << failuresText(whole);
    CheckLimits limits;
    limits.ignore = {{10, 12, 4, 4}};
    const Judgement ignored = judgeImages(actual, expected, limits);
    EXPECT_TRUE(ignored.passed) << failuresText(ignored);
    EXPECT_EQ(ignored.comparison.comparedPixels, 32u * 32u - 16u);
    limits.ignore = {{10, 12, 4, 3}}; // one row of the square still counted
    EXPECT_FALSE(judgeImages(actual, expected, limits).passed);
}

// Each metric's limit fails the judgement on its own, naming its flag; and holds when set loose.
TEST(Judge, EachMetricLimitFailsWithItsFlag) {
    const Image expected = judgeFilled(32, 32, {40, 40, 40, 255});
    const Image actual = withSquare(expected, 8, 8, 8, {200, 200, 200, 255});
    CheckLimits loose; // per-channel limits wide open: only the limit under test can fail
    loose.tolerance = {255, 255, 32 * 32};
    const Judgement none = judgeImages(actual, expected, loose);
    ASSERT_TRUE(none.passed) << failuresText(none);
    ASSERT_TRUE(none.ssim && none.perceptual);
    EXPECT_LT(none.ssim->mean, 1.0);
    EXPECT_GT(none.perceptual->differingPixels, 0);

    CheckLimits ssimLimit = loose;
    ssimLimit.ssimMin = none.ssim->mean + 1e-6;
    const Judgement ssimFailed = judgeImages(actual, expected, ssimLimit);
    EXPECT_FALSE(ssimFailed.passed);
    EXPECT_TRUE(failureNames(ssimFailed, "--ssim-min")) << failuresText(ssimFailed);
    ssimLimit.ssimMin = none.ssim->mean - 1e-6;
    EXPECT_TRUE(judgeImages(actual, expected, ssimLimit).passed);

    CheckLimits perceptual = loose;
    perceptual.perceptualMaxPixels = none.perceptual->differingPixels - 1;
    const Judgement perceptualFailed = judgeImages(actual, expected, perceptual);
    EXPECT_FALSE(perceptualFailed.passed);
    EXPECT_TRUE(failureNames(perceptualFailed, "--perceptual-max-pixels")) << failuresText(perceptualFailed);
    perceptual.perceptualMaxPixels = none.perceptual->differingPixels;
    EXPECT_TRUE(judgeImages(actual, expected, perceptual).passed);
}

TEST(Judge, DifferentSizesFailWithBothSizesAndNoMetric) {
    const Judgement j = judgeImages(Image(4, 4), Image(4, 5), CheckLimits{});
    EXPECT_FALSE(j.passed);
    ASSERT_EQ(j.failures.size(), 1u);
    EXPECT_NE(j.failures[0].find("actual 4x4, expected 4x5"), std::string::npos) << j.failures[0];
    EXPECT_FALSE(j.ssim);
    EXPECT_FALSE(j.perceptual);
}

// A limit nobody could mean (a NaN passes every comparison) is refused by name, however it was filled.
TEST(Judge, BadLimitValuesAreRefusedByName) {
    const Image image(4, 4);
    const double nan = std::nan("");
    const auto refusal = [&](const CheckLimits& limits) {
        try {
            judgeImages(image, image, limits);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("(no InputError)");
    };
    CheckLimits l;
    l.tolerance.meanDelta = nan;
    EXPECT_NE(refusal(l).find("--mean"), std::string::npos);
    l = {};
    l.ssimMin = nan;
    EXPECT_NE(refusal(l).find("--ssim-min"), std::string::npos);
    l = {};
    l.perceptualThreshold = 1.5;
    EXPECT_NE(refusal(l).find("--perceptual-threshold"), std::string::npos);
    l = {};
    l.tolerance.maxDelta = 256;
    EXPECT_NE(refusal(l).find("--max"), std::string::npos);
}

} // namespace
