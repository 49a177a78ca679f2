// SSIM (compare/metrics.h): what it is on cases worked by hand, and held to scikit-image itself (Debian's
// python3-skimage, tests/compare/independent/ssim_skimage.py) within 1e-4 on a set of pairs.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/run_process.h"
#include "compare/doctored.h"
#include "shadelab/compare/judge.h"
#include "shadelab/compare/metrics.h"
#include "shadelab/image/image_file.h"

namespace shadelab {
namespace {

namespace fs = std::filesystem;
using compare_test::noise;
using compare_test::shadedDisc;

TEST(Ssim, IdenticalImagesScoreOneEverywhere) {
    const Image a = noise(32, 24, 7);
    const SsimResult s = ssim(a, a);
    EXPECT_DOUBLE_EQ(s.mean, 1.0);
    EXPECT_EQ(s.meanPixels, std::size_t(22 * 14)); // the 5-pixel margin left out of the mean
    for (float v : s.map.values) EXPECT_NEAR(v, 1.0f, 1e-6f);
}

// Two flat images: σ = 0 in both windows, so only the luminance term remains,
// (2·μx·μy + C₁)/(μx² + μy² + C₁) with C₁ = (0.01·255)².
TEST(Ssim, FlatImagesLeaveOnlyTheLuminanceTerm) {
    Image a(16, 16), b(16, 16);
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        std::fill_n(&a.rgba[i], 3, std::uint8_t(100));
        std::fill_n(&b.rgba[i], 3, std::uint8_t(120));
        a.rgba[i + 3] = b.rgba[i + 3] = 255;
    }
    const double c1 = 2.55 * 2.55;
    EXPECT_NEAR(ssim(a, b).mean, (2 * 100.0 * 120 + c1) / (100.0 * 100 + 120.0 * 120 + c1), 1e-9);
}

// One bright pixel in the middle of an 11x11 flat image: the only pixel 5 px from every border is that one,
// and its window lies wholly inside the image, so the mean is worked out by hand. With w the window's centre
// weight, g(0)² for the 1-D Gaussian g(i) = exp(-i²/(2σ²)) / Σ exp(-j²/(2σ²)) over i, j in -5..5:
//   μx = 100, σx² = 0, σxy = 0;  μy = 100 + 100 w,  σy² = w (1 − w) 100²  (a two-valued window).
TEST(Ssim, OneBrightPixelWorkedByHand) {
    Image a(11, 11), b(11, 11);
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        std::fill_n(&a.rgba[i], 3, std::uint8_t(100));
        std::fill_n(&b.rgba[i], 3, std::uint8_t(100));
        a.rgba[i + 3] = b.rgba[i + 3] = 255;
    }
    std::fill_n(b.pixel(5, 5), 3, std::uint8_t(200));
    double sum = 0;
    for (int i = -5; i <= 5; ++i) sum += std::exp(-i * i / (2 * 1.5 * 1.5));
    const double w = (1 / sum) * (1 / sum);
    const double muX = 100, muY = 100 + 100 * w, varY = w * (1 - w) * 100 * 100;
    const double c1 = 2.55 * 2.55, c2 = 7.65 * 7.65;
    const double expected = (2 * muX * muY + c1) * c2 / ((muX * muX + muY * muY + c1) * (varY + c2));
    const SsimResult s = ssim(a, b);
    EXPECT_EQ(s.meanPixels, std::size_t(1));
    EXPECT_NEAR(s.mean, expected, 1e-12);
    EXPECT_LT(expected, 0.5) << "a lone bright pixel is a large structural change";
}

// The mean is over the counted pixels only: a difference under a left-out rectangle does not lower it.
TEST(Ssim, LeftOutPixelsAreNotInTheMean) {
    const Image a = shadedDisc(48, 48, 0);
    Image b = a;
    for (int y = 20; y < 28; ++y)
        for (int x = 20; x < 28; ++x) b.pixel(x, y)[0] = 255;
    EXPECT_LT(ssim(a, b).mean, 0.99);
    const std::optional<PixelSelection> selection =
        makeSelection(48, 48, nullptr, {IgnoreRect{12, 12, 24, 24}});
    ASSERT_TRUE(selection);
    EXPECT_DOUBLE_EQ(ssim(a, b, &*selection).mean, 1.0);
}

TEST(Ssim, AnImageSmallerThanTheWindowIsAveragedWhole) {
    const Image a = noise(8, 8, 1), b = noise(8, 8, 2);
    const SsimResult s = ssim(a, b);
    EXPECT_EQ(s.meanPixels, std::size_t(64));
    EXPECT_TRUE(std::isfinite(s.mean));
    EXPECT_LT(s.mean, 1.0);
}

// ---- against scikit-image ----

struct SkimageFigures {
    double mean = 0, mapMean = 0;
};

// Runs the script without a shell; fails the test (and returns nullopt) if it does not answer.
std::optional<SkimageFigures> skimageSsim(const fs::path& a, const fs::path& b, const fs::path& mask = {}) {
    std::vector<std::string> args{fs::path(SHADELAB_TEST_DATA) / "compare/independent/ssim_skimage.py",
                                  a.string(), b.string()};
    if (!mask.empty()) args.push_back(mask.string());
    cli_test::RunOptions options;
    options.program = "/usr/bin/python3";
    const cli_test::Outcome run = cli_test::runWith(args, fs::temp_directory_path(), options);
    EXPECT_EQ(run.exitCode, 0) << cli_test::describe(run);
    SkimageFigures figures;
    std::istringstream in(run.out);
    if (!(in >> figures.mean >> figures.mapMean)) {
        ADD_FAILURE() << "ssim_skimage.py printed: " << run.out << run.err;
        return std::nullopt;
    }
    return figures;
}

// What scikit-image needs, or why it cannot run: in CI a missing piece fails, elsewhere the test is skipped.
std::string skimageMissing() {
    cli_test::RunOptions options;
    options.program = "/usr/bin/python3";
    const cli_test::Outcome run =
        cli_test::runWith({"-c", "import skimage.metrics, PIL, numpy"}, fs::temp_directory_path(), options);
    return run.exitCode == 0
               ? ""
               : "python3 with skimage, PIL and numpy (apt-get install python3-skimage python3-pil)";
}

TEST(SsimAgainstSkimage, EveryPairWithin1e4) {
    if (const std::string missing = skimageMissing(); !missing.empty()) {
        if (std::getenv("CI")) FAIL() << "CI must hold SSIM to scikit-image; missing: " << missing;
        GTEST_SKIP() << "missing: " << missing;
    }
    const fs::path folder = compare_test::freshFolder("ssim");
    double largestGap = 0;
    for (const compare_test::Pair& pair : compare_test::independentPairs()) {
        SCOPED_TRACE(pair.name);
        const fs::path a = folder / (pair.name + ".a.png"), b = folder / (pair.name + ".b.png");
        writePng(pair.actual, a);
        writePng(pair.expected, b);
        fs::path maskFile;
        std::optional<PixelSelection> selection;
        if (pair.mask) {
            maskFile = folder / (pair.name + ".mask.png");
            writePng(*pair.mask, maskFile);
            selection = makeSelection(pair.actual.width, pair.actual.height, &*pair.mask, {});
        }
        const std::optional<SkimageFigures> theirs = skimageSsim(a, b, maskFile);
        if (!theirs) continue;
        const SsimResult ours = ssim(pair.actual, pair.expected, selection ? &*selection : nullptr);
        double mapMean = 0;
        for (float v : ours.map.values) mapMean += v;
        mapMean /= double(ours.map.values.size());
        EXPECT_NEAR(ours.mean, theirs->mean, 1e-4);
        EXPECT_NEAR(mapMean, theirs->mapMean, 1e-4) << "the whole map, its reflected border included";
        largestGap =
            std::max({largestGap, std::abs(ours.mean - theirs->mean), std::abs(mapMean - theirs->mapMean)});
        std::printf("%-28s ours %.9f  scikit-image %.9f\n", pair.name.c_str(), ours.mean, theirs->mean);
    }
    std::printf("largest gap to scikit-image: %.3g\n", largestGap);
    fs::remove_all(folder);
}

} // namespace
} // namespace shadelab
