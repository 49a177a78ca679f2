#include "app/check/compare_command.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/check/figures_json.h"
#include "app/check/memory_check.h"
#include "shadelab/errors.h"
#include "shadelab/image/image_file.h"
#include "shadelab/io/atomic_file.h"
#include "shadelab/io/text.h"

namespace shadelab::app {
namespace {

// The size a PNG's header claims, read before any pixel is; nullopt for a file that does not start as a
// PNG (its decoder then says why).
std::optional<PngSize> compareClaimedSize(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(33, '\0');
    in.read(head.data(), std::streamsize(head.size()));
    head.resize(std::size_t(in.gcount()));
    return pngSize(head);
}

// What comparing the files will take, from their headers and sizes, against the memory budget: each image
// decoded (4 bytes a pixel) and the files themselves, the process without GL (measured: 29 MB peak for two
// 64x64 images), and per pixel of the larger size `bytesPerPixel`. Checked twice: before decoding, with the
// difference image and its rows for the encoder (7), so that the decoder's own refusal of a forged header
// comes first; and before judging, adding the selection and its mask (5), SSIM's luma, five filtered
// moments and map (4 bytes each: 32), the perceptual map (4). The per-pixel figures are counted from the
// code, not measured.
void checkCompareMemory(const CompareOptions& o, double bytesPerPixel) {
    double need = kProcessBaselineBytes, largest = 0;
    std::string sizes;
    for (const std::string* path : {&o.actual, &o.expected, &o.mask}) {
        if (path->empty()) continue;
        std::error_code error;
        const auto bytes = std::filesystem::file_size(*path, error);
        if (!error) need += double(bytes);
        if (const std::optional<PngSize> size = compareClaimedSize(*path)) {
            const double pixels = double(size->width) * double(size->height);
            need += 4 * pixels;
            largest = std::max(largest, pixels);
            sizes += (sizes.empty() ? "" : ", ") + std::to_string(size->width) + "x" +
                     std::to_string(size->height);
        }
    }
    need += bytesPerPixel * largest;
    checkMemoryBudget("comparing " + (sizes.empty() ? std::string("the images") : sizes), need,
                      "ACTUAL and EXPECTED (smaller images)");
}
constexpr double kDecodeBytesPerPixel = 7;
double judgeBytesPerPixel() {
    return kDecodeBytesPerPixel + 5 + 32 + 4;
}

nlohmann::json optionalJson(const auto& value) {
    return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

// `compare --json`: every figure and every limit, as one object for a CI dashboard. The paths are the
// arguments as given (JSON strings escape whatever bytes they hold).
std::string judgementJson(const Judgement& j, const CompareOptions& o, bool wroteDiff, bool wroteHeatmap) {
    const Comparison& c = j.comparison;
    const CheckLimits& l = o.limits;
    const auto size = [](int width, int height) {
        return nlohmann::json{{"width", width}, {"height", height}};
    };
    const auto pathOrNull = [](const std::string& path, bool written = true) {
        return path.empty() || !written ? nlohmann::json(nullptr) : nlohmann::json(path);
    };
    nlohmann::json ignore = nlohmann::json::array();
    for (const IgnoreRect& r : l.ignore)
        ignore.push_back({{"x", r.x}, {"y", r.y}, {"width", r.width}, {"height", r.height}});
    nlohmann::json out{
        {"actual", o.actual},
        {"expected", o.expected},
        {"mask", pathOrNull(o.mask)},
        {"ignore", ignore},
        {"alpha_compared", !l.ignoreAlpha},
        {"actual_size", size(c.actualWidth, c.actualHeight)},
        {"expected_size", size(c.expectedWidth, c.expectedHeight)},
        {"size_matches", c.sizeMatches},
        {"limits",
         {{"max", l.tolerance.maxDelta},
          {"mean", l.tolerance.meanDelta},
          {"outliers", l.tolerance.outlierBudget},
          {"ssim_min", optionalJson(l.ssimMin)},
          {"perceptual_max_pixels", optionalJson(l.perceptualMaxPixels)},
          {"perceptual_threshold", l.perceptualThreshold}}},
        {"passed", j.passed},
        {"failures", j.failures},
        {"diff", pathOrNull(o.diff, wroteDiff)},
        {"heatmap", pathOrNull(o.heatmap, wroteHeatmap)},
    };
    addFiguresJson(out, j, l);
    // Bytes that are not UTF-8 in a path are replaced rather than refused: the result must still print.
    return out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

// The summary: compareImages' line, then a line per figure beyond it and one per failed limit.
std::string judgementSummary(const Judgement& j) {
    std::string text = j.comparison.summary();
    if (j.comparison.sizeMatches) {
        if (!j.passed && text.starts_with("pass")) text.replace(0, 4, "FAIL");
        char line[160];
        if (j.ssim) text += (std::snprintf(line, sizeof line, "\nSSIM %.4f", j.ssim->mean), line);
        if (j.perceptual)
            text +=
                (std::snprintf(line, sizeof line, ", %ld perceptually differing pixel(s), %ld anti-aliased",
                               j.perceptual->differingPixels, j.perceptual->antialiasedPixels),
                 line);
        for (const std::string& failure : j.failures) text += "\nfailed: " + failure;
    }
    return text;
}

// An output of compare's, checked before anything is read: a file (standard output carries the summary),
// none of the inputs (by inode: a link or a hard link to one is one).
void checkCompareOutput(const std::string& path, const char* flag, const CompareOptions& o) {
    if (path.empty()) return;
    if (path == "-")
        throw InputError(std::string(flag) +
                         " -: standard output carries the summary; give the image a file name");
    (void)resolveOutput(path, flag);
    for (const std::string* input : {&o.actual, &o.expected, &o.mask})
        refuseOverwritingInput(path, flag, *input);
    refuseStandardOutputAlias(path, flag, o.json ? "the JSON of --json" : "the summary");
}

Image readCompareInput(const std::string& path, const char* what) {
    if (std::error_code error; !std::filesystem::is_regular_file(path, error))
        throw InputError(std::string(what) + ": " + printable(path) + " is not a readable file");
    try {
        return readPng(path);
    } catch (const RuntimeError& e) {
        throw InputError(std::string(what) + ": " + e.what());
    }
}

} // namespace

int runCompare(const CompareOptions& o) {
    checkCompareOutput(o.diff, "--diff", o);
    checkCompareOutput(o.heatmap, "--heatmap", o);
    if (!o.diff.empty() && o.diff == o.heatmap)
        throw InputError("--diff and --heatmap: both name " + printable(o.diff) + "; give each its own file");
    checkCompareMemory(o, kDecodeBytesPerPixel);
    const Image actual = readCompareInput(o.actual, "ACTUAL");
    const Image expected = readCompareInput(o.expected, "EXPECTED");
    std::optional<Image> mask;
    if (!o.mask.empty()) mask = readCompareInput(o.mask, "--mask");
    checkCompareMemory(o, judgeBytesPerPixel());
    const Judgement j = judgeImages(actual, expected, o.limits, mask ? &*mask : nullptr);

    const bool writeDiff = !j.passed && !o.diff.empty();
    if (writeDiff) {
        const std::optional<PixelSelection> selection =
            makeSelection(actual.width, actual.height, mask ? &*mask : nullptr, o.limits.ignore);
        std::optional<Image> leftOut; // the selection as diffImage's mask: black where not compared
        if (selection) {
            leftOut.emplace(selection->width, selection->height);
            for (std::size_t i = 0; i < selection->counted.size(); ++i)
                if (selection->counted[i]) std::fill_n(&leftOut->rgba[i * 4], 4, std::uint8_t(255));
        }
        writePng(diffImage(actual, expected, leftOut ? &*leftOut : nullptr, !o.limits.ignoreAlpha), o.diff);
    }
    const bool writeHeatmap = !j.passed && !o.heatmap.empty() && j.ssim;
    if (writeHeatmap) {
        MetricMap dissimilarity = j.ssim->map; // 1 − SSIM: 0 the same, 1 and over unrelated
        for (float& v : dissimilarity.values) v = 1.0f - v;
        const std::optional<PixelSelection> selection =
            makeSelection(actual.width, actual.height, mask ? &*mask : nullptr, o.limits.ignore);
        writePng(heatmap(dissimilarity, 0.0f, 1.0f, "1 - SSIM", selection ? &*selection : nullptr),
                 o.heatmap);
    }
    if (o.json) {
        std::printf("%s\n", judgementJson(j, o, writeDiff, writeHeatmap).c_str());
    } else {
        std::printf("%s\n", judgementSummary(j).c_str());
        if (writeDiff)
            std::printf("difference ×8 written to %s (pixels not compared: dark grey)\n",
                        printable(o.diff).c_str());
        if (writeHeatmap) std::printf("heatmap of 1 - SSIM written to %s\n", printable(o.heatmap).c_str());
        if (!j.passed && !o.heatmap.empty() && !j.ssim) std::printf("no heatmap: the sizes differ\n");
    }
    return j.passed ? kExitOk : kExitRuntimeError; // as cmp and diff: 1 is "they differ"
}

void addFiguresJson(nlohmann::json& out, const Judgement& judgement, const CheckLimits& limits) {
    const Comparison& c = judgement.comparison;
    if (c.sizeMatches) {
        out["max_delta"] = c.maxDelta;
        out["mean_delta"] = c.meanDelta;
        out["outliers"] = c.outliers;
        out["compared_pixels"] = c.comparedPixels;
        out["pixels"] = c.pixels;
    }
    if (judgement.ssim) out["ssim"] = judgement.ssim->mean;
    if (judgement.perceptual)
        out["perceptual"] = {{"differing_pixels", judgement.perceptual->differingPixels},
                             {"antialiased_pixels", judgement.perceptual->antialiasedPixels},
                             {"threshold", limits.perceptualThreshold}};
}

} // namespace shadelab::app
