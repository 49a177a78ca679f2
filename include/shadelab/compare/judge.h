// One comparison of an actual image with an expected one against a set of limits: every figure the limits
// can be set on, and which limits failed. `shadelab compare`, `shadelab review` and the light
// `shadelab-compare` all judge through this.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "shadelab/compare/metrics.h"
#include "shadelab/image/image.h"

namespace shadelab {

struct IgnoreRect { // --ignore x,y,w,h: pixels left out, in the actual image's pixel coordinates
    int x = 0, y = 0, width = 0, height = 0;
};

// Every limit a comparison can be held to. The per-channel ones always apply; an unset optional is no limit.
struct CheckLimits {
    Tolerance tolerance;                     // --max, --mean, --outliers
    bool ignoreAlpha = false;                // --ignore-alpha: alpha is not a compared channel
    std::optional<double> ssimMin;           // --ssim-min
    std::optional<long> perceptualMaxPixels; // --perceptual-max-pixels
    double perceptualThreshold = 0.1;        // --perceptual-threshold (pixelmatch's threshold)
    std::vector<IgnoreRect> ignore;          // --ignore, repeatable
};

struct Judgement {
    Comparison comparison;                      // max / mean / outliers, alpha included unless ignoreAlpha
    std::optional<SsimResult> ssim;             // computed whenever the sizes match
    std::optional<PerceptualResult> perceptual; // computed whenever the sizes match
    std::vector<std::string> failures;          // one line per failed limit, with the figure and the limit
    bool passed = false;
};

// The selection `mask` (same size as actual, black = left out) and `rects` make, or nullopt if neither
// leaves a pixel out. Throws InputError naming --mask or --ignore for a size or a rectangle that does not
// fit.
std::optional<PixelSelection> makeSelection(int width, int height, const Image* mask,
                                            const std::vector<IgnoreRect>& rects);
Judgement judgeImages(const Image& actual, const Image& expected, const CheckLimits& limits,
                      const Image* mask = nullptr);

} // namespace shadelab
