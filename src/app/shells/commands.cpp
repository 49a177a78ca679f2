#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/measure/memory_budget.h"
#include "app/report/showcase.h"
#include "app/shells/commands.h"
#include "shadelab/context/headless.h"
#include "shadelab/errors.h"
#include "shadelab/exact/reference.h"
#include "shadelab/gl/program.h"
#include "shadelab/image/image_file.h"
#include "shadelab/io/atomic_file.h"
#include "shadelab/io/text.h"
#include "shadelab/vocabulary.h"

namespace shadelab::app {
namespace {

// A value from the command line quoted back: control bytes escaped, so no name can forge a line.
std::string quoted(const std::string& s) {
    return "\"" + printable(s) + "\"";
}

} // namespace

void checkOutputPath(const std::filesystem::path& out, const char* argument) {
    (void)resolveOutput(out, argument); // throws InputError for what cannot be an output
}

Api apiFromArgument(const std::string& name) {
    return parseNameOrThrow(name, "--api", kApis);
}

ContextRequest contextFromArguments(const std::string& backend, const std::string& api,
                                    const std::string& eglDevice) {
    ContextRequest request;
    request.backend = parseNameOrThrow(backend, "--backend", kBackends);
    request.api = apiFromArgument(api);
    if (!eglDevice.empty()) {
        const bool digits =
            eglDevice.size() <= 4 && eglDevice.find_first_not_of("0123456789") == std::string::npos;
        if (!digits)
            throw InputError("--egl-device: " + quoted(eglDevice) +
                             " is neither a device number (0, 1, …) nor list; see --egl-device list");
        request.eglDevice = std::stoi(eglDevice);
    }
    checkContextRequest(request); // before any work, not when the context is made
    return request;
}

int runListEglDevices(Api api) {
    for (const std::string& line : describeEglDevices(api)) std::printf("%s\n", line.c_str());
    return kExitOk;
}

namespace {} // namespace

int runRender(const Scene& scene, const ContextRequest& context, const std::filesystem::path& out,
              bool specialize, bool verbose) {
    checkMemoryBudget("a render of " + sizeText(scene), kGlBaselineBytes + renderBytes(scene),
                      "--size (or the scene's image)");
    HeadlessRenderer renderer(context);
    if (verbose)
        std::fprintf(stderr, "shadelab: %s, %s context: %s\n", renderer.origin().c_str(),
                     std::string(displayName(renderer.api())).c_str(), renderer.rendererString().c_str());
    renderer.setSpecialization(specialize ? gl::Specialization::Values : gl::Specialization::None);
    writePng(renderer.render(scene), out);
    return kExitOk;
}

int runReference(const Scene& scene, const std::filesystem::path& out) {
    checkMemoryBudget("the reference of " + sizeText(scene), referenceBytes(scene),
                      "--size (or the scene's image)");
    writePng(toImage8(renderReference(scene).color), out);
    return kExitOk;
}

int runShowcase(const Scene& scene, const ContextRequest& context, const std::filesystem::path& out) {
    // One tile rendered at a time (kShowcaseTile square, whatever the scene's size), blitted into the
    // canvas of every shading mode × lighting model, each tile's picture and error view.
    const Scene tile = atSize(scene, kShowcaseTile, kShowcaseTile);
    const double canvasBytes = 4.0 * int(kShadingModes.size()) * kShowcaseTile * int(kLightingModels.size()) *
                               (2 * kShowcaseTile + 2 * kShowcaseStripHeight);
    checkMemoryBudget("the showcase of " + sizeText(tile) + " tiles",
                      kGlBaselineBytes + renderBytes(tile) + canvasBytes, "--size (or the scene's image)");
    HeadlessRenderer renderer(context);
    writePng(renderShowcase(renderer, scene, kShowcaseTile), out);
    if (out != "-") std::printf("%s\n", out.string().c_str());
    return kExitOk;
}

namespace {

// The size a PNG's header claims, read before any pixel is; nullopt for a file that does not start as a
// PNG (its decoder then says why).
std::optional<PngSize> claimedSize(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(33, '\0');
    in.read(head.data(), std::streamsize(head.size()));
    head.resize(std::size_t(in.gcount()));
    return pngSize(head);
}

// What comparing the files will take, from their headers and sizes, against the memory budget: each image
// decoded (4 bytes a pixel), the difference image of the larger size and its rows for the encoder (7), the
// files themselves, and the process without GL (measured: 29 MB peak for two 64x64 images).
void checkCompareMemory(const CompareOptions& o) {
    double need = kProcessBaselineBytes, largest = 0;
    std::string sizes;
    for (const std::string* path : {&o.actual, &o.expected, &o.mask}) {
        if (path->empty()) continue;
        std::error_code error;
        const auto bytes = std::filesystem::file_size(*path, error);
        if (!error) need += double(bytes);
        if (const std::optional<PngSize> size = claimedSize(*path)) {
            const double pixels = double(size->width) * double(size->height);
            need += 4 * pixels;
            largest = std::max(largest, pixels);
            sizes += (sizes.empty() ? "" : ", ") + std::to_string(size->width) + "x" +
                     std::to_string(size->height);
        }
    }
    need += 7 * largest;
    checkMemoryBudget("comparing " + (sizes.empty() ? std::string("the images") : sizes), need,
                      "ACTUAL and EXPECTED (smaller images)");
}

// `compare --json`: what the summary line says, as one object for a CI dashboard. The paths are the
// arguments as given (JSON strings escape whatever bytes they hold).
std::string comparisonJson(const Comparison& c, const CompareOptions& o, bool wroteDiff) {
    const auto size = [](int width, int height) {
        return nlohmann::json{{"width", width}, {"height", height}};
    };
    const auto pathOrNull = [](const std::string& path) {
        return path.empty() ? nlohmann::json(nullptr) : nlohmann::json(path);
    };
    nlohmann::json out{
        {"actual", o.actual},
        {"expected", o.expected},
        {"mask", pathOrNull(o.mask)},
        {"actual_size", size(c.actualWidth, c.actualHeight)},
        {"expected_size", size(c.expectedWidth, c.expectedHeight)},
        {"size_matches", c.sizeMatches},
        {"limits", {{"max", o.maxDelta}, {"mean", o.meanDelta}, {"outliers", o.outliers}}},
        {"passed", c.passed},
        {"diff", wroteDiff ? nlohmann::json(o.diff) : nlohmann::json(nullptr)},
    };
    if (c.sizeMatches) {
        out["max_delta"] = c.maxDelta;
        out["mean_delta"] = c.meanDelta;
        out["outliers"] = c.outliers;
        out["compared_pixels"] = c.comparedPixels;
        out["pixels"] = c.pixels;
    }
    // Bytes that are not UTF-8 in a path are replaced rather than refused: the result must still print.
    return out.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

} // namespace

int runCompare(const CompareOptions& o) {
    auto read = [](const std::string& path, const char* what) {
        if (std::error_code error; !std::filesystem::is_regular_file(path, error))
            throw InputError(std::string(what) + ": " + printable(path) + " is not a readable file");
        try {
            return readPng(path);
        } catch (const RuntimeError& e) {
            throw InputError(std::string(what) + ": " + e.what());
        }
    };
    if (o.maxDelta < 0 || o.maxDelta > 255 || !(o.meanDelta >= 0) || o.outliers < 0)
        throw InputError("--max 0..255, --mean >= 0 and --outliers >= 0, got " + std::to_string(o.maxDelta) +
                         ", " + std::to_string(o.meanDelta) + ", " + std::to_string(o.outliers));
    // The difference image is an output like any other, checked before anything is read; it may be none of
    // the inputs (by inode: a link or a hard link to one is one), and standard output carries the summary.
    if (!o.diff.empty()) {
        if (o.diff == "-")
            throw InputError(
                "--diff -: standard output carries the summary; give the difference image a file "
                "name");
        refuseOverwritingInput(o.diff, "--diff", o.actual);
        refuseOverwritingInput(o.diff, "--diff", o.expected);
        refuseOverwritingInput(o.diff, "--diff", o.mask);
        refuseStandardOutputAlias(o.diff, "--diff", o.json ? "the JSON of --json" : "the summary");
    }
    checkCompareMemory(o);
    const Image actual = read(o.actual, "ACTUAL");
    const Image expected = read(o.expected, "EXPECTED");
    std::optional<Image> mask;
    if (!o.mask.empty()) {
        mask = read(o.mask, "--mask");
        if (mask->width != actual.width || mask->height != actual.height)
            throw InputError("--mask: " + std::to_string(mask->width) + "x" + std::to_string(mask->height) +
                             ", but ACTUAL is " + std::to_string(actual.width) + "x" +
                             std::to_string(actual.height));
    }
    const bool sameSize = actual.width == expected.width && actual.height == expected.height;
    const Comparison c = compareImages(actual, expected, Tolerance{o.maxDelta, o.meanDelta, o.outliers},
                                       sameSize && mask ? &*mask : nullptr);
    const bool writeDiff = !c.passed && !o.diff.empty();
    if (writeDiff) writePng(diffImage(actual, expected), o.diff);
    if (o.json) {
        std::printf("%s\n", comparisonJson(c, o, writeDiff).c_str());
    } else {
        std::printf("%s\n", c.summary().c_str());
        if (writeDiff) std::printf("difference ×8 written to %s\n", printable(o.diff).c_str());
    }
    return c.passed ? kExitOk : kExitRuntimeError; // as cmp and diff: 1 is "they differ"
}

} // namespace shadelab::app
