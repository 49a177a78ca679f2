// The XWD reader on files built here byte by byte, so what the window test sees of a capture is known to be
// decoded right: both byte orders, padded rows, a colormap and a window name to skip, and the rejections.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "window/xwd.h"

namespace shadelab::window_test {
namespace {

struct XwdFile {
    std::uint32_t width = 3, height = 2, bytesPerLine = 16, byteOrder = kXwdLsbFirst, depth = 24, bpp = 32;
    std::uint32_t format = kXwdZPixmap, visualClass = kXwdTrueColor, ncolors = 2;
    std::uint32_t redMask = 0xff0000, greenMask = 0x00ff00, blueMask = 0x0000ff;
    std::string name = "shadelab";

    std::vector<std::uint8_t> bytes(const std::vector<std::uint32_t>& pixels) const {
        std::vector<std::uint32_t> header(kXwdFieldCount, 0);
        header[kXwdHeaderSize] = std::uint32_t(kXwdHeaderBytes + name.size() + 1);
        header[kXwdFileVersion] = kXwdVersion;
        header[kXwdPixmapFormat] = format;
        header[kXwdPixmapDepth] = depth;
        header[kXwdPixmapWidth] = header[kXwdWindowWidth] = width;
        header[kXwdPixmapHeight] = header[kXwdWindowHeight] = height;
        header[kXwdByteOrder] = byteOrder;
        header[kXwdBitsPerPixel] = bpp;
        header[kXwdBytesPerLine] = bytesPerLine;
        header[kXwdVisualClass] = visualClass;
        header[kXwdRedMask] = redMask;
        header[kXwdGreenMask] = greenMask;
        header[kXwdBlueMask] = blueMask;
        header[kXwdNColors] = ncolors;
        std::vector<std::uint8_t> out;
        for (std::uint32_t v : header)
            for (int shift : {24, 16, 8, 0}) out.push_back(std::uint8_t(v >> shift));
        out.insert(out.end(), name.begin(), name.end());
        out.push_back(0);
        out.insert(out.end(), ncolors * kXwdColorBytes, 0xab); // colormap entries: skipped, not read
        for (std::uint32_t y = 0; y < height; ++y) {
            // Padding past the pixels; wide enough for them even when bytesPerLine is (deliberately) too
            // short.
            std::vector<std::uint8_t> row(std::max<std::size_t>(bytesPerLine, std::size_t(width) * 4), 0xcd);
            for (std::uint32_t x = 0; x < width; ++x) {
                const std::uint32_t p = pixels[y * width + x];
                for (int i = 0; i < 4; ++i)
                    row[x * 4 + std::uint32_t(i)] =
                        std::uint8_t(p >> (byteOrder == kXwdLsbFirst ? 8 * i : 24 - 8 * i));
            }
            out.insert(out.end(), row.begin(), row.begin() + std::ptrdiff_t(bytesPerLine));
        }
        return out;
    }
};

const std::vector<std::uint32_t> kPixels = {
    0x00ff0000, 0x0000ff00, 0x000000ff,  // red, green, blue
    0xff102030, 0x00ffffff, 0x00000000}; // unused byte set, white, black

void expectPixel(const Image& image, int x, int y, int r, int g, int b) {
    const std::uint8_t* p = image.pixel(x, y);
    EXPECT_EQ(int(p[0]), r) << "red at " << x << "," << y;
    EXPECT_EQ(int(p[1]), g) << "green at " << x << "," << y;
    EXPECT_EQ(int(p[2]), b) << "blue at " << x << "," << y;
    EXPECT_EQ(int(p[3]), 255) << "alpha at " << x << "," << y;
}

void expectKnownPixels(const Image& image) {
    ASSERT_EQ(image.width, 3);
    ASSERT_EQ(image.height, 2);
    expectPixel(image, 0, 0, 255, 0, 0);
    expectPixel(image, 1, 0, 0, 255, 0);
    expectPixel(image, 2, 0, 0, 0, 255);
    expectPixel(image, 0, 1, 0x10, 0x20, 0x30);
    expectPixel(image, 1, 1, 255, 255, 255);
    expectPixel(image, 2, 1, 0, 0, 0);
}

TEST(Xwd, ReadsLsbFirstWithPaddedRows) {
    expectKnownPixels(parseXwd(XwdFile{}.bytes(kPixels), "test"));
}

TEST(Xwd, ReadsMsbFirst) {
    XwdFile file;
    file.byteOrder = kXwdMsbFirst;
    expectKnownPixels(parseXwd(file.bytes(kPixels), "test"));
}

TEST(Xwd, FollowsTheMasks) {
    XwdFile file; // BGR order instead of RGB
    file.redMask = 0x0000ff;
    file.blueMask = 0xff0000;
    const Image image = parseXwd(file.bytes(kPixels), "test");
    expectPixel(image, 0, 0, 0, 0, 255);
    expectPixel(image, 0, 1, 0x30, 0x20, 0x10);
}

void expectRejected(const XwdFile& file, const std::string& field) {
    try {
        parseXwd(file.bytes(kPixels), "test.xwd");
        ADD_FAILURE() << "accepted a file with a bad " << field;
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("test.xwd"), std::string::npos) << e.what();
    }
}

TEST(Xwd, RejectsWhatItCannotDecode) {
    XwdFile f;
    f.bpp = 24;
    expectRejected(f, "bits_per_pixel");
    f = {};
    f.depth = 16;
    expectRejected(f, "pixmap_depth");
    f = {};
    f.format = 1; // XYPixmap
    expectRejected(f, "pixmap_format");
    f = {};
    f.visualClass = 3; // PseudoColor
    expectRejected(f, "visual_class");
    f = {};
    f.bytesPerLine = 8;
    expectRejected(f, "bytes_per_line");
    f = {};
    f.byteOrder = 7;
    expectRejected(f, "byte_order");
    f = {};
    f.greenMask = 0xff00ff;
    expectRejected(f, "green_mask");
}

TEST(Xwd, RejectsATruncatedFile) {
    std::vector<std::uint8_t> bytes = XwdFile{}.bytes(kPixels);
    bytes.pop_back();
    EXPECT_THROW(parseXwd(bytes, "test"), std::runtime_error);
    bytes.resize(50);
    EXPECT_THROW(parseXwd(bytes, "test"), std::runtime_error);
}

} // namespace
} // namespace shadelab::window_test
