// `shadelab compare` end to end (docs/ci-engineers.md "Screenshot regression in your CI"): it judges as the
// tests do (the figures of compareImages, a mask's black pixels not compared, the mean over the compared
// pixels), --json for a dashboard, 16-bit files read as stored, a forged header refused before allocating,
// --diff never one of the inputs, and different sizes named; then every limit of compare/judge.h (SSIM,
// the perceptual delta, --ignore, alpha), bad values refused by name, and `shadelab-compare` giving
// the same answers. Each test in a fresh temporary folder (cli_fixture.h). Built into cli_test.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <png.h>

#include "cli/cli_fixture.h"
#include "cli/run_process.h"
#include "shadelab/image/image.h"
#include "shadelab/image/image_file.h"

namespace {

using namespace shadelab::cli_test;

namespace fs = std::filesystem;

// The regression kit: `shadelab compare` is the tests' comparison from a shell. 0 within the
// tolerance, 1 beyond it (the figures printed, --diff written), 2 for a file that is not there; a mask's
// black pixels are not compared.
TEST_F(CliTest, CompareJudgesAsTheTestsDo) {
    ASSERT_EQ(shadelab({"render", "--size", "64x64", "--out", "a.png"}).exitCode, 0);
    ASSERT_EQ(shadelab({"render", "--size", "64x64", "--shading", "flat", "--out", "b.png"}).exitCode, 0);
    const Outcome same = shadelab({"compare", "a.png", "a.png"});
    EXPECT_EQ(same.exitCode, 0) << describe(same);
    EXPECT_TRUE(same.out.starts_with("pass: max delta 0")) << same.out;
    const Outcome differ = shadelab({"compare", "a.png", "b.png", "--diff", "d.png"});
    EXPECT_EQ(differ.exitCode, 1) << describe(differ);
    EXPECT_TRUE(differ.out.starts_with("FAIL: max delta ")) << differ.out;
    EXPECT_TRUE(pngSize(readFile(dir_ / "d.png"))) << "the difference image";
    const shadelab::Image a = shadelab::readPng(dir_ / "a.png"), b = shadelab::readPng(dir_ / "b.png");
    const shadelab::Comparison c = shadelab::compareImages(a, b, shadelab::Tolerance{});
    EXPECT_NE(differ.out.find("max delta " + std::to_string(c.maxDelta) + ","), std::string::npos)
        << "the same figure as compareImages: " << c.summary() << " vs " << differ.out;
    const Outcome loose = shadelab({"compare", "a.png", "b.png", "--max", "255", "--mean", "255"});
    EXPECT_EQ(loose.exitCode, 0) << describe(loose);
    const shadelab::Image black(64, 64); // all zero: nothing is compared
    shadelab::writePng(black, dir_ / "mask.png");
    const Outcome masked = shadelab({"compare", "a.png", "b.png", "--mask", "mask.png"});
    EXPECT_EQ(masked.exitCode, 0) << describe(masked);
    const Outcome missing = shadelab({"compare", "a.png", "nothere.png"});
    EXPECT_EQ(missing.exitCode, 2) << describe(missing);
    EXPECT_NE(missing.err.find("nothere.png"), std::string::npos) << describe(missing);
}

// `compare --json` is the summary as one object for a CI dashboard: the same figures as
// compareImages, the limits, the sizes (both, when they differ), passed as the exit code says, the diff's
// path when one was written.
TEST_F(CliTest, CompareJsonCarriesTheFiguresOfTheSummary) {
    ASSERT_EQ(shadelab({"render", "--size", "64x64", "--out", "a.png"}).exitCode, 0);
    ASSERT_EQ(shadelab({"render", "--size", "64x64", "--shading", "flat", "--out", "b.png"}).exitCode, 0);
    ASSERT_EQ(shadelab({"render", "--size", "32x48", "--out", "small.png"}).exitCode, 0);
    shadelab::Image mask(64, 64);
    shadelab::fillRect(mask, 0, 20, 64, 24, {255, 255, 255, 255}); // compares rows 20..43 only
    shadelab::writePng(mask, dir_ / "mask.png");
    const shadelab::Image a = shadelab::readPng(dir_ / "a.png"), b = shadelab::readPng(dir_ / "b.png");
    const shadelab::Comparison c = shadelab::compareImages(a, b, shadelab::Tolerance{2, 0.5, 3, true}, &mask);
    ASSERT_FALSE(c.passed) << "flat and phong must differ for this test: " << c.summary();

    const Outcome differ = shadelab({"compare", "a.png", "b.png", "--max", "2", "--mean", "0.5", "--outliers",
                                     "3", "--mask", "mask.png", "--diff", "d.png", "--json"});
    EXPECT_EQ(differ.exitCode, 1) << describe(differ);
    const nlohmann::json j = nlohmann::json::parse(differ.out); // nothing but the object on standard output
    EXPECT_EQ(j["actual"], "a.png");
    EXPECT_EQ(j["expected"], "b.png");
    EXPECT_EQ(j["mask"], "mask.png");
    EXPECT_EQ(j["passed"], false);
    EXPECT_EQ(j["size_matches"], true);
    EXPECT_EQ(j["max_delta"], c.maxDelta);
    EXPECT_DOUBLE_EQ(j["mean_delta"].get<double>(), c.meanDelta);
    EXPECT_EQ(j["outliers"], c.outliers);
    EXPECT_EQ(j["compared_pixels"], 64 * 24);
    EXPECT_EQ(j["pixels"], 64 * 64);
    EXPECT_EQ(j["limits"]["max"], 2);
    EXPECT_EQ(j["limits"]["mean"], 0.5);
    EXPECT_EQ(j["limits"]["outliers"], 3);
    EXPECT_EQ(j["diff"], "d.png");
    EXPECT_TRUE(pngSize(readFile(dir_ / "d.png"))) << "the difference image";

    const Outcome same = shadelab({"compare", "a.png", "a.png", "--diff", "none.png", "--json"});
    EXPECT_EQ(same.exitCode, 0) << describe(same);
    const nlohmann::json k = nlohmann::json::parse(same.out);
    EXPECT_EQ(k["passed"], true);
    EXPECT_EQ(k["max_delta"], 0);
    EXPECT_EQ(k["mask"], nullptr);
    EXPECT_EQ(k["diff"], nullptr) << "no difference image is written for a pass";
    EXPECT_FALSE(fs::exists(dir_ / "none.png"));

    const Outcome sizes = shadelab({"compare", "a.png", "small.png", "--json"});
    EXPECT_EQ(sizes.exitCode, 1) << describe(sizes);
    const nlohmann::json m = nlohmann::json::parse(sizes.out);
    EXPECT_EQ(m["size_matches"], false);
    EXPECT_EQ(m["passed"], false);
    EXPECT_EQ(m["actual_size"], (nlohmann::json{{"width", 64}, {"height", 64}}));
    EXPECT_EQ(m["expected_size"], (nlohmann::json{{"width", 32}, {"height", 48}}));
    EXPECT_FALSE(m.contains("max_delta")) << "no figures for images of different sizes";
}

// The mean is over the compared pixels: a mask that keeps one row must not dilute a difference everywhere
// (10/255 apart failed --mean 5 without a mask and passed with one, "mean 1.0").
TEST_F(CliTest, CompareMeanIsOverTheComparedPixels) {
    shadelab::writePng(filled(16, 16, 100), dir_ / "a.png");
    shadelab::writePng(filled(16, 16, 110), dir_ / "b.png");
    shadelab::Image mask = filled(16, 16, 0);
    std::fill_n(mask.rgba.begin(), 16 * 4, std::uint8_t(255)); // the first row is compared
    shadelab::writePng(mask, dir_ / "mask.png");
    const Outcome plain = shadelab({"compare", "a.png", "b.png", "--max", "255", "--mean", "5"});
    EXPECT_EQ(plain.exitCode, 1) << describe(plain);
    const Outcome masked =
        shadelab({"compare", "a.png", "b.png", "--max", "255", "--mean", "5", "--mask", "mask.png"});
    EXPECT_EQ(masked.exitCode, 1) << describe(masked);
    EXPECT_NE(masked.out.find("mean delta 10.0000 over the 16 compared pixels of 256"), std::string::npos)
        << masked.out;
    const Outcome help = shadelab({"compare", "--help"});
    EXPECT_NE(help.out.find("over the compared pixels"), std::string::npos) << help.out;
}

// A 16-bit PNG holding the samples s·257 of an 8-bit one, written by libpng as linear data with a gAMA
// chunk of 1.0 (PNG_FORMAT_LINEAR_RGB).
void writeSixteenBitPng(const shadelab::Image& image, const fs::path& path) {
    std::vector<std::uint16_t> samples;
    for (std::size_t i = 0; i < image.rgba.size(); ++i)
        if (i % 4 != 3) samples.push_back(std::uint16_t(image.rgba[i] * 257));
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = png_uint_32(image.width);
    png.height = png_uint_32(image.height);
    png.format = PNG_FORMAT_LINEAR_RGB;
    ASSERT_TRUE(png_image_write_to_file(&png, path.c_str(), 0, samples.data(), 0, nullptr)) << png.message;
}

// compare reads the stored samples: a 16-bit file (with its gAMA chunk) and the 8-bit file of the same
// picture are identical ("max delta 58" before: the 16-bit file was converted as linear light to sRGB).
TEST_F(CliTest, CompareReadsTheStoredSamplesOfSixteenBitFiles) {
    shadelab::Image picture(16, 8);
    for (std::size_t i = 0; i < picture.rgba.size(); ++i) picture.rgba[i] = std::uint8_t(i * 37 % 256);
    shadelab::writePng(picture, dir_ / "eight.png");
    writeSixteenBitPng(picture, dir_ / "sixteen.png");
    ASSERT_EQ(readFile(dir_ / "sixteen.png")[24], 16) << "IHDR's bit depth: the file is not 16-bit";
    const Outcome r = shadelab({"compare", "sixteen.png", "eight.png"});
    EXPECT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_TRUE(r.out.starts_with("pass: max delta 0,")) << r.out;
}

std::uint32_t crc32Of(std::string_view bytes) {
    std::uint32_t crc = 0xffffffffu;
    for (const char byte : bytes) {
        crc ^= std::uint8_t(byte);
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

std::string pngChunk(std::string_view type, std::string_view data) {
    auto big32 = [](std::uint32_t v) {
        return std::string{char(v >> 24), char(v >> 16 & 0xff), char(v >> 8 & 0xff), char(v & 0xff)};
    };
    const std::string body = std::string(type) + std::string(data);
    return big32(std::uint32_t(data.size())) + body + big32(crc32Of(body));
}

// A 69-byte file whose (valid) header claims 32768x32768 pixels cost 4.2 GB and 16 s before "image too
// large": the header is checked against what the file can hold before anything is allocated.
TEST_F(CliTest, CompareRefusesAForgedHeaderBeforeAllocating) {
    std::string ihdr = {0, 0, char(0x80), 0, 0, 0, char(0x80), 0, 8, 2, 0, 0, 0}; // 32768x32768, 8-bit RGB
    const std::string idat = {0x78, 0x01, 0x01, 0x00, 0x00, char(0xff), char(0xff)};
    const std::string forged = std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", ihdr) +
                               pngChunk("IDAT", idat) + pngChunk("IEND", "");
    writeFile(dir_ / "forged.png", forged);
    shadelab::writePng(filled(8, 8, 0), dir_ / "b.png");
    const auto start = std::chrono::steady_clock::now();
    const Outcome r = shadelab({"compare", "forged.png", "b.png"});
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find("32768x32768"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("cannot hold"), std::string::npos) << r.err;
}

// --diff is an output: never one of the inputs (by inode, so no link or hard link either), never standard
// output (which carries the summary); refused with exit 2 before anything is read.
TEST_F(CliTest, CompareDiffNamingAnInputIsRefused) {
    shadelab::writePng(filled(8, 8, 0), dir_ / "a.png");
    shadelab::writePng(filled(8, 8, 200), dir_ / "b.png");
    shadelab::writePng(filled(8, 8, 255), dir_ / "mask.png");
    fs::create_symlink("b.png", dir_ / "link.png");
    fs::create_hard_link(dir_ / "mask.png", dir_ / "hard.png");
    const std::string before =
        readFile(dir_ / "a.png") + readFile(dir_ / "b.png") + readFile(dir_ / "mask.png");
    for (const char* diff : {"a.png", "b.png", "link.png", "hard.png"}) {
        const Outcome r = shadelab({"compare", "a.png", "b.png", "--mask", "mask.png", "--diff", diff});
        EXPECT_EQ(r.exitCode, 2) << diff << ": " << describe(r);
        EXPECT_NE(r.err.find("--diff"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("is the input file"), std::string::npos) << r.err;
        EXPECT_TRUE(r.out.empty()) << "refused before comparing: " << r.out;
    }
    EXPECT_EQ(readFile(dir_ / "a.png") + readFile(dir_ / "b.png") + readFile(dir_ / "mask.png"), before);
    EXPECT_TRUE(fs::is_symlink(dir_ / "link.png"));
    const Outcome dash = shadelab({"compare", "a.png", "b.png", "--diff", "-"});
    EXPECT_EQ(dash.exitCode, 2) << describe(dash);
    EXPECT_NE(dash.err.find("--diff -"), std::string::npos) << dash.err;
    EXPECT_TRUE(dash.out.empty()) << "no PNG interleaved with the summary";
}

// Different sizes: both named, and the difference image still written (a pixel only one image has is a
// full difference).
TEST_F(CliTest, CompareOfDifferentSizesNamesBothAndWritesTheDiff) {
    shadelab::writePng(filled(16, 16, 0), dir_ / "a.png");
    shadelab::writePng(filled(16, 8, 0), dir_ / "b.png");
    const Outcome r = shadelab({"compare", "a.png", "b.png", "--diff", "d.png"});
    EXPECT_EQ(r.exitCode, 1) << describe(r);
    EXPECT_NE(r.out.find("actual 16x16, expected 16x8"), std::string::npos) << r.out;
    const std::optional<PngSize> size = pngSize(readFile(dir_ / "d.png"));
    ASSERT_TRUE(size) << "no difference image";
    EXPECT_EQ(size->width, 16u);
    EXPECT_EQ(size->height, 16u);
}

// ---- the limits of compare/judge.h ----

// An 8-bit RGBA PNG that keeps its alpha (writePng writes RGB).
void writeRgbaPng(const shadelab::Image& image, const fs::path& path) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = png_uint_32(image.width);
    png.height = png_uint_32(image.height);
    png.format = PNG_FORMAT_RGBA;
    ASSERT_TRUE(png_image_write_to_file(&png, path.c_str(), 0, image.rgba.data(), 0, nullptr)) << png.message;
}

// 64x64 grey, and the same with an 8x8 light square at (8, 8): a difference every metric sees.
void writeSquarePair(const fs::path& dir) {
    const shadelab::Image grey = filled(64, 64, 60);
    shadelab::Image square = grey;
    shadelab::fillRect(square, 8, 8, 8, 8, {220, 220, 220, 255});
    shadelab::writePng(square, dir / "square.png");
    shadelab::writePng(grey, dir / "grey.png");
}

std::vector<std::string> plus(std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

// Alpha is compared: a fully transparent picture fails against the opaque one of the same colour, and
// passes with --ignore-alpha, which the JSON says.
TEST_F(CliTest, CompareComparesAlphaUnlessIgnored) {
    shadelab::Image transparent = filled(16, 16, 120);
    for (std::size_t i = 3; i < transparent.rgba.size(); i += 4) transparent.rgba[i] = 0;
    writeRgbaPng(transparent, dir_ / "transparent.png");
    shadelab::writePng(filled(16, 16, 120), dir_ / "opaque.png");
    const Outcome compared = shadelab({"compare", "transparent.png", "opaque.png", "--json"});
    EXPECT_EQ(compared.exitCode, 1) << describe(compared);
    const nlohmann::json j = nlohmann::json::parse(compared.out);
    EXPECT_EQ(j["alpha_compared"], true);
    EXPECT_EQ(j["max_delta"], 255);
    const Outcome ignored = shadelab({"compare", "transparent.png", "opaque.png", "--ignore-alpha",
                                      "--perceptual-max-pixels", "0", "--json"});
    EXPECT_EQ(ignored.exitCode, 0) << describe(ignored);
    const nlohmann::json k = nlohmann::json::parse(ignored.out);
    EXPECT_EQ(k["alpha_compared"], false);
    EXPECT_EQ(k["max_delta"], 0);
    EXPECT_EQ(k["perceptual"]["differing_pixels"], 0) << "nor does the perceptual delta see alpha";
}

// --ignore leaves its rectangles out of every figure, and --diff draws what was left out (by --ignore or
// --mask) dark grey rather than as a difference.
TEST_F(CliTest, CompareIgnoreAndMaskLeaveOutAndTheDiffShowsIt) {
    writeSquarePair(dir_);
    const Outcome whole = shadelab({"compare", "square.png", "grey.png"});
    EXPECT_EQ(whole.exitCode, 1) << describe(whole);
    const Outcome ignored =
        shadelab({"compare", "square.png", "grey.png", "--ignore", "8,8,8,8", "--perceptual-max-pixels", "0",
                  "--json"}); // not --ssim-min 1: SSIM windows next to the rectangle still reach into it
    EXPECT_EQ(ignored.exitCode, 0) << describe(ignored);
    const nlohmann::json j = nlohmann::json::parse(ignored.out);
    EXPECT_EQ(j["compared_pixels"], 64 * 64 - 64);
    EXPECT_EQ(j["ignore"], (nlohmann::json::array({{{"x", 8}, {"y", 8}, {"width", 8}, {"height", 8}}})));

    // Half the square ignored, and a mask leaving out the first row: the diff shows each as grey.
    shadelab::Image mask = filled(64, 64, 255);
    shadelab::fillRect(mask, 0, 0, 64, 1, {0, 0, 0, 255});
    shadelab::writePng(mask, dir_ / "mask.png");
    const Outcome half = shadelab({"compare", "square.png", "grey.png", "--ignore", "8,8,4,8", "--mask",
                                   "mask.png", "--diff", "d.png"});
    EXPECT_EQ(half.exitCode, 1) << describe(half);
    EXPECT_NE(half.out.find("dark grey"), std::string::npos) << half.out;
    const shadelab::Image diff = shadelab::readPng(dir_ / "d.png");
    const auto at = [&](int x, int y) {
        const std::uint8_t* p = diff.pixel(x, y);
        return glm::u8vec4(p[0], p[1], p[2], p[3]);
    };
    EXPECT_EQ(at(9, 9), shadelab::kDiffLeftOut) << "inside --ignore";
    EXPECT_EQ(at(20, 0), shadelab::kDiffLeftOut) << "black in --mask";
    EXPECT_EQ(at(13, 9), glm::u8vec4(255, 255, 255, 255)) << "compared and different: 160 x8, clamped";
    EXPECT_EQ(at(20, 20), glm::u8vec4(0, 0, 0, 255)) << "compared and the same";
}

// Each metric's flag fails the comparison beyond its limit and passes within it, figures from --json.
TEST_F(CliTest, CompareEachMetricLimitPassesAndFails) {
    writeSquarePair(dir_);
    const std::vector<std::string> loose{"compare", "square.png", "grey.png", "--max",
                                         "255",     "--mean",     "255",      "--json"};
    const Outcome figures = shadelab(loose);
    ASSERT_EQ(figures.exitCode, 0) << describe(figures);
    const nlohmann::json f = nlohmann::json::parse(figures.out);
    const double ssim = f["ssim"].get<double>();
    const long differing = f["perceptual"]["differing_pixels"].get<long>();
    ASSERT_LT(ssim, 0.99);
    ASSERT_GT(differing, 0);
    const auto number = [](double v) { return std::to_string(v); };
    struct Row {
        std::vector<std::string> passing, failing;
        std::string flag;
    };
    const std::vector<Row> rows{
        {{"--ssim-min", number(ssim - 0.001)}, {"--ssim-min", number(ssim + 0.001)}, "--ssim-min"},
        {{"--perceptual-max-pixels", std::to_string(differing)},
         {"--perceptual-max-pixels", std::to_string(differing - 1)},
         "--perceptual-max-pixels"},
        // 60 against 220 is a YIQ delta far under threshold 1's 35215: nothing differs at 1.
        {{"--perceptual-max-pixels", "0", "--perceptual-threshold", "1"},
         {"--perceptual-max-pixels", "0", "--perceptual-threshold", "0.1"},
         "--perceptual-max-pixels"},
    };
    for (const Row& row : rows) {
        const Outcome pass = shadelab(plus(loose, row.passing));
        EXPECT_EQ(pass.exitCode, 0) << row.flag << ": " << describe(pass);
        const Outcome fail = shadelab(plus(loose, row.failing));
        EXPECT_EQ(fail.exitCode, 1) << row.flag << ": " << describe(fail);
        if (fail.exitCode != 1) continue;
        const nlohmann::json j = nlohmann::json::parse(fail.out);
        ASSERT_EQ(j["failures"].size(), 1u) << fail.out;
        EXPECT_NE(j["failures"][0].get<std::string>().find(row.flag), std::string::npos) << fail.out;
    }
}

// --json holds every figure and every limit, and a line for each failed limit; --heatmap's path when written.
TEST_F(CliTest, CompareJsonHoldsEveryFigureAndFailedLimit) {
    writeSquarePair(dir_);
    const Outcome r =
        shadelab({"compare", "square.png", "grey.png", "--ssim-min", "0.999", "--perceptual-max-pixels", "3",
                  "--perceptual-threshold", "0.05", "--ignore", "0,0,2,2", "--heatmap", "h.png", "--json"});
    EXPECT_EQ(r.exitCode, 1) << describe(r);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    const nlohmann::json& l = j["limits"];
    EXPECT_EQ(l["ssim_min"], 0.999);
    EXPECT_EQ(l["perceptual_max_pixels"], 3);
    EXPECT_EQ(l["perceptual_threshold"], 0.05);
    EXPECT_TRUE(j["ssim"].is_number());
    EXPECT_TRUE(j["perceptual"]["differing_pixels"].is_number_integer());
    EXPECT_TRUE(j["perceptual"]["antialiased_pixels"].is_number_integer());
    EXPECT_EQ(j["perceptual"]["threshold"], 0.05);
    EXPECT_EQ(j["alpha_compared"], true);
    EXPECT_EQ(j["ignore"].size(), 1u);
    std::string failures;
    for (const auto& f : j["failures"]) failures += f.get<std::string>() + "\n";
    for (const char* flag : {"--max", "--ssim-min", "--perceptual-max-pixels"})
        EXPECT_NE(failures.find(flag), std::string::npos) << flag << " not among\n" << failures;
    EXPECT_EQ(j["heatmap"], "h.png");
    const shadelab::Image heat = shadelab::readPng(dir_ / "h.png");
    EXPECT_GE(heat.width, 64);
    EXPECT_GT(heat.height, 64) << "the picture and its scale under it";
}

// A bad value exits 2 before anything is read, naming the flag and the value.
TEST_F(CliTest, CompareRefusesBadLimitValuesByName) {
    shadelab::writePng(filled(16, 16, 0), dir_ / "a.png");
    const std::vector<std::pair<std::string, std::string>> bad{
        {"--ssim-min", "nan"},
        {"--ssim-min", "1.5"},
        {"--mean", "nan"},
        {"--mean", "-1"},
        {"--max", "256"},
        {"--outliers", "-3"},
        {"--perceptual-max-pixels", "-1"},
        {"--perceptual-max-pixels", "2.5"},
        {"--perceptual-threshold", "1.5"},
        {"--perceptual-threshold", "inf"},
        {"--ignore", "1,2,3"},
        {"--ignore", "0,0,0,5"},
        {"--ignore", "a,b,c,d"},
        {"--ignore", "1,2,3,4,5"},
        {"--ignore", "10,0,10,10"}, // past the right edge of 16x16
    };
    for (const auto& [flag, value] : bad) {
        const Outcome r = shadelab({"compare", "a.png", "a.png", flag, value});
        EXPECT_EQ(r.exitCode, 2) << flag << " " << value << ": " << describe(r);
        EXPECT_NE(r.err.find(flag), std::string::npos) << describe(r);
        EXPECT_NE(r.err.find(value), std::string::npos) << describe(r);
        EXPECT_TRUE(r.out.empty()) << describe(r);
    }
}

// The light program answers as shadelab does: the same JSON to the byte, the same exit codes.
TEST_F(CliTest, ShadelabCompareGivesTheSameAnswers) {
    writeSquarePair(dir_);
    RunOptions light;
    light.program = SHADELAB_COMPARE_EXE;
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"compare", "square.png", "grey.png", "--json", "--ssim-min", "0.9"},
             {"compare", "grey.png", "grey.png", "--json", "--ignore", "1,1,4,4"},
             {"compare", "grey.png", "grey.png", "--ssim-min", "nan"},
             {"compare", "square.png", "grey.png", "--max", "255", "--mean", "255"}}) {
        const Outcome full = shadelab(args);
        const Outcome small = runWith(args, dir_, light);
        EXPECT_EQ(small.exitCode, full.exitCode) << describe(small) << describe(full);
        EXPECT_EQ(small.out, full.out);
    }
}

} // namespace
