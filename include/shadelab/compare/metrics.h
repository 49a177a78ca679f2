// Image metrics for screenshot regression beyond per-channel max and mean (docs/ci-engineers.md "Which
// metric"): SSIM and pixelmatch's perceptual YIQ delta with anti-aliasing detection; and the
// colour-blind-safe heatmap a per-pixel map is drawn as. No GL: the light `shadelab-compare` links these.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "shadelab/image/image.h"

namespace shadelab {

// One value per pixel, rows top to bottom (an SSIM map, a perceptual map, a difference).
struct MetricMap {
    int width = 0, height = 0;
    std::vector<float> values;

    float at(int x, int y) const { return values[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// Which pixels count: a mask (black = left out) and rectangles, both optional; `nullptr` counts every pixel.
// Built once per comparison by judgeImages (compare/judge.h) and handed to each metric.
struct PixelSelection {
    int width = 0, height = 0;
    std::vector<std::uint8_t> counted; // 1 counted, 0 left out; width·height entries

    bool isCounted(int x, int y) const {
        return counted[std::size_t(y) * std::size_t(width) + std::size_t(x)] != 0;
    }
};

// ---- SSIM (Wang, Bovik, Sheikh, Simoncelli 2004) ----
// On luma Y = 0.299 R + 0.587 G + 0.114 B of the stored 8-bit colour (alpha not used), data range 255,
// an 11×11 Gaussian window with σ = 1.5 (truncated at 3.5σ, normalized), K₁ = 0.01, K₂ = 0.03, population
// (not sample) covariances, borders reflected half-sample symmetric — what scikit-image's
// structural_similarity(gaussian_weights=True, sigma=1.5, use_sample_covariance=False, data_range=255)
// computes. `mean` is the map's mean over the pixels at least 5 px from every border (scikit-image crops the
// same margin), and of those only the counted ones. An image under 11 px on a side has no such interior and
// is averaged whole (scikit-image refuses it); with no pixel counted the mean is 1 (nothing differs).
struct SsimResult {
    double mean = 1;
    std::size_t meanPixels = 0; // the pixels the mean is over
    MetricMap map;              // the full-size SSIM map, -1..1
};
SsimResult ssim(const Image& actual, const Image& expected, const PixelSelection* selection = nullptr);

// ---- the perceptual delta of pixelmatch 7.2.0 (mapbox/pixelmatch; tests/compare/independent/) ----
// Per pixel, the YIQ colour difference (Kotsarenko & Ramos 2010) of the two pixels, each blended by its alpha
// over pixelmatch's checkerboard when either is translucent, against threshold² · 35215; a differing pixel
// that either image shows as anti-aliasing (pixelmatch's antialiased() test on both images) is counted as
// AA, not as differing. Pixels the selection leaves out count as the same.
struct PerceptualOptions {
    double threshold = 0.1; // pixelmatch's `threshold`, 0..1: smaller is stricter
};
struct PerceptualResult {
    long differingPixels = 0; // what pixelmatch returns (includeAA false)
    long antialiasedPixels = 0;
    MetricMap map; // 0 same (or not counted), 1 anti-aliased, 2 differing
};
PerceptualResult perceptualDelta(const Image& actual, const Image& expected, const PerceptualOptions& options,
                                 const PixelSelection* selection = nullptr);

// ---- the heatmap ----
// `map` drawn with a colour-blind-safe sequential colour map (viridis: lightness rises monotonically, and it
// reads the same under the common colour-vision deficiencies) from `low` to `high`, with a scale bar under
// the picture labelled with `label` and the two ends' values. Pixels left out by `selection` are grey.
Image heatmap(const MetricMap& map, float low, float high, std::string_view label,
              const PixelSelection* selection = nullptr);
// The colour map's colour at t in [0, 1] (clamped; NaN → 0).
glm::u8vec4 heatmapColour(double t);

} // namespace shadelab
