// PNG files on disk, apart from image.h so that code which only handles images in memory does not parse
// <filesystem> (about 2 s of clang-tidy's time for each file that includes it).
#pragma once

#include <filesystem>

#include "shadelab/image/image.h"

namespace shadelab {

// Writes an opaque RGB PNG (alpha dropped) by the output rules (io/atomic_file.h): a regular file through a
// temporary file beside `path` renamed over it; "-", a device or a FIFO written through.
// Throws RuntimeError naming the path on any failure, leaving nothing behind.
// `inFolder`: as a file of a folder of outputs (OutputRule::InFolder, io/atomic_file.h): created inside its
// folder, replacing only a regular file there, never through a link.
void writePng(const Image& image, const std::filesystem::path& path, bool inFolder = false);
// Reads a PNG's stored samples as 8-bit RGBA (alpha 255 if the file has none): any colour type, 16-bit
// samples scaled to 8 (v/257, rounded), no gamma applied (gAMA, sRGB, iCCP are ignored), so two files that
// hold the same samples read the same. A header claiming more pixels than the file can hold is refused
// before anything is allocated for it. Throws RuntimeError naming the path.
Image readPng(const std::filesystem::path& path);

} // namespace shadelab
