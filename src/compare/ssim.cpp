// SSIM (Wang, Bovik, Sheikh & Simoncelli 2004, "Image quality assessment: from error visibility to structural
// similarity"), computed as scikit-image's structural_similarity(gaussian_weights=True, sigma=1.5,
// use_sample_covariance=False, data_range=255) does (skimage/metrics/_structural_similarity.py, 0.19):
// local means, variances and covariance by one Gaussian window, then
//   S = (2 μx μy + C₁)(2 σxy + C₂) / ((μx² + μy² + C₁)(σx² + σy² + C₂)),  C₁ = (K₁·255)², C₂ = (K₂·255)².
// tests/compare/ssim_test.cpp holds it to scikit-image itself on a set of pairs.
#include <cmath>
#include <cstddef>
#include <vector>

#include "shadelab/compare/metrics.h"

namespace shadelab {

namespace {

constexpr double kSsimSigma = 1.5;
constexpr double kSsimTruncate = 3.5; // scipy.ndimage.gaussian_filter's default: radius int(3.5σ + 0.5) = 5
constexpr int kSsimRadius = 5;        // int(kSsimTruncate * kSsimSigma + 0.5), as scipy rounds the radius
constexpr double kSsimK1 = 0.01, kSsimK2 = 0.03, kSsimRange = 255;

// A grey plane in double, rows top to bottom.
struct SsimPlane {
    int width = 0, height = 0;
    std::vector<double> v;
    double& at(int x, int y) { return v[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    double at(int x, int y) const { return v[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// ITU-R BT.601 luma of the stored 8-bit colour, 0..255 (the Y of YIQ, which pixelmatch also uses).
SsimPlane ssimLuma(const Image& image) {
    SsimPlane luma{image.width, image.height, std::vector<double>(std::size_t(image.width) * image.height)};
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            luma.at(x, y) = 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
        }
    return luma;
}

// The normalized 11-tap Gaussian, as scipy's _gaussian_kernel1d.
std::vector<double> ssimGaussianTaps() {
    std::vector<double> taps(2 * kSsimRadius + 1);
    double sum = 0;
    for (int i = -kSsimRadius; i <= kSsimRadius; ++i)
        sum += taps[std::size_t(i) + kSsimRadius] = std::exp(-0.5 * i * i / (kSsimSigma * kSsimSigma));
    for (double& t : taps) t /= sum;
    return taps;
}

// scipy's mode 'reflect' (half-sample symmetric: d c b a | a b c d | d c b a), for any overshoot.
int ssimReflect(int i, int n) {
    const int period = 2 * n;
    i %= period;
    if (i < 0) i += period;
    return i < n ? i : period - 1 - i;
}

// The Gaussian window applied as two 1-D passes (it separates): down the columns, then along the rows.
SsimPlane ssimBlur(const SsimPlane& in, const std::vector<double>& taps) {
    SsimPlane columns = in, out = in;
    for (int y = 0; y < in.height; ++y)
        for (int x = 0; x < in.width; ++x) {
            double sum = 0;
            for (std::size_t t = 0; t < taps.size(); ++t)
                sum += taps[t] * in.at(x, ssimReflect(y + int(t) - kSsimRadius, in.height));
            columns.at(x, y) = sum;
        }
    for (int y = 0; y < in.height; ++y)
        for (int x = 0; x < in.width; ++x) {
            double sum = 0;
            for (std::size_t t = 0; t < taps.size(); ++t)
                sum += taps[t] * columns.at(ssimReflect(x + int(t) - kSsimRadius, in.width), y);
            out.at(x, y) = sum;
        }
    return out;
}

SsimPlane ssimProduct(const SsimPlane& a, const SsimPlane& b) {
    SsimPlane p = a;
    for (std::size_t i = 0; i < p.v.size(); ++i) p.v[i] = a.v[i] * b.v[i];
    return p;
}

} // namespace

SsimResult ssim(const Image& actual, const Image& expected, const PixelSelection* selection) {
    const std::vector<double> taps = ssimGaussianTaps();
    const SsimPlane x = ssimLuma(actual), y = ssimLuma(expected);
    const SsimPlane muX = ssimBlur(x, taps), muY = ssimBlur(y, taps);
    const SsimPlane xx = ssimBlur(ssimProduct(x, x), taps), yy = ssimBlur(ssimProduct(y, y), taps),
                    xy = ssimBlur(ssimProduct(x, y), taps);
    constexpr double c1 = (kSsimK1 * kSsimRange) * (kSsimK1 * kSsimRange);
    constexpr double c2 = (kSsimK2 * kSsimRange) * (kSsimK2 * kSsimRange);

    SsimResult result;
    result.map = MetricMap{x.width, x.height, std::vector<float>(x.v.size())};
    // The mean leaves out a margin of the window's radius, where the window reaches past the border (as
    // scikit-image crops it); an image too small to have such an interior is averaged whole.
    const bool hasInterior = x.width > 2 * kSsimRadius && x.height > 2 * kSsimRadius;
    const int margin = hasInterior ? kSsimRadius : 0;
    double sum = 0;
    std::size_t counted = 0;
    for (int py = 0; py < x.height; ++py)
        for (int px = 0; px < x.width; ++px) {
            const double mx = muX.at(px, py), my = muY.at(px, py);
            // Population variances and covariance (use_sample_covariance=False).
            const double vx = xx.at(px, py) - mx * mx, vy = yy.at(px, py) - my * my;
            const double vxy = xy.at(px, py) - mx * my;
            const double s =
                ((2 * mx * my + c1) * (2 * vxy + c2)) / ((mx * mx + my * my + c1) * (vx + vy + c2));
            result.map.values[std::size_t(py) * std::size_t(x.width) + std::size_t(px)] = float(s);
            const bool inside =
                px >= margin && py >= margin && px < x.width - margin && py < x.height - margin;
            if (inside && (!selection || selection->isCounted(px, py))) {
                sum += s;
                ++counted;
            }
        }
    result.meanPixels = counted;
    result.mean = counted ? sum / double(counted) : 1.0;
    return result;
}

} // namespace shadelab
