// A reader for what `xwd` writes (X11's XWD format, file version 7), limited to what a 24-bit TrueColor
// window gives: ZPixmap at 32 bits per pixel. Anything else is rejected with a message naming the field,
// rather than decoded into a picture that merely looks plausible.
//
// The layout (X11/XWDFile.h): a header of 25 big-endian CARD32 (100 bytes), the window name up to
// header_size, ncolors XWDColor entries of 12 bytes, then height rows of bytes_per_line bytes each, every
// pixel a CARD32 in the header's byte_order whose channels are picked out by red/green/blue_mask.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "shadelab/image.h"

namespace shadelab::window_test {

// The header fields, in file order.
enum XwdField : int {
    kXwdHeaderSize,
    kXwdFileVersion,
    kXwdPixmapFormat,
    kXwdPixmapDepth,
    kXwdPixmapWidth,
    kXwdPixmapHeight,
    kXwdXOffset,
    kXwdByteOrder,
    kXwdBitmapUnit,
    kXwdBitmapBitOrder,
    kXwdBitmapPad,
    kXwdBitsPerPixel,
    kXwdBytesPerLine,
    kXwdVisualClass,
    kXwdRedMask,
    kXwdGreenMask,
    kXwdBlueMask,
    kXwdBitsPerRgb,
    kXwdColormapEntries,
    kXwdNColors,
    kXwdWindowWidth,
    kXwdWindowHeight,
    kXwdWindowX,
    kXwdWindowY,
    kXwdWindowBorderWidth,
    kXwdFieldCount
};
inline constexpr std::size_t kXwdHeaderBytes = kXwdFieldCount * 4;
inline constexpr std::size_t kXwdColorBytes = 12;
inline constexpr std::uint32_t kXwdVersion = 7, kXwdZPixmap = 2, kXwdTrueColor = 4;
inline constexpr std::uint32_t kXwdLsbFirst = 0, kXwdMsbFirst = 1;

// Decodes an XWD file into an opaque RGBA image, rows top to bottom. Throws std::runtime_error naming
// `source` and the offending field for anything but a 24-bit TrueColor ZPixmap at 32 bits per pixel.
Image parseXwd(std::span<const std::uint8_t> bytes, const std::string& source);
Image readXwd(const std::filesystem::path& path);

} // namespace shadelab::window_test
