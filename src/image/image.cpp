// 8-bit and float images and the regression comparison. PNG I/O lives in png.cpp (the browser build has
// no libpng: the page encodes its PNGs itself), the font in font.cpp.
#include "shadelab/image/image.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "shadelab/errors.h"

namespace shadelab {

namespace {

std::size_t checkedSize(int w, int h, std::size_t channels) {
    if (w < 0 || h < 0)
        throw InputError("image size " + std::to_string(w) + "x" + std::to_string(h) +
                         ": width and height must be >= 0");
    return std::size_t(w) * std::size_t(h) * channels;
}

struct Span {
    int begin, end;
};

// Clips [start, start + length) to [0, limit), in 64 bits so far-off rectangles cannot overflow.
Span clipSpan(long long start, long long length, int limit) {
    const long long begin = std::clamp(start, 0LL, (long long)limit);
    const long long end = std::clamp(start + length, 0LL, (long long)limit);
    return {int(begin), int(std::max(begin, end))};
}

} // namespace

Image::Image(int w, int h) : width(w), height(h), rgba(checkedSize(w, h, 4), 0) {}

ImageF::ImageF(int w, int h) : width(w), height(h), rgba(checkedSize(w, h, 4), 0.0f) {}

std::uint8_t toUnorm8(double c) {
    if (!(c > 0.0)) return 0; // also NaN
    if (c >= 1.0) return 255;
    return std::uint8_t(std::lround(c * 255.0));
}

Image toImage8(const ImageF& image) {
    Image result(image.width, image.height);
    std::transform(image.rgba.begin(), image.rgba.end(), result.rgba.begin(),
                   [](float c) { return toUnorm8(c); });
    return result;
}

// Non-finite values are counted only as non-finite, so the two counts never overlap.
ValueScan scanValues(const ImageF& image, float lo, float hi) {
    ValueScan scan;
    for (float v : image.rgba) {
        if (!std::isfinite(v))
            ++scan.nonFinite;
        else if (v < lo || v > hi)
            ++scan.outOfRange;
    }
    return scan;
}

std::string Comparison::summary() const {
    std::ostringstream text;
    if (!sizeMatches) {
        text << "FAIL: the image sizes differ: actual " << actualWidth << "x" << actualHeight << ", expected "
             << expectedWidth << "x" << expectedHeight;
        return text.str();
    }
    text << (passed ? "pass" : "FAIL") << ": max delta " << maxDelta << ", mean delta " << std::fixed
         << std::setprecision(4) << meanDelta;
    if (comparedPixels != pixels) text << " over the " << comparedPixels << " compared pixels of " << pixels;
    text << " (limit " << tolerance.meanDelta << "), " << outliers << " pixel(s) over the max-delta limit "
         << tolerance.maxDelta << " (budget " << tolerance.outlierBudget << ")";
    return text.str();
}

Comparison compareImages(const Image& actual, const Image& expected, const Tolerance& tolerance,
                         const Image* mask) {
    Comparison result;
    result.tolerance = tolerance;
    result.actualWidth = actual.width;
    result.actualHeight = actual.height;
    result.expectedWidth = expected.width;
    result.expectedHeight = expected.height;
    if (actual.width != expected.width || actual.height != expected.height) {
        result.sizeMatches = false;
        return result;
    }
    if (mask && (mask->width != actual.width || mask->height != actual.height))
        throw std::invalid_argument("compareImages: the mask's size differs from the images'");
    result.pixels = std::size_t(actual.width) * std::size_t(actual.height);
    std::uint64_t deltaSum = 0;
    for (std::size_t i = 0; i < result.pixels * 4; i += 4) {
        if (mask && mask->rgba[i] == 0 && mask->rgba[i + 1] == 0 && mask->rgba[i + 2] == 0) continue;
        ++result.comparedPixels;
        int pixelMax = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            const int delta = std::abs(int(actual.rgba[i + c]) - int(expected.rgba[i + c]));
            deltaSum += std::uint64_t(delta);
            pixelMax = std::max(pixelMax, delta);
        }
        if (tolerance.compareAlpha)
            pixelMax = std::max(pixelMax, std::abs(int(actual.rgba[i + 3]) - int(expected.rgba[i + 3])));
        result.maxDelta = std::max(result.maxDelta, pixelMax);
        if (pixelMax > tolerance.maxDelta) ++result.outliers;
    }
    result.meanDelta = result.comparedPixels ? double(deltaSum) / (3.0 * double(result.comparedPixels)) : 0.0;
    result.passed = result.outliers <= tolerance.outlierBudget && result.meanDelta <= tolerance.meanDelta;
    return result;
}

// Sizes may differ (that is one way to fail); the diff then covers both, and a pixel only one image has is
// shown as a full difference.
Image diffImage(const Image& actual, const Image& expected, const Image* mask, bool withAlpha) {
    Image diff(std::max(actual.width, expected.width), std::max(actual.height, expected.height));
    if (mask && (mask->width != diff.width || mask->height != diff.height)) mask = nullptr; // sizes differ
    for (int y = 0; y < diff.height; ++y) {
        for (int x = 0; x < diff.width; ++x) {
            std::uint8_t* out = diff.pixel(x, y);
            if (mask) {
                const std::uint8_t* m = mask->pixel(x, y);
                if (m[0] == 0 && m[1] == 0 && m[2] == 0) {
                    std::copy_n(&kDiffLeftOut.x, 4, out);
                    continue;
                }
            }
            const bool inBoth =
                x < actual.width && y < actual.height && x < expected.width && y < expected.height;
            const int alphaDelta =
                inBoth && withAlpha ? std::abs(int(actual.pixel(x, y)[3]) - int(expected.pixel(x, y)[3])) : 0;
            for (int c = 0; c < 3; ++c) {
                const int delta =
                    inBoth ? std::max(std::abs(int(actual.pixel(x, y)[c]) - int(expected.pixel(x, y)[c])),
                                      alphaDelta)
                           : 255;
                // ×8 makes a one-step difference visible without saturating everything else.
                out[c] = std::uint8_t(std::min(delta * 8, 255));
            }
            out[3] = 255;
        }
    }
    return diff;
}

void blit(Image& canvas, const Image& tile, int x, int y) {
    const Span xs = clipSpan(x, tile.width, canvas.width);
    const Span ys = clipSpan(y, tile.height, canvas.height);
    if (xs.begin == xs.end) return;
    for (int row = ys.begin; row < ys.end; ++row)
        std::copy_n(tile.pixel(xs.begin - x, row - y), std::size_t(xs.end - xs.begin) * 4,
                    canvas.pixel(xs.begin, row));
}

void fillRect(Image& canvas, int x, int y, int w, int h, glm::u8vec4 color) {
    const Span xs = clipSpan(x, w, canvas.width);
    const Span ys = clipSpan(y, h, canvas.height);
    for (int row = ys.begin; row < ys.end; ++row)
        for (int col = xs.begin; col < xs.end; ++col) std::copy_n(&color.x, 4, canvas.pixel(col, row));
}

} // namespace shadelab
