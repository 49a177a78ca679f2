// PNG I/O through libpng's simplified API: written atomically (atomic_file.h), read whole and checked.
#include <algorithm>
#include <system_error>

#include <png.h>

#include "shadelab/atomic_file.h"
#include "shadelab/errors.h"
#include "shadelab/image.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& path) {
    return "\"" + path.string() + "\"";
}

[[noreturn]] void writeFailed(const fs::path& path, const std::string& reason) {
    failWrite("PNG", path, reason);
}

[[noreturn]] void readFailed(const fs::path& path, const std::string& reason) {
    throw RuntimeError("cannot read PNG " + quoted(path) + ": " + reason);
}

void checkWritable(const Image& image, const fs::path& path) {
    if (image.width <= 0 || image.height <= 0)
        writeFailed(path, "the image is empty (" + std::to_string(image.width) + "x" +
                              std::to_string(image.height) + ")");
    if (image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
        writeFailed(path, "the pixel buffer does not match the image size");
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

void writePng(const Image& image, const fs::path& path) {
    checkWritable(image, path);
    const std::vector<std::uint8_t> rgb = dropAlpha(image);
    writeFileAtomically(path, "PNG", [&](std::FILE* file) {
        PngImage out;
        out.png.width = png_uint_32(image.width);
        out.png.height = png_uint_32(image.height);
        out.png.format = PNG_FORMAT_RGB;
        if (!png_image_write_to_stdio(&out.png, file, 0, rgb.data(), 0, nullptr))
            writeFailed(path, std::string("libpng: ") + out.png.message);
    });
}

Image readPng(const fs::path& path) {
    PngImage in;
    if (!png_image_begin_read_from_file(&in.png, path.c_str())) readFailed(path, in.png.message);
    if (in.png.width > kMaxPngSide || in.png.height > kMaxPngSide)
        readFailed(path,
                   "implausible size " + std::to_string(in.png.width) + "x" + std::to_string(in.png.height));
    in.png.format = PNG_FORMAT_RGBA;
    Image image(int(in.png.width), int(in.png.height));
    if (!png_image_finish_read(&in.png, nullptr, image.rgba.data(), 0, nullptr))
        readFailed(path, in.png.message);
    return image;
}

Image decodePng(std::string_view bytes, std::string_view what) {
    auto fail = [&](const std::string& reason) { throw RuntimeError(std::string(what) + ": " + reason); };
    static constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
    // IEND: length 0, type, CRC — the last 12 bytes of every complete PNG. libpng's simplified reader
    // stops after the last row, so a file cut off after its pixel data would otherwise pass.
    static constexpr std::string_view kIend("\0\0\0\0IEND\xae\x42\x60\x82", 12);
    if (bytes.size() < kSignature.size() + kIend.size() || !bytes.starts_with(kSignature))
        fail("not a PNG (" + std::to_string(bytes.size()) + " bytes without the PNG signature)");
    if (!bytes.ends_with(kIend)) fail("truncated PNG: it does not end with the IEND chunk");
    PngImage in;
    if (!png_image_begin_read_from_memory(&in.png, bytes.data(), bytes.size())) fail(in.png.message);
    if (in.png.width > kMaxPngSide || in.png.height > kMaxPngSide)
        fail("implausible size " + std::to_string(in.png.width) + "x" + std::to_string(in.png.height));
    in.png.format = PNG_FORMAT_RGBA;
    Image image(int(in.png.width), int(in.png.height));
    if (!png_image_finish_read(&in.png, nullptr, image.rgba.data(), 0, nullptr)) fail(in.png.message);
    return image;
}

} // namespace shadelab
