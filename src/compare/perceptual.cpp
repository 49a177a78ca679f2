// The perceptual delta of pixelmatch 7.2.0 (github.com/mapbox/pixelmatch,
// index.js; ISC licence), written anew in C++ and held to pixelmatch itself
// (tests/compare/perceptual_test.cpp): per pixel, the YIQ colour difference of
// Kotsarenko & Ramos, "Measuring perceived color difference using YIQ NTSC
// transmission color space in mobile applications" (2010), against
// threshold²·35215 (35215 is the largest delta, black against white); a
// differing pixel counts as anti-aliasing, not as a difference, when either
// image shows it as an edge pixel between two flat regions (Vyšniauskas,
// "Anti-aliased pixel and intensity slope detector", 2009).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "shadelab/compare/metrics.h"

namespace shadelab {

namespace {

constexpr double kPixelmatchMaxYiqDelta = 35215;

// A translucent pixel is blended over pixelmatch's checkerboard background: per
// channel 48 or 207, chosen by the pixel's byte offset `k` (its index × 4) as
// pixelmatch chooses it.
struct PixelmatchBackground {
    double r, g, b;
};
PixelmatchBackground pixelmatchBackground(std::size_t k) {
    const auto pick = [](std::size_t n) { return 48.0 + 159.0 * double(n % 2); };
    return {pick(k), pick(std::size_t(double(k) / 1.618033988749895)),
            pick(std::size_t(double(k) / 2.618033988749895))};
}

// The channel differences of two RGBA pixels, blended over the background at
// `k` when either is translucent.
struct PixelmatchRgbDelta {
    double r, g, b;
};
PixelmatchRgbDelta pixelmatchDifference(const std::uint8_t* p1, const std::uint8_t* p2, std::size_t k) {
    PixelmatchRgbDelta d{double(p1[0]) - p2[0], double(p1[1]) - p2[1], double(p1[2]) - p2[2]};
    if (p1[3] < 255 || p2[3] < 255) {
        const double a1 = p1[3], a2 = p2[3], da = a1 - a2;
        const PixelmatchBackground bg = pixelmatchBackground(k);
        d = {(p1[0] * a1 - p2[0] * a2 - bg.r * da) / 255, (p1[1] * a1 - p2[1] * a2 - bg.g * da) / 255,
             (p1[2] * a1 - p2[2] * a2 - bg.b * da) / 255};
    }
    return d;
}

double pixelmatchY(const PixelmatchRgbDelta& d) {
    return d.r * 0.29889531 + d.g * 0.58662247 + d.b * 0.11448223;
}

// The squared YIQ distance, weighted; its sign says whether the first pixel is
// the darker (pixelmatch returns -delta when y > 0).
double pixelmatchColourDelta(const std::uint8_t* p1, const std::uint8_t* p2, std::size_t k) {
    const PixelmatchRgbDelta d = pixelmatchDifference(p1, p2, k);
    const double y = pixelmatchY(d);
    const double i = d.r * 0.59597799 - d.g * 0.27417610 - d.b * 0.32180189;
    const double q = d.r * 0.21147017 - d.g * 0.52261711 + d.b * 0.31114694;
    const double delta = 0.5053 * y * y + 0.299 * i * i + 0.1957 * q * q;
    return y > 0 ? -delta : delta;
}

// The brightness difference between the centre pixel (at byte offset k) and a
// neighbour of one image.
double pixelmatchBrightnessDelta(const std::uint8_t* centre, const std::uint8_t* neighbour, std::size_t k) {
    if (std::memcmp(centre, neighbour, 4) == 0) return 0;
    return pixelmatchY(pixelmatchDifference(centre, neighbour, k));
}

bool pixelmatchSame(const Image& image, int x1, int y1, int x2, int y2) {
    return std::memcmp(image.pixel(x1, y1), image.pixel(x2, y2), 4) == 0;
}

// Whether (x1, y1) has more than two neighbours of exactly its colour (a pixel
// on the image's border counts one such neighbour for free, as pixelmatch
// does).
bool pixelmatchHasManySiblings(const Image& image, int x1, int y1) {
    const int x0 = std::max(x1 - 1, 0), y0 = std::max(y1 - 1, 0);
    const int x2 = std::min(x1 + 1, image.width - 1), y2 = std::min(y1 + 1, image.height - 1);
    int zeroes = (x1 == x0 || x1 == x2 || y1 == y0 || y1 == y2) ? 1 : 0;
    for (int x = x0; x <= x2; ++x)
        for (int y = y0; y <= y2; ++y) {
            if (x == x1 && y == y1) continue;
            zeroes += pixelmatchSame(image, x1, y1, x, y);
            if (zeroes > 2) return true;
        }
    return false;
}

// pixelmatch's antialiased(): (x1, y1) of `image` lies on an anti-aliased edge
// when it has at most two neighbours of its own brightness, and its darkest or
// its brightest neighbour sits in a flat region in both images.
bool pixelmatchAntialiased(const Image& image, const Image& other, int x1, int y1) {
    const int x0 = std::max(x1 - 1, 0), y0 = std::max(y1 - 1, 0);
    const int x2 = std::min(x1 + 1, image.width - 1), y2 = std::min(y1 + 1, image.height - 1);
    const std::size_t k = (std::size_t(y1) * std::size_t(image.width) + std::size_t(x1)) * 4;
    int zeroes = (x1 == x0 || x1 == x2 || y1 == y0 || y1 == y2) ? 1 : 0;
    double lowest = 0, highest = 0;
    int minX = 0, minY = 0, maxX = 0, maxY = 0;
    for (int x = x0; x <= x2; ++x)
        for (int y = y0; y <= y2; ++y) {
            if (x == x1 && y == y1) continue;
            const double delta = pixelmatchBrightnessDelta(image.pixel(x1, y1), image.pixel(x, y), k);
            if (delta == 0) {
                if (++zeroes > 2) return false;
            } else if (delta < lowest) {
                lowest = delta;
                minX = x;
                minY = y;
            } else if (delta > highest) {
                highest = delta;
                maxX = x;
                maxY = y;
            }
        }
    if (lowest == 0 || highest == 0) return false; // no darker or no brighter neighbour: not an edge
    return (pixelmatchHasManySiblings(image, minX, minY) && pixelmatchHasManySiblings(other, minX, minY)) ||
           (pixelmatchHasManySiblings(image, maxX, maxY) && pixelmatchHasManySiblings(other, maxX, maxY));
}

} // namespace

PerceptualResult perceptualDelta(const Image& actual, const Image& expected, const PerceptualOptions& options,
                                 const PixelSelection* selection) {
    if (actual.width != expected.width || actual.height != expected.height)
        throw std::invalid_argument("perceptualDelta: the images differ in size"); // as pixelmatch throws
    PerceptualResult result;
    result.map = MetricMap{actual.width, actual.height, std::vector<float>(actual.rgba.size() / 4, 0.0f)};
    if (actual.rgba == expected.rgba) return result; // pixelmatch's fast path: nothing differs
    const double maxDelta = kPixelmatchMaxYiqDelta * options.threshold * options.threshold;
    for (int y = 0; y < actual.height; ++y)
        for (int x = 0; x < actual.width; ++x) {
            if (selection && !selection->isCounted(x, y)) continue;
            const std::uint8_t *a = actual.pixel(x, y), *b = expected.pixel(x, y);
            if (std::memcmp(a, b, 4) == 0) continue;
            const std::size_t k = (std::size_t(y) * std::size_t(actual.width) + std::size_t(x)) * 4;
            if (std::abs(pixelmatchColourDelta(a, b, k)) <= maxDelta) continue;
            float& mark = result.map.values[k / 4];
            if (pixelmatchAntialiased(actual, expected, x, y) ||
                pixelmatchAntialiased(expected, actual, x, y)) {
                ++result.antialiasedPixels;
                mark = 1;
            } else {
                ++result.differingPixels;
                mark = 2;
            }
        }
    return result;
}

} // namespace shadelab
