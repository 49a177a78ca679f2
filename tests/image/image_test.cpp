// Images without GL: PNG I/O (round trip, atomic writes, loud failures), the float → 8-bit rule, the
// regression comparison, and the drawing helpers used to label report images.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include "shadelab/errors.h"
#include "shadelab/image/image.h"
#include "shadelab/image/image_file.h"

namespace shadelab {
namespace {

namespace fs = std::filesystem;

constexpr glm::u8vec4 kWhite{255, 255, 255, 255};
constexpr const char* kTimesUtf8 = "\xC3\x97"; // ×, spelled as bytes to test the decoder

// A fresh directory per test, so the "nothing left behind" checks see only what the test wrote.
class ImageFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "shadelab_image_test.XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr) << "mkdtemp failed";
        dir_ = pattern;
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::vector<fs::path> entries() const {
        std::vector<fs::path> result;
        for (const auto& entry : fs::directory_iterator(dir_)) result.push_back(entry.path());
        return result;
    }

    fs::path dir_;
};

// Every channel value appears, and alpha varies, so a round trip has something to get wrong.
Image gradient(int w, int h, std::uint8_t seed = 0) {
    Image image(w, h);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = std::uint8_t(i * 7 + seed);
    return image;
}

void expectSameRgbOpaque(const Image& actual, const Image& expected) {
    ASSERT_EQ(actual.width, expected.width);
    ASSERT_EQ(actual.height, expected.height);
    for (int y = 0; y < expected.height; ++y)
        for (int x = 0; x < expected.width; ++x) {
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(actual.pixel(x, y)[c], expected.pixel(x, y)[c])
                    << x << "," << y << " channel " << c;
            ASSERT_EQ(actual.pixel(x, y)[3], 255) << x << "," << y;
        }
}

template <typename F> std::string runtimeErrorMessage(F&& f) {
    try {
        f();
    } catch (const RuntimeError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no RuntimeError thrown";
    return {};
}

// ---- PNG I/O ----

TEST_F(ImageFileTest, PngRoundTripKeepsRgbAndReadsOpaque) {
    const Image image = gradient(37, 19);
    const fs::path path = dir_ / "round.png";
    writePng(image, path);
    expectSameRgbOpaque(readPng(path), image);
}

TEST_F(ImageFileTest, SuccessfulWriteLeavesOnlyTheTarget) {
    const fs::path path = dir_ / "only.png";
    writePng(gradient(4, 4), path);
    EXPECT_EQ(entries(), std::vector<fs::path>{path});
}

TEST_F(ImageFileTest, WriteReplacesAnExistingFileByRename) {
    const fs::path path = dir_ / "replace.png";
    writePng(gradient(8, 8, 1), path);
    struct stat before {};
    ASSERT_EQ(::stat(path.c_str(), &before), 0);

    const Image second = gradient(5, 3, 99);
    writePng(second, path);
    struct stat after {};
    ASSERT_EQ(::stat(path.c_str(), &after), 0);

    // A new inode shows the file was swapped in whole, never rewritten in place.
    EXPECT_NE(before.st_ino, after.st_ino);
    expectSameRgbOpaque(readPng(path), second);
    EXPECT_EQ(entries(), std::vector<fs::path>{path});
}

TEST_F(ImageFileTest, WriteIntoMissingDirectoryThrowsNamingThePath) {
    const fs::path path = dir_ / "missing" / "out.png";
    const std::string message = runtimeErrorMessage([&] { writePng(gradient(2, 2), path); });
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_FALSE(fs::exists(path));
    EXPECT_TRUE(entries().empty());
}

TEST_F(ImageFileTest, WriteOverADirectoryThrows) {
    const fs::path path = dir_ / "adir";
    fs::create_directory(path);
    const std::string message = runtimeErrorMessage([&] { writePng(gradient(2, 2), path); });
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find("directory"), std::string::npos) << message;
    EXPECT_TRUE(fs::is_directory(path));
    EXPECT_EQ(entries(), std::vector<fs::path>{path});
}

// Root ignores directory permissions, so as root the unwritable folder is /proc, where nobody can create
// a file.
TEST_F(ImageFileTest, WriteIntoProcThrowsAndLeavesNothing) {
    const std::string message =
        runtimeErrorMessage([&] { writePng(gradient(2, 2), "/proc/shadelab-out.png"); });
    EXPECT_NE(message.find("/proc/shadelab-out.png"), std::string::npos) << message;
    EXPECT_FALSE(fs::exists("/proc/shadelab-out.png"));
}

TEST_F(ImageFileTest, WriteIntoUnwritableDirectoryThrows) {
    if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions (WriteIntoProc covers root)";
    const fs::path locked = dir_ / "locked";
    fs::create_directory(locked);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
    const std::string message = runtimeErrorMessage([&] { writePng(gradient(2, 2), locked / "out.png"); });
    fs::permissions(locked, fs::perms::owner_all);
    EXPECT_NE(message.find("out.png"), std::string::npos) << message;
    EXPECT_TRUE(fs::is_empty(locked));
}

TEST_F(ImageFileTest, WriteOfEmptyImageThrowsAndLeavesNothing) {
    const fs::path path = dir_ / "empty.png";
    EXPECT_THROW(writePng(Image(0, 4), path), RuntimeError);
    EXPECT_THROW(writePng(Image(4, 0), path), RuntimeError);
    EXPECT_TRUE(entries().empty());
}

TEST_F(ImageFileTest, ReadOfMissingOrBrokenFileThrowsNamingThePath) {
    const fs::path missing = dir_ / "missing.png";
    EXPECT_NE(runtimeErrorMessage([&] { readPng(missing); }).find(missing.string()), std::string::npos);

    const fs::path broken = dir_ / "broken.png";
    std::ofstream(broken) << "not a png";
    EXPECT_NE(runtimeErrorMessage([&] { readPng(broken); }).find(broken.string()), std::string::npos);
}

// ---- float → 8-bit ----

TEST(ToUnorm8, ClampsRoundsHalfUpAndMapsNanToZero) {
    const double half = 0.5 / 255.0; // exactly 0.5 after ×255
    EXPECT_EQ(toUnorm8(-1.0), 0);
    EXPECT_EQ(toUnorm8(-0.0), 0);
    EXPECT_EQ(toUnorm8(0.0), 0);
    EXPECT_EQ(toUnorm8(std::nextafter(half, 0.0)), 0);
    EXPECT_EQ(toUnorm8(half), 1);
    EXPECT_EQ(toUnorm8(127.5 / 255.0), 128);
    EXPECT_EQ(toUnorm8(1.0), 255);
    EXPECT_EQ(toUnorm8(2.0), 255);
    EXPECT_EQ(toUnorm8(std::numeric_limits<double>::quiet_NaN()), 0);
    EXPECT_EQ(toUnorm8(std::numeric_limits<double>::infinity()), 255);
    EXPECT_EQ(toUnorm8(-std::numeric_limits<double>::infinity()), 0);
}

TEST(ToImage8, ConvertsEveryChannel) {
    ImageF image(2, 1);
    image.rgba = {0.0f, 0.5f, 1.0f, 1.0f, -3.0f, 7.0f, std::nanf(""), 0.0f};
    const Image result = toImage8(image);
    EXPECT_EQ(result.width, 2);
    EXPECT_EQ(result.height, 1);
    EXPECT_EQ(result.rgba, (std::vector<std::uint8_t>{0, 128, 255, 255, 0, 255, 0, 0}));
}

TEST(ImageConstruction, IsZeroFilled) {
    const Image image(3, 2);
    EXPECT_EQ(image.rgba, std::vector<std::uint8_t>(24, 0));
    const ImageF imageF(2, 2);
    EXPECT_EQ(imageF.rgba, std::vector<float>(16, 0.0f));
}

// ---- scan and compare ----

TEST(ScanValues, CountsNonFiniteAndOutOfRangeSeparately) {
    const float nan = std::nanf(""), inf = std::numeric_limits<float>::infinity();
    ImageF image(2, 2);
    image.rgba = {nan,  inf,  -0.1f, 1.1f, // 2 non-finite, 2 out of range
                  0.0f, 1.0f, 0.5f,  -inf, // the bounds are inside; −inf is non-finite only
                  0.2f, 0.3f, 0.4f,  0.6f, //
                  0.7f, 0.8f, 0.9f,  1.0f};
    const ValueScan scan = scanValues(image);
    EXPECT_EQ(scan.nonFinite, 3u);
    EXPECT_EQ(scan.outOfRange, 2u);
    EXPECT_EQ(scanValues(image, -1.0f, 2.0f).outOfRange, 0u);
}

TEST(CompareImages, IdenticalImagesPassWithZeros) {
    const Image image = gradient(16, 16);
    const Comparison result = compareImages(image, image, {});
    EXPECT_TRUE(result.passed) << result.summary();
    EXPECT_TRUE(result.sizeMatches);
    EXPECT_EQ(result.maxDelta, 0);
    EXPECT_EQ(result.meanDelta, 0.0);
    EXPECT_EQ(result.outliers, 0);
}

TEST(CompareImages, OutlierBudgetDecides) {
    const Image expected = gradient(10, 10);
    Image actual = expected;
    actual.pixel(3, 4)[1] += 10;

    const Comparison strict =
        compareImages(actual, expected, {.maxDelta = 2, .meanDelta = 1.0, .outlierBudget = 0});
    EXPECT_FALSE(strict.passed);
    EXPECT_EQ(strict.outliers, 1);
    EXPECT_EQ(strict.maxDelta, 10);

    const Comparison lenient =
        compareImages(actual, expected, {.maxDelta = 2, .meanDelta = 1.0, .outlierBudget = 1});
    EXPECT_TRUE(lenient.passed) << lenient.summary();
    EXPECT_EQ(lenient.maxDelta, 10); // the true maximum, outliers included
}

TEST(CompareImages, MeanIsOverAllColourChannelsAndIgnoresAlpha) {
    Image expected(2, 2), actual(2, 2);
    actual.pixel(0, 0)[0] = 12;  // R
    actual.pixel(1, 1)[2] = 6;   // B
    actual.pixel(1, 0)[3] = 200; // alpha: not compared
    const Comparison result = compareImages(actual, expected, {.maxDelta = 255, .meanDelta = 1.5});
    EXPECT_DOUBLE_EQ(result.meanDelta, 18.0 / 12.0);
    EXPECT_EQ(result.maxDelta, 12);
    EXPECT_TRUE(result.passed) << result.summary();
    EXPECT_FALSE(compareImages(actual, expected, {.maxDelta = 255, .meanDelta = 1.4}).passed);
}

TEST(CompareImages, SizeMismatchFails) {
    const Comparison result = compareImages(Image(4, 4), Image(4, 5), {.maxDelta = 255, .meanDelta = 255});
    EXPECT_FALSE(result.sizeMatches);
    EXPECT_FALSE(result.passed);
    EXPECT_NE(result.summary().find("size"), std::string::npos) << result.summary();
}

TEST(CompareImages, SummaryCarriesTheNumbers) {
    Image expected(2, 2), actual(2, 2);
    actual.pixel(0, 0)[0] = 12;
    const std::string summary = compareImages(actual, expected, {.maxDelta = 2}).summary();
    EXPECT_NE(summary.find("FAIL"), std::string::npos) << summary;
    EXPECT_NE(summary.find("12"), std::string::npos) << summary;
    EXPECT_NE(summary.find("1.0000"), std::string::npos) << summary;
}

TEST(DiffImage, AmplifiesByEightClampsAndIsOpaque) {
    Image expected(2, 1), actual(2, 1);
    actual.pixel(0, 0)[0] = 3;   // 24
    actual.pixel(0, 0)[1] = 40;  // 320 → 255
    expected.pixel(1, 0)[2] = 1; // |−1| → 8
    actual.pixel(1, 0)[3] = 77;  // alpha differences are not shown
    const Image diff = diffImage(actual, expected);
    EXPECT_EQ(diff.rgba, (std::vector<std::uint8_t>{24, 255, 0, 255, 0, 0, 8, 255}));
}

// ---- drawing ----

int countLit(const Image& image, int x0 = 0, int y0 = 0, int x1 = INT32_MAX, int y1 = INT32_MAX) {
    int count = 0;
    for (int y = std::max(y0, 0); y < std::min(y1, image.height); ++y)
        for (int x = std::max(x0, 0); x < std::min(x1, image.width); ++x) count += image.pixel(x, y)[3] != 0;
    return count;
}

TEST(FillRectAndBlit, AreClippedToTheCanvas) {
    Image canvas(8, 8);
    fillRect(canvas, -2, 6, 4, 10, kWhite);
    EXPECT_EQ(countLit(canvas), 2 * 2);
    fillRect(canvas, 100, 100, 5, 5, kWhite);
    fillRect(canvas, 0, 0, -3, 4, kWhite);
    EXPECT_EQ(countLit(canvas), 4);

    Image tile(3, 3);
    fillRect(tile, 0, 0, 3, 3, {1, 2, 3, 4});
    Image target(4, 4);
    blit(target, tile, 2, -1);
    EXPECT_EQ(countLit(target), 2 * 2);
    EXPECT_EQ(target.pixel(3, 1)[2], 3);
    EXPECT_EQ(target.pixel(1, 0)[3], 0);
}

// The labels' font (DejaVu Sans Mono Bold through stb_truetype): glyphs land inside the line box the
// layout functions promise, scale grows them, and the text is what it says (no longer upper-cased).
TEST(DrawText, GlyphsLieInsideTheirLineBox) {
    Image canvas(80, 40);
    drawText(canvas, 3, 4, "Ag", 1, kWhite);
    EXPECT_GT(countLit(canvas), 20);
    EXPECT_EQ(countLit(canvas, 3, 4, 3 + textWidth("Ag", 1), 4 + textLineHeight(1)), countLit(canvas));
    EXPECT_EQ(canvas.pixel(0, 0)[3], 0);
}

TEST(DrawText, ScaleGrowsTheGlyphsAndTheirBox) {
    Image one(80, 80), two(80, 80);
    drawText(one, 0, 0, "A", 1, kWhite);
    drawText(two, 0, 0, "A", 2, kWhite);
    EXPECT_GT(countLit(two), 3 * countLit(one)); // about 4×: antialiased edges round differently
    EXPECT_LT(countLit(two), 5 * countLit(one));
    EXPECT_EQ(textLineHeight(2), 2 * textLineHeight(1));
    EXPECT_NEAR(textWidth("A", 2), 2 * textWidth("A", 1), 1); // advances round to whole pixels
}

TEST(DrawText, LowerCaseIsItsOwnGlyphAndUtf8IsDecoded) {
    Image upper(60, 20), lower(60, 20), accent(20, 20), plain(20, 20);
    drawText(upper, 0, 0, "PHONG", 1, kWhite);
    drawText(lower, 0, 0, "phong", 1, kWhite);
    EXPECT_NE(upper.rgba, lower.rgba);
    drawText(accent, 0, 0, "\xC3\xA9", 1, kWhite); // é, two bytes: one glyph
    drawText(plain, 0, 0, "e", 1, kWhite);
    EXPECT_GT(countLit(accent), countLit(plain)) << "é is e with its accent";
    EXPECT_EQ(textWidth("\xC3\xA9", 1), textWidth("e", 1));
}

TEST(TextWidth, IsTheAdvanceOfAMonospacedFont) {
    EXPECT_EQ(textWidth("", 3), 0);
    EXPECT_EQ(textWidth("AB", 1), 2 * textWidth("A", 1));
    EXPECT_EQ(textWidth(kTimesUtf8, 1), textWidth("x", 1));
    EXPECT_EQ(textWidth("A", 0), 0);
}

TEST(DrawText, ClipsAtEveryEdgeWithoutCrashing) {
    Image canvas(16, 16);
    drawText(canvas, 12, 12, "HELLO", 3, kWhite);
    drawText(canvas, -20, -5, "WORLD", 2, kWhite);
    drawText(canvas, -2'000'000'000, 2'000'000'000, "FAR", 1'000'000, kWhite);
    drawText(canvas, 0, 0, "M", 1'000'000'000, kWhite);
    EXPECT_EQ(countLit(canvas, 0, 0, 16, 16), countLit(canvas));
    EXPECT_GT(countLit(canvas), 0);
}

} // namespace
} // namespace shadelab
