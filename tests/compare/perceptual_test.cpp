// The perceptual delta (compare/metrics.h): what it counts on cases worked by hand, and held to pixelmatch
// itself (npm, the version tests/compare/independent/package-lock.json pins) on a set of pairs, at three
// thresholds: the counts, and each pixel's class (same, anti-aliased, differing), must be equal.
#include <png.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <stdexcept>
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

// pixelmatch throws on images of two sizes; reading past the smaller one would be undefined.
TEST(Perceptual, ImagesOfTwoSizesAreRefused) {
    EXPECT_THROW(perceptualDelta(flat(4, 4, 0), flat(5, 4, 0), {}), std::invalid_argument);
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

// What pixelmatch.mjs reports: pixelmatch's count and its class of each pixel ('0', '1' AA, '2' differing).
struct PixelmatchVerdict {
    long differing = -1;
    std::string map;
};

// The text after `key` on its line of `out`, or nullopt.
std::optional<std::string> pixelmatchField(const std::string& out, const std::string& key) {
    const std::size_t at = out.find(key);
    if (at == std::string::npos) return std::nullopt;
    const std::size_t from = at + key.size();
    return out.substr(from, out.find('\n', from) - from);
}

PixelmatchVerdict runPixelmatch(const fs::path& a, const fs::path& b, double threshold) {
    cli_test::RunOptions options;
    options.program = "/usr/bin/env";
    const cli_test::Outcome run =
        cli_test::runWith({"node", (independentFolder() / "pixelmatch.mjs").string(), a.string(), b.string(),
                           std::to_string(threshold)},
                          fs::temp_directory_path(), options);
    EXPECT_EQ(run.exitCode, 0) << cli_test::describe(run);
    const std::optional<std::string> differing = pixelmatchField(run.out, "differing=");
    const std::optional<std::string> map = pixelmatchField(run.out, "map=");
    if (!differing || !map) {
        ADD_FAILURE() << "pixelmatch.mjs printed: " << run.out << run.err;
        return {};
    }
    return {std::stol(*differing), *map};
}

// Where our map and pixelmatch's disagree: how many pixels, and the first of them.
std::string mapDisagreement(const MetricMap& ours, const std::string& theirs) {
    if (theirs.size() != ours.values.size())
        return "pixelmatch's map has " + std::to_string(theirs.size()) + " pixels";
    long count = 0;
    std::string first;
    for (std::size_t i = 0; i < theirs.size(); ++i) {
        const char mine = char('0' + int(ours.values[i]));
        if (mine == theirs[i]) continue;
        if (count++ == 0)
            first = "first at (" + std::to_string(i % std::size_t(ours.width)) + ", " +
                    std::to_string(i / std::size_t(ours.width)) + "): ours " + mine + ", pixelmatch's " +
                    theirs[i];
    }
    return count == 0 ? "" : std::to_string(count) + " pixels classed otherwise; " + first;
}

// Images whose edges cross the border, where pixelmatch counts a missing neighbour as one of the same colour.
std::vector<compare_test::Pair> borderPairs() {
    std::vector<compare_test::Pair> pairs;
    // Three grey levels: many neighbours of exactly one colour, the case hasManySiblings() decides.
    const auto levels = [](std::uint32_t seed) {
        Image image = compare_test::noise(64, 48, seed);
        for (std::size_t i = 0; i < image.rgba.size(); i += 4)
            std::fill_n(&image.rgba[i], 3, std::uint8_t(image.rgba[i] / 86 * 120));
        return image;
    };
    pairs.push_back({"levels-64x48", levels(6), levels(7), std::nullopt});
    pairs.push_back({"disc-at-border-shifted", compare_test::shadedDisc(40, 32, -17),
                     compare_test::shadedDisc(40, 32, -16), std::nullopt});
    return pairs;
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
    for (compare_test::Pair& pair : borderPairs()) pairs.push_back(std::move(pair));

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
            const PixelmatchVerdict theirs = runPixelmatch(a, b, threshold);
            EXPECT_EQ(ours.differingPixels, theirs.differing);
            EXPECT_EQ(mapDisagreement(ours.map, theirs.map), "");
            std::printf("%-24s %.2f  ours %5ld (+%ld AA)  pixelmatch %5ld\n", pair.name.c_str(), threshold,
                        ours.differingPixels, ours.antialiasedPixels, theirs.differing);
            ++compared;
        }
    }
    EXPECT_GE(compared, 30);
    fs::remove_all(folder);
}

} // namespace
} // namespace shadelab
