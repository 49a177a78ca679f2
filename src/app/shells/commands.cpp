#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <regex>

#include "app/measure/memory_budget.h"
#include "app/shells/commands.h"
#include "shadelab/atomic_file.h"
#include "shadelab/errors.h"
#include "shadelab/gl/program.h"
#include "shadelab/headless.h"
#include "shadelab/reference.h"
#include "shadelab/text.h"

namespace shadelab::app {
namespace {

std::string quoted(const std::string& s) {
    return "\"" + s + "\"";
}

} // namespace

void checkOutputPath(const std::filesystem::path& out, const char* argument) {
    (void)resolveOutput(out, argument); // throws InputError for what cannot be an output
}

Api apiFromArgument(const std::string& name) {
    const auto api = parseApi(name);
    if (!api)
        throw InputError("--api: unknown value " + quoted(name) +
                         "; expected gl (desktop OpenGL 3.3 core) or gles (OpenGL ES 3.0)");
    return *api;
}

ContextRequest contextFromArguments(const std::string& backend, const std::string& api,
                                    const std::string& eglDevice) {
    ContextRequest request;
    const auto parsed = parseBackend(backend);
    if (!parsed) throw InputError("--backend: unknown value " + quoted(backend) + "; expected egl or osmesa");
    request.backend = *parsed;
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

namespace {

std::string sizeText(const Scene& scene) {
    return std::to_string(scene.width) + "x" + std::to_string(scene.height);
}

} // namespace

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
    writePng(toImage8(renderReference(scene).color), out);
    return kExitOk;
}

int runShowcase(const Scene& scene, const ContextRequest& context, const std::filesystem::path& out) {
    // Four panels of the scene's size side by side.
    checkMemoryBudget("the showcase of " + sizeText(scene), kGlBaselineBytes + 4 * renderBytes(scene),
                      "--size (or the scene's image)");
    HeadlessRenderer renderer(context);
    writePng(renderShowcase(renderer, scene), out);
    if (out != "-") std::printf("%s\n", out.string().c_str());
    return kExitOk;
}

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
    Image actual = read(o.actual, "ACTUAL");
    const Image expected = read(o.expected, "EXPECTED");
    if (!o.mask.empty()) {
        const Image mask = read(o.mask, "--mask");
        if (mask.width != actual.width || mask.height != actual.height)
            throw InputError("--mask: " + std::to_string(mask.width) + "x" + std::to_string(mask.height) +
                             ", but ACTUAL is " + std::to_string(actual.width) + "x" +
                             std::to_string(actual.height));
        // Black in the mask: not compared (the expected pixel is taken as the actual one).
        if (expected.width == actual.width && expected.height == actual.height)
            for (std::size_t i = 0; i < mask.rgba.size(); i += 4)
                if (mask.rgba[i] == 0 && mask.rgba[i + 1] == 0 && mask.rgba[i + 2] == 0)
                    std::copy_n(&expected.rgba[i], 4, &actual.rgba[i]);
    }
    const Comparison c = compareImages(actual, expected, Tolerance{o.maxDelta, o.meanDelta, o.outliers});
    std::printf("%s\n", c.summary().c_str());
    if (c.passed) return kExitOk;
    if (!o.diff.empty() && c.sizeMatches) {
        writePng(diffImage(actual, expected), o.diff);
        std::printf("difference ×8 written to %s\n", printable(o.diff).c_str());
    }
    return kExitRuntimeError; // as cmp and diff: 1 is "they differ"
}

} // namespace shadelab::app
