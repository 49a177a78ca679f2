// PNG I/O through libpng: encoded by its simplified API and written atomically (atomic_file.h); read by its
// low-level API, whole and checked, as the stored samples.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <functional>
#include <new>
#include <system_error>
#include <vector>

#include <png.h>

#include "shadelab/errors.h"
#include "shadelab/image/image.h"
#include "shadelab/image/image_file.h"
#include "shadelab/io/atomic_file.h"
#include "shadelab/io/text.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& path) {
    return "\"" + printable(path.string()) + "\"";
}

[[noreturn]] void writeFailed(const fs::path& path, const std::string& reason) {
    failWrite("PNG", path, reason);
}

[[noreturn]] void readFailed(const fs::path& path, const std::string& reason) {
    throw RuntimeError("cannot read PNG " + quoted(path) + ": " + reason);
}

// "" or why `image` cannot be a PNG.
std::string unwritableBecause(const Image& image) {
    if (image.width <= 0 || image.height <= 0)
        return "the image is empty (" + std::to_string(image.width) + "x" + std::to_string(image.height) +
               ")";
    if (image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
        return "the pixel buffer does not match the image size";
    return "";
}

void checkWritable(const Image& image, const fs::path& path) {
    if (const std::string why = unwritableBecause(image); !why.empty()) writeFailed(path, why);
    if (!path.has_filename()) writeFailed(path, "the path names no file");
    std::error_code error;
    if (fs::is_directory(path, error)) writeFailed(path, "it is a directory");
}

// The file is opaque: alpha is coverage, which only matters before the image is composited.
std::vector<std::uint8_t> dropAlpha(const Image& image) {
    std::vector<std::uint8_t> rgb(image.rgba.size() / 4 * 3);
    for (std::size_t src = 0, dst = 0; src < image.rgba.size(); src += 4, dst += 3)
        std::copy_n(&image.rgba[src], 3, &rgb[dst]);
    return rgb;
}

// Owns a png_image so every exit path releases libpng's state.
struct PngImage {
    png_image png{};
    PngImage() { png.version = PNG_IMAGE_VERSION; }
    PngImage(const PngImage&) = delete;
    PngImage& operator=(const PngImage&) = delete;
    ~PngImage() { png_image_free(&png); }
};

// Far beyond any render here; it stops a corrupt header from asking for gigabytes.
constexpr png_uint_32 kMaxPngSide = 1 << 15;

} // namespace

std::string encodePng(const Image& image) {
    if (const std::string why = unwritableBecause(image); !why.empty())
        throw RuntimeError("cannot encode PNG: " + why);
    const std::vector<std::uint8_t> rgb = dropAlpha(image);
    PngImage out;
    out.png.width = png_uint_32(image.width);
    out.png.height = png_uint_32(image.height);
    out.png.format = PNG_FORMAT_RGB;
    png_alloc_size_t size = 0;
    if (!png_image_write_get_memory_size(out.png, size, 0, rgb.data(), 0, nullptr))
        throw RuntimeError(std::string("cannot encode PNG: libpng: ") + out.png.message);
    std::string bytes(size, '\0');
    if (!png_image_write_to_memory(&out.png, bytes.data(), &size, 0, rgb.data(), 0, nullptr))
        throw RuntimeError(std::string("cannot encode PNG: libpng: ") + out.png.message);
    bytes.resize(size);
    return bytes;
}

// Encoded straight into the temporary file (not through encodePng): no second copy of a large picture.
void writePng(const Image& image, const fs::path& path, bool inFolder) {
    checkWritable(image, path);
    const std::vector<std::uint8_t> rgb = dropAlpha(image);
    writeFileAtomically(
        path, "PNG",
        [&](std::FILE* file) {
            PngImage out;
            out.png.width = png_uint_32(image.width);
            out.png.height = png_uint_32(image.height);
            out.png.format = PNG_FORMAT_RGB;
            if (!png_image_write_to_stdio(&out.png, file, 0, rgb.data(), 0, nullptr))
                writeFailed(path, std::string("libpng: ") + out.png.message);
        },
        inFolder ? OutputRule::InFolder : OutputRule::Anywhere);
}

namespace {

// libpng's low-level reader over bytes in memory. Its errors longjmp back to decodeRows (libpng is C:
// no C++ exception may cross it); the message is kept here for the exception thrown after.
struct MemorySource {
    const unsigned char* data = nullptr;
    std::size_t size = 0, offset = 0;
    char message[200] = "";
};

void readFromMemory(png_structp png, png_bytep out, png_size_t count) {
    auto* source = static_cast<MemorySource*>(png_get_io_ptr(png));
    if (count > source->size - source->offset) png_error(png, "truncated PNG: the data ends early");
    std::memcpy(out, source->data + source->offset, count);
    source->offset += count;
}

void keepError(png_structp png, png_const_charp message) {
    auto* source = static_cast<MemorySource*>(png_get_error_ptr(png));
    std::snprintf(source->message, sizeof source->message, "%s", message);
    png_longjmp(png, 1);
}

void ignoreWarning(png_structp, png_const_charp) {}

// The stored samples as 8-bit RGBA, whatever the file's colour type and depth: palettes and gray
// expanded, 16-bit samples scaled by 255/65535 and rounded (v/257), alpha 255 where the file has none. No
// gamma is applied (gAMA, sRGB and iCCP are ignored): two files holding the same samples compare equal.
// Between setjmp and the longjmp of an error no object with a destructor lives in this frame.
bool decodeRows(png_structp png, png_infop info, MemorySource& source, std::vector<std::uint8_t>& rgba,
                std::vector<png_bytep>& rows, png_uint_32& width, png_uint_32& height) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_read_fn(png, &source, readFromMemory);
    png_read_info(png, info);
    width = png_get_image_width(png, info);
    height = png_get_image_height(png, info);
    if (width > kMaxPngSide || height > kMaxPngSide) {
        std::snprintf(source.message, sizeof source.message, "implausible size %ux%u", unsigned(width),
                      unsigned(height));
        return false;
    }
    // Deflate expands at most about 1032:1: a header that claims more pixels than the file's bytes can
    // hold is corrupt or forged, and is refused before gigabytes are allocated for it.
    const double rowBytes =
        std::ceil(double(width) * png_get_channels(png, info) * png_get_bit_depth(png, info) / 8);
    if (double(height) * (rowBytes + 1) > 1032.0 * double(source.size) + 4096) {
        std::snprintf(source.message, sizeof source.message,
                      "the header claims %ux%u pixels, which %zu bytes cannot hold: a corrupt header",
                      unsigned(width), unsigned(height), source.size);
        return false;
    }
    png_set_expand(png);
    png_set_scale_16(png);
    png_set_gray_to_rgb(png);
    png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
    (void)png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_rowbytes(png, info) != std::size_t(width) * 4) {
        std::snprintf(source.message, sizeof source.message, "unexpected row layout");
        return false;
    }
    rgba.resize(std::size_t(width) * height * 4);
    rows.resize(height);
    for (png_uint_32 y = 0; y < height; ++y) rows[y] = rgba.data() + std::size_t(y) * width * 4;
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
    return true;
}

Image decodeStoredSamples(std::string_view bytes, const std::function<void(const std::string&)>& fail) {
    static constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
    if (bytes.size() < kSignature.size() || !bytes.starts_with(kSignature))
        fail("not a PNG (" + std::to_string(bytes.size()) + " bytes without the PNG signature)");
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_read_struct(&png, nullptr, nullptr);
        fail("libpng could not start");
    }
    MemorySource source;
    source.data = reinterpret_cast<const unsigned char*>(bytes.data());
    source.size = bytes.size();
    png_set_error_fn(png, &source, keepError, ignoreWarning);
    std::vector<std::uint8_t> rgba;
    std::vector<png_bytep> rows;
    png_uint_32 width = 0, height = 0;
    bool decoded = false;
    try {
        decoded = decodeRows(png, info, source, rgba, rows, width, height);
    } catch (const std::bad_alloc&) {
        png_destroy_read_struct(&png, &info, nullptr);
        throw RuntimeError("out of memory for a " + std::to_string(width) + "x" + std::to_string(height) +
                           " PNG");
    }
    png_destroy_read_struct(&png, &info, nullptr);
    if (!decoded) fail(source.message);
    Image image;
    image.width = int(width);
    image.height = int(height);
    image.rgba = std::move(rgba);
    return image;
}

} // namespace

Image readPng(const fs::path& path) {
    std::error_code error;
    if (fs::is_directory(path, error)) readFailed(path, "it is a directory");
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) readFailed(path, std::strerror(errno));
    std::string bytes;
    char buffer[1 << 16];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;) bytes.append(buffer, n);
    const bool failed = std::ferror(file) != 0;
    std::fclose(file);
    if (failed) readFailed(path, "read error");
    return decodeStoredSamples(bytes, [&](const std::string& reason) { readFailed(path, reason); });
}

Image decodePng(std::string_view bytes, std::string_view what) {
    auto fail = [&](const std::string& reason) { throw RuntimeError(std::string(what) + ": " + reason); };
    // IEND: length 0, type, CRC — the last 12 bytes of every complete PNG. A file cut off after its pixel
    // data would otherwise pass.
    static constexpr std::string_view kIend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
    if (bytes.starts_with("\x89PNG\r\n\x1a\n") && !bytes.ends_with(kIend))
        fail("truncated PNG: it does not end with the IEND chunk");
    return decodeStoredSamples(bytes, fail);
}

std::optional<PngSize> pngSize(std::string_view bytes) {
    static constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
    if (bytes.size() < 24 || !bytes.starts_with(kSignature) || bytes.substr(12, 4) != "IHDR")
        return std::nullopt;
    auto big32 = [&](std::size_t at) {
        std::uint32_t value = 0;
        for (std::size_t i = 0; i < 4; ++i) value = value << 8 | std::uint8_t(bytes[at + i]);
        return value;
    };
    return PngSize{big32(16), big32(20)};
}

} // namespace shadelab
