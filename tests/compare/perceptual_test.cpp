// The perceptual delta (compare/metrics.h): what it counts on cases worked by hand, and held to pixelmatch
// itself (npm, the version tests/compare/independent/package-lock.json pins) on a set of pairs, at three
// thresholds: the counts must be equal.
#include <png.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/run_process.h"
#include "compare/doctored.h"
#include "shadelab/compare/judge.h"
#include "shadelab/compare/metrics.h"

namespace shadelab {
namespace {

namespace fs = std::filesystem;

Image flat(int width, int height, std::uint8_t grey) {
    Image image(width, height);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = i % 4 == 3 ? 255 : grey;
    return image;
}

TEST(Perceptual, IdenticalImagesDifferNowhere) {
    const Image a = compare_test::noise(20, 20, 3);
    const PerceptualResult r = perceptualDelta(a, a, {});
    EXPECT_EQ(r.differingPixels, 0);
    EXPECT_EQ(r.antialiasedPixels, 0);
}

// One pixel changed inside a flat area: its neighbours all share one brightness, so it is no edge.
TEST(Perceptual, OneChangedPixelInAFlatAreaDiffers) {
    const Image a = flat(16, 16, 100);
    Image b = a;
    b.pixel(8, 8)[0] = 200;
    const PerceptualResult r = perceptualDelta(a, b, {});
    EXPECT_EQ(r.differingPixels, 1);
    EXPECT_EQ(r.antialiasedPixels, 0);
    EXPECT_EQ(r.map.at(8, 8), 2.0f);
}

// A pixel on the ramp between a flat dark and a flat light area (its darkest and brightest neighbours each
// in a flat region, in both images) is anti-aliasing: counted apart, not as differing.
TEST(Perceptual, AnAntiAliasedEdgePixelIsSetAside) {
    Image a = flat(16, 16, 0);
    for (int y = 0; y < 16; ++y)
        for (int x = 9; x < 16; ++x) std::fill_n(a.pixel(x, y), 3, std::uint8_t(255));
    for (int y = 0; y < 16; ++y) std::fill_n(a.pixel(8, y), 3, std::uint8_t(128));
    Image b = a;
    std::fill_n(b.pixel(8, 8), 3, std::uint8_t(60));
    const PerceptualResult r = perceptualDelta(a, b, {});
    EXPECT_EQ(r.differingPixels, 0);
    EXPECT_EQ(r.antialiasedPixels, 1);
    EXPECT_EQ(r.map.at(8, 8), 1.0f);
}

TEST(Perceptual, TheThresholdAndTheSelectionDecide) {
    const Image a = flat(16, 16, 100);
    Image b = a;
    b.pixel(8, 8)[0] = 110; // a small red change
    EXPECT_EQ(perceptualDelta(a, b, {0.0}).differingPixels, 1);
    EXPECT_EQ(perceptualDelta(a, b, {1.0}).differingPixels, 0);
    const std::optional<PixelSelection> selection = makeSelection(16, 16, nullptr, {IgnoreRect{6, 6, 4, 4}});
    ASSERT_TRUE(selection);
    EXPECT_EQ(perceptualDelta(a, b, {0.0}, &*selection).differingPixels, 0);
}

// ---- against pixelmatch ----

// RGBA with its alpha (shadelab's own writePng drops alpha: its renders are opaque).
void writeRgba(const Image& image, const fs::path& path) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = png_uint_32(image.width);
    png.height = png_uint_32(image.height);
    png.format = PNG_FORMAT_RGBA;
    ASSERT_TRUE(png_image_write_to_file(&png, path.c_str(), 0, image.rgba.data(), 0, nullptr)) << png.message;
}

const fs::path& independentFolder() {
    static const fs::path folder = fs::path(SHADELAB_TEST_DATA) / "compare/independent";
    return folder;
}

std::string pixelmatchMissing() {
    cli_test::RunOptions options;
    options.program = "/usr/bin/env";
    const cli_test::Outcome node =
        cli_test::runWith({"node", "--version"}, fs::temp_directory_path(), options);
    if (node.exitCode != 0) return "node (apt-get install nodejs)";
    if (!fs::exists(independentFolder() / "node_modules/pixelmatch/package.json"))
        return "pixelmatch in tests/compare/independent/node_modules (run "
               "tests/compare/independent/install.sh)";
    return "";
}

long pixelmatchCount(const fs::path& a, const fs::path& b, double threshold) {
    cli_test::RunOptions options;
    options.program = "/usr/bin/env";
    const cli_test::Outcome run =
        cli_test::runWith({"node", (independentFolder() / "pixelmatch.mjs").string(), a.string(), b.string(),
                           std::to_string(threshold)},
                          fs::temp_directory_path(), options);
    EXPECT_EQ(run.exitCode, 0) << cli_test::describe(run);
    const std::string key = "differing=";
    const std::size_t at = run.out.find(key);
    if (at == std::string::npos) {
        ADD_FAILURE() << "pixelmatch.mjs printed: " << run.out << run.err;
        return -1;
    }
    return std::stol(run.out.substr(at + key.size()));
}

TEST(PerceptualAgainstPixelmatch, EveryPairAndThresholdCountsTheSame) {
    if (const std::string missing = pixelmatchMissing(); !missing.empty()) {
        if (std::getenv("CI"))
            FAIL() << "CI must hold the perceptual delta to pixelmatch; missing: " << missing;
        GTEST_SKIP() << "missing: " << missing;
    }
    std::vector<compare_test::Pair> pairs = compare_test::independentPairs();
    // Translucent pixels: blended over pixelmatch's checkerboard.
    Image translucent = compare_test::shadedDisc(40, 32, 0);
    for (std::size_t i = 3; i < translucent.rgba.size(); i += 4)
        translucent.rgba[i] = std::uint8_t((i * 37) % 256);
    pairs.push_back({"alpha-varied", compare_test::shadedDisc(40, 32, 0), translucent, std::nullopt});
    Image clear = compare_test::shadedDisc(40, 32, 0);
    for (std::size_t i = 3; i < clear.rgba.size(); i += 4) clear.rgba[i] = 0;
    pairs.push_back({"transparent-vs-opaque", clear, compare_test::shadedDisc(40, 32, 0), std::nullopt});
    pairs.push_back({"odd-13x7", compare_test::noise(13, 7, 8), compare_test::noise(13, 7, 9), std::nullopt});

    const fs::path folder = compare_test::freshFolder("pixelmatch");
    int compared = 0;
    for (const compare_test::Pair& pair : pairs) {
        if (pair.mask) continue; // pixelmatch 7 takes no mask
        const fs::path a = folder / (pair.name + ".a.png"), b = folder / (pair.name + ".b.png");
        writeRgba(pair.actual, a);
        writeRgba(pair.expected, b);
        for (double threshold : {0.05, 0.1, 0.3}) {
            SCOPED_TRACE(pair.name + " at threshold " + std::to_string(threshold));
            const PerceptualResult ours = perceptualDelta(pair.actual, pair.expected, {threshold});
            const long theirs = pixelmatchCount(a, b, threshold);
            EXPECT_EQ(ours.differingPixels, theirs);
            std::printf("%-24s %.2f  ours %5ld (+%ld AA)  pixelmatch %5ld\n", pair.name.c_str(), threshold,
                        ours.differingPixels, ours.antialiasedPixels, theirs);
            ++compared;
        }
    }
    EXPECT_GE(compared, 30);
    fs::remove_all(folder);
}

} // namespace
} // namespace shadelab
