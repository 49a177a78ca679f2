#include "window/xwd.h"

#include <array>
#include <bit>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace shadelab::window_test {
namespace {

constexpr std::array<const char*, kXwdFieldCount> kFieldNames = {
    "header_size",   "file_version",   "pixmap_format",  "pixmap_depth",     "pixmap_width",
    "pixmap_height", "xoffset",        "byte_order",     "bitmap_unit",      "bitmap_bit_order",
    "bitmap_pad",    "bits_per_pixel", "bytes_per_line", "visual_class",     "red_mask",
    "green_mask",    "blue_mask",      "bits_per_rgb",   "colormap_entries", "ncolors",
    "window_width",  "window_height",  "window_x",       "window_y",         "window_bdrwidth"};

std::uint32_t bigEndian32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

std::uint32_t littleEndian32(const std::uint8_t* p) {
    return std::uint32_t(p[3]) << 24 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[1]) << 8 | p[0];
}

// One colour channel of a TrueColor visual: where its bits are and how to widen them to 8.
struct Channel {
    int shift = 0;
    std::uint32_t max = 0; // the largest value of the channel's bits
    std::uint8_t read(std::uint32_t pixel, std::uint32_t mask) const {
        const std::uint32_t value = (pixel & mask) >> shift;
        return std::uint8_t(max == 255 ? value : (value * 255 + max / 2) / max);
    }
};

class Parser {
public:
    Parser(std::span<const std::uint8_t> bytes, const std::string& source) : bytes_(bytes), source_(source) {}

    Image parse() {
        if (bytes_.size() < kXwdHeaderBytes)
            fail("the file has " + std::to_string(bytes_.size()) + " bytes, less than the 100-byte header");
        for (int i = 0; i < kXwdFieldCount; ++i)
            header_[std::size_t(i)] = bigEndian32(&bytes_[std::size_t(i) * 4]);
        expect(kXwdFileVersion, kXwdVersion, "XWD version 7");
        expect(kXwdPixmapFormat, kXwdZPixmap, "ZPixmap");
        expect(kXwdVisualClass, kXwdTrueColor, "a TrueColor visual");
        expect(kXwdPixmapDepth, 24, "a 24-bit-depth window");
        expect(kXwdBitsPerPixel, 32, "32 bits per pixel at depth 24");
        expect(kXwdXOffset, 0, "no x offset");
        if (field(kXwdByteOrder) != kXwdLsbFirst && field(kXwdByteOrder) != kXwdMsbFirst)
            fail("byte_order is " + std::to_string(field(kXwdByteOrder)) + ", expected 0 (LSBFirst) or 1");
        if (field(kXwdHeaderSize) < kXwdHeaderBytes)
            fail("header_size is " + std::to_string(field(kXwdHeaderSize)) + ", less than 100");

        const std::uint64_t width = field(kXwdPixmapWidth), height = field(kXwdPixmapHeight);
        const std::uint64_t bytesPerLine = field(kXwdBytesPerLine);
        if (width == 0 || height == 0 || width > 16384 || height > 16384)
            fail("pixmap size " + std::to_string(width) + "x" + std::to_string(height) + " is out of range");
        if (bytesPerLine < width * 4)
            fail("bytes_per_line is " + std::to_string(bytesPerLine) + ", less than 4 × width (" +
                 std::to_string(width * 4) + ")");
        const std::uint64_t imageOffset =
            std::uint64_t(field(kXwdHeaderSize)) + std::uint64_t(field(kXwdNColors)) * kXwdColorBytes;
        const std::uint64_t needed = imageOffset + bytesPerLine * height;
        if (bytes_.size() < needed)
            fail("the file has " + std::to_string(bytes_.size()) + " bytes; header_size + ncolors × 12 + " +
                 "bytes_per_line × height needs " + std::to_string(needed));

        const std::array<Channel, 3> channels = {channel(kXwdRedMask), channel(kXwdGreenMask),
                                                 channel(kXwdBlueMask)};
        if ((field(kXwdRedMask) & field(kXwdGreenMask)) || (field(kXwdRedMask) & field(kXwdBlueMask)) ||
            (field(kXwdGreenMask) & field(kXwdBlueMask)))
            fail("the colour masks overlap");
        const bool lsbFirst = field(kXwdByteOrder) == kXwdLsbFirst;

        Image image{int(width), int(height)};
        for (std::uint64_t y = 0; y < height; ++y) {
            const std::uint8_t* row = &bytes_[imageOffset + y * bytesPerLine];
            for (std::uint64_t x = 0; x < width; ++x) {
                const std::uint32_t pixel = lsbFirst ? littleEndian32(row + x * 4) : bigEndian32(row + x * 4);
                std::uint8_t* out = image.pixel(int(x), int(y));
                out[0] = channels[0].read(pixel, field(kXwdRedMask));
                out[1] = channels[1].read(pixel, field(kXwdGreenMask));
                out[2] = channels[2].read(pixel, field(kXwdBlueMask));
                out[3] = 255;
            }
        }
        return image;
    }

private:
    std::uint32_t field(XwdField f) const { return header_[std::size_t(f)]; }

    [[noreturn]] void fail(const std::string& why) const {
        throw std::runtime_error(
            "xwd: " + source_ + ": " + why +
            " (this reader takes a 24-bit TrueColor window as ZPixmap, 32 bits per pixel)");
    }

    void expect(XwdField f, std::uint32_t value, const char* meaning) const {
        if (field(f) != value)
            fail(std::string(kFieldNames[std::size_t(f)]) + " is " + std::to_string(field(f)) +
                 ", expected " + std::to_string(value) + " (" + meaning + ")");
    }

    // A mask must be one run of 1 to 16 bits.
    Channel channel(XwdField f) const {
        const std::uint32_t mask = field(f);
        const int shift = std::countr_zero(mask), bits = std::popcount(mask);
        if (mask == 0 || bits > 16 || (mask >> shift) != (std::uint32_t(1) << bits) - 1)
            fail(std::string(kFieldNames[std::size_t(f)]) + " is " + std::to_string(mask) +
                 ", not one run of 1 to 16 bits");
        return {shift, (std::uint32_t(1) << bits) - 1};
    }

    std::span<const std::uint8_t> bytes_;
    std::string source_;
    std::array<std::uint32_t, kXwdFieldCount> header_{};
};

} // namespace

Image parseXwd(std::span<const std::uint8_t> bytes, const std::string& source) {
    return Parser(bytes, source).parse();
}

Image readXwd(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("xwd: cannot open " + path.string());
    const std::vector<std::uint8_t> bytes(std::istreambuf_iterator<char>(in), {});
    return parseXwd(bytes, path.string());
}

} // namespace shadelab::window_test
