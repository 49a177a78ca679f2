// One comparison against every limit (compare/judge.h): the per-channel figures always, SSIM and the
// perceptual delta whenever the sizes match; a line for each failed limit.
#include "shadelab/compare/judge.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "shadelab/errors.h"

namespace shadelab {
namespace {

std::string judgeNumber(double value, int decimals = 4) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

std::string judgeSize(int width, int height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

// The limits' own values, checked whoever filled them (the command line refuses them earlier, with the
// same words): a NaN limit would pass everything.
void checkLimitValues(const CheckLimits& limits) {
    const Tolerance& t = limits.tolerance;
    const auto refuse = [](const std::string& flag, const std::string& value, const std::string& fix) {
        throw InputError(flag + ": got " + value + "; " + fix);
    };
    if (t.maxDelta < 0 || t.maxDelta > 255) refuse("--max", std::to_string(t.maxDelta), "give 0..255");
    if (!(t.meanDelta >= 0) || !std::isfinite(t.meanDelta))
        refuse("--mean", judgeNumber(t.meanDelta), "give a number >= 0");
    if (t.outlierBudget < 0) refuse("--outliers", std::to_string(t.outlierBudget), "give a count >= 0");
    if (limits.ssimMin && !(*limits.ssimMin >= -1 && *limits.ssimMin <= 1))
        refuse("--ssim-min", judgeNumber(*limits.ssimMin), "give a number from -1 to 1 (1: identical)");
    if (limits.perceptualMaxPixels && *limits.perceptualMaxPixels < 0)
        refuse("--perceptual-max-pixels", std::to_string(*limits.perceptualMaxPixels), "give a count >= 0");
    if (!(limits.perceptualThreshold >= 0 && limits.perceptualThreshold <= 1))
        refuse("--perceptual-threshold", judgeNumber(limits.perceptualThreshold),
               "give a number from 0 to 1 (pixelmatch's default 0.1)");
}

// The selection as compareImages takes it: a mask, black where a pixel is left out.
Image judgeMaskImage(const PixelSelection& selection) {
    Image mask(selection.width, selection.height);
    for (int y = 0; y < selection.height; ++y)
        for (int x = 0; x < selection.width; ++x)
            if (selection.isCounted(x, y)) {
                std::uint8_t* p = mask.pixel(x, y);
                p[0] = p[1] = p[2] = p[3] = 255;
            }
    return mask;
}

// A copy with every pixel opaque: what the perceptual delta sees under --ignore-alpha (it blends each
// pixel over white by its alpha).
Image judgeOpaque(const Image& image) {
    Image opaque = image;
    for (std::size_t i = 3; i < opaque.rgba.size(); i += 4) opaque.rgba[i] = 255;
    return opaque;
}

void judgeFailures(Judgement& j, const CheckLimits& limits) {
    const Comparison& c = j.comparison;
    if (!c.sizeMatches) {
        j.failures.push_back("the image sizes differ: actual " + judgeSize(c.actualWidth, c.actualHeight) +
                             ", expected " + judgeSize(c.expectedWidth, c.expectedHeight));
        return;
    }
    const Tolerance& t = limits.tolerance;
    if (c.outliers > t.outlierBudget)
        j.failures.push_back(std::to_string(c.outliers) + " pixel(s) over --max " +
                             std::to_string(t.maxDelta) + " (largest difference " +
                             std::to_string(c.maxDelta) + "), more than --outliers " +
                             std::to_string(t.outlierBudget));
    if (c.meanDelta > t.meanDelta)
        j.failures.push_back("mean delta " + judgeNumber(c.meanDelta) + " over --mean " +
                             judgeNumber(t.meanDelta));
    if (limits.ssimMin && j.ssim && j.ssim->mean < *limits.ssimMin)
        j.failures.push_back("SSIM " + judgeNumber(j.ssim->mean) + " under --ssim-min " +
                             judgeNumber(*limits.ssimMin));
    if (limits.perceptualMaxPixels && j.perceptual &&
        j.perceptual->differingPixels > *limits.perceptualMaxPixels)
        j.failures.push_back(std::to_string(j.perceptual->differingPixels) +
                             " perceptually differing pixel(s) (threshold " +
                             judgeNumber(limits.perceptualThreshold, 3) + ") over --perceptual-max-pixels " +
                             std::to_string(*limits.perceptualMaxPixels));
}

} // namespace

std::optional<PixelSelection> makeSelection(int width, int height, const Image* mask,
                                            const std::vector<IgnoreRect>& rects) {
    if (mask && (mask->width != width || mask->height != height))
        throw InputError("--mask: " + judgeSize(mask->width, mask->height) + ", but ACTUAL is " +
                         judgeSize(width, height) + "; give a mask of ACTUAL's size");
    for (const IgnoreRect& r : rects) {
        const std::string given = std::to_string(r.x) + "," + std::to_string(r.y) + "," +
                                  std::to_string(r.width) + "," + std::to_string(r.height);
        if (r.width <= 0 || r.height <= 0)
            throw InputError("--ignore: got " + given +
                             "; the width and height (x,y,w,h) must be at least 1");
        // In 64 bits: x + w must not wrap.
        if (r.x < 0 || r.y < 0 || (long long)r.x + r.width > width || (long long)r.y + r.height > height)
            throw InputError("--ignore: got " + given + ", which does not lie within ACTUAL (" +
                             judgeSize(width, height) + "); give x,y,w,h with x + w <= " +
                             std::to_string(width) + " and y + h <= " + std::to_string(height));
    }
    PixelSelection selection{width, height,
                             std::vector<std::uint8_t>(std::size_t(width) * std::size_t(height), 1)};
    bool leftOut = false;
    if (mask)
        for (std::size_t i = 0; i < selection.counted.size(); ++i) {
            const std::uint8_t* m = &mask->rgba[i * 4];
            if (m[0] == 0 && m[1] == 0 && m[2] == 0) {
                selection.counted[i] = 0;
                leftOut = true;
            }
        }
    for (const IgnoreRect& r : rects) {
        for (int y = r.y; y < r.y + r.height; ++y)
            for (int x = r.x; x < r.x + r.width; ++x)
                selection.counted[std::size_t(y) * std::size_t(width) + std::size_t(x)] = 0;
        leftOut = true;
    }
    if (!leftOut) return std::nullopt;
    return selection;
}

Judgement judgeImages(const Image& actual, const Image& expected, const CheckLimits& limits,
                      const Image* mask) {
    checkLimitValues(limits);
    const std::optional<PixelSelection> selection =
        makeSelection(actual.width, actual.height, mask, limits.ignore);
    Tolerance tolerance = limits.tolerance;
    tolerance.compareAlpha = !limits.ignoreAlpha;
    Judgement j;
    const bool sameSize = actual.width == expected.width && actual.height == expected.height;
    const std::optional<Image> maskImage =
        sameSize && selection ? std::optional<Image>(judgeMaskImage(*selection)) : std::nullopt;
    j.comparison = compareImages(actual, expected, tolerance, maskImage ? &*maskImage : nullptr);
    if (sameSize) {
        const PixelSelection* counted = selection ? &*selection : nullptr;
        j.ssim = ssim(actual, expected, counted);
        const PerceptualOptions perceptual{limits.perceptualThreshold};
        j.perceptual = limits.ignoreAlpha
                           ? perceptualDelta(judgeOpaque(actual), judgeOpaque(expected), perceptual, counted)
                           : perceptualDelta(actual, expected, perceptual, counted);
    }
    judgeFailures(j, limits);
    j.passed = j.failures.empty();
    return j;
}

} // namespace shadelab
