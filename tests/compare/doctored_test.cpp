// What each metric catches and misses on two doctored copies of a real render (tests/references/
// phong_phong.png, a Phong-shaded sphere with a highlight): the picture shifted right by one pixel, which
// nobody would call a regression, and the highlight smeared by a 5x5 blur over a 6-px disc, which a person
// sees. The figures are printed (docs/ci-engineers.md "Which metric" quotes them); the assertions hold what
// the guide says of each metric and of its recommended limits.
#include <cstdio>

#include <gtest/gtest.h>

#include "compare/doctored.h"
#include "shadelab/compare/judge.h"

namespace shadelab {
namespace {

// The guide's recommended limits (docs/ci-engineers.md "Recommended limits").
// Where one driver draws both images, as in the example job (examples/ci/screenshot-regression.sh's
// TOLERANCE): it gives the same pixels run after run, so the limits only absorb what a driver update may
// move (8 silhouette pixels by up to 2 levels) and every figure is held.
constexpr int kSameDriverMax = 2;
constexpr double kSameDriverMean = 0.05;
constexpr int kSameDriverOutliers = 8;
// The perceptual count at pixelmatch's default threshold, allowing the same 8 edge pixels.
constexpr long kPerceptualMaxPixels = 8;
constexpr double kPerceptualThreshold = 0.1;
// Where another driver or GPU draws the expected image: the per-channel limits are let go (rasterizers differ
// at every silhouette pixel), SSIM holds the structure and the perceptual count what a person would see.
constexpr double kOtherDriverSsimMin = 0.99;

CheckLimits sameDriverLimits() {
    CheckLimits l;
    l.tolerance = {kSameDriverMax, kSameDriverMean, kSameDriverOutliers};
    l.perceptualMaxPixels = kPerceptualMaxPixels;
    l.perceptualThreshold = kPerceptualThreshold;
    return l;
}

CheckLimits otherDriverLimits() {
    CheckLimits l;
    l.tolerance = {255, 255, 0};
    l.ssimMin = kOtherDriverSsimMin;
    l.perceptualMaxPixels = kPerceptualMaxPixels;
    l.perceptualThreshold = kPerceptualThreshold;
    return l;
}

bool failedOn(const Judgement& j, const std::string& flag) {
    for (const std::string& f : j.failures)
        if (f.find(flag) != std::string::npos) return true;
    return false;
}

void print(const char* name, const Judgement& j) {
    const Comparison& c = j.comparison;
    std::printf("%-9s max %3d  mean %.4f  over 2: %4d px  SSIM %.5f  perceptual %4ld px (+%ld AA)\n", name,
                c.maxDelta, c.meanDelta, c.outliers, j.ssim->mean, j.perceptual->differingPixels,
                j.perceptual->antialiasedPixels);
}

TEST(DoctoredRenders, WhatEachMetricCatchesAndMisses) {
    const Image render = compare_test::phongRender();
    const Judgement shift = judgeImages(compare_test::renderShifted(), render, sameDriverLimits());
    const Judgement smear = judgeImages(compare_test::renderSmeared(), render, sameDriverLimits());
    ASSERT_TRUE(shift.ssim && shift.perceptual && smear.ssim && smear.perceptual);
    print("shifted", shift);
    print("smeared", smear);

    // Per channel: the shift moves every edge of the sphere, so it has far more pixels over 2 than the smear,
    // and a larger mean; the smear still has a few dozen pixels over 2.
    EXPECT_GT(shift.comparison.outliers, 10 * smear.comparison.outliers);
    EXPECT_GT(shift.comparison.meanDelta, 10 * smear.comparison.meanDelta);
    EXPECT_GT(smear.comparison.outliers, 8);
    // SSIM, being about local structure, scores the invisible shift far lower than the visible smear: it
    // cannot be set to flag the smear without flagging the shift.
    EXPECT_LT(shift.ssim->mean, smear.ssim->mean);
    EXPECT_GT(smear.ssim->mean, 0.999);
    // The perceptual count sets part of the shift aside as anti-aliasing, and counts few smeared pixels: the
    // smear changes the highlight's colour by less than threshold 0.1 in most of its pixels.
    EXPECT_GT(shift.perceptual->antialiasedPixels, 0);
    EXPECT_GT(shift.perceptual->differingPixels, smear.perceptual->differingPixels);
    EXPECT_LE(smear.perceptual->differingPixels, 8);
}

// What the guide says of its recommended limits where one driver draws: they flag both; the smear by the
// per-channel limits only.
TEST(DoctoredRenders, WhatTheSameDriverLimitsFlag) {
    const Image render = compare_test::phongRender();
    const Judgement shift = judgeImages(compare_test::renderShifted(), render, sameDriverLimits());
    const Judgement smear = judgeImages(compare_test::renderSmeared(), render, sameDriverLimits());
    for (const std::string& f : shift.failures) std::printf("shifted: %s\n", f.c_str());
    for (const std::string& f : smear.failures) std::printf("smeared: %s\n", f.c_str());
    EXPECT_FALSE(shift.passed);
    EXPECT_TRUE(failedOn(shift, "--perceptual-max-pixels"));
    EXPECT_FALSE(smear.passed);
    EXPECT_TRUE(failedOn(smear, "--max") || failedOn(smear, "--mean") || failedOn(smear, "outlier"));
    EXPECT_FALSE(failedOn(smear, "--perceptual-max-pixels")) << "the perceptual limit alone misses the smear";
}

// ... and where another driver draws: they flag the shift (on SSIM and on the perceptual count) and pass the
// smear. No --ssim-min can do otherwise: SSIM scores the shift lower than the smear.
TEST(DoctoredRenders, WhatTheOtherDriverLimitsFlag) {
    const Image render = compare_test::phongRender();
    const Judgement shift = judgeImages(compare_test::renderShifted(), render, otherDriverLimits());
    const Judgement smear = judgeImages(compare_test::renderSmeared(), render, otherDriverLimits());
    for (const std::string& f : shift.failures) std::printf("shifted (other driver): %s\n", f.c_str());
    EXPECT_FALSE(shift.passed);
    EXPECT_TRUE(failedOn(shift, "--ssim-min"));
    EXPECT_TRUE(failedOn(shift, "--perceptual-max-pixels"));
    EXPECT_TRUE(smear.passed) << "the limits for another driver miss the smear";
    ASSERT_TRUE(shift.ssim && smear.ssim);
    EXPECT_LT(shift.ssim->mean, smear.ssim->mean);
}

} // namespace
} // namespace shadelab
