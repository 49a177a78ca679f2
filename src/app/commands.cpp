#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <regex>

#include "app/commands.h"
#include "app/memory_budget.h"
#include "shadelab/atomic_file.h"
#include "shadelab/errors.h"
#include "shadelab/headless.h"
#include "shadelab/reference.h"
#include "shadelab/text.h"

namespace shadelab::app {
namespace {

std::string quoted(const std::string& s) {
    return "\"" + s + "\"";
}

} // namespace

void composeSize(Scene& scene, const std::string& text) {
    static const std::regex kSize(R"(([0-9]{1,9})x([0-9]{1,9}))");
    std::smatch m;
    const std::string range = "1.." + std::to_string(kMaxImageSize);
    if (!std::regex_match(text, m, kSize))
        throw InputError("--size: expected WxH with W and H in " + range + " (e.g. 512x512), got " +
                         quoted(text));
    const long width = std::stol(m[1]), height = std::stol(m[2]);
    if (width < 1 || height < 1 || width > kMaxImageSize || height > kMaxImageSize)
        throw InputError("--size: W and H must be in " + range + ", got " + quoted(text));
    scene.width = int(width);
    scene.height = int(height);
}

namespace {

// "auto" or a whole number 0..kMaxSubdivisions; a larger level names the memory it would need.
int parseLevel(const std::string& text) {
    if (text == "auto") return kAutoSubdivisions;
    static const std::regex kLevel(R"(-?[0-9]{1,9})");
    if (!std::regex_match(text, kLevel))
        throw InputError("--subdivisions: expected a level 0.." + std::to_string(kMaxSubdivisions) +
                         " or auto, got " + quoted(text));
    const int level = std::stoi(text);
    checkSubdivisionLevel(level, "--subdivisions");
    return level;
}

// A positive decimal number of pixels: digits, an optional fraction and exponent. Not hex (0x10), not
// inf or nan, not empty, nothing after the number.
double parseTolerance(const std::string& text) {
    static const std::regex kDecimal(R"([+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?)");
    const std::string shown = quoted(printable(text));
    if (!std::regex_match(text, kDecimal))
        throw InputError("--tolerance-px: expected a positive decimal number of pixels such as 0.5, got " +
                         shown);
    const double value = std::strtod(text.c_str(), nullptr);
    if (!(value > 0) || !std::isfinite(value))
        throw InputError("--tolerance-px: must be a positive, finite number of pixels such as 0.5, got " +
                         shown);
    return value;
}

} // namespace

Scene composeScene(const std::string& path, const SceneOverrides& o) {
    Scene scene = path.empty() ? Scene{} : loadScene(path);
    if (o.shading) {
        const auto mode = parseShadingMode(*o.shading);
        if (!mode)
            throw InputError("--shading: unknown value " + quoted(*o.shading) +
                             "; expected one of flat, gouraud, phong, toon");
        scene.shading = *mode;
    }
    if (o.lighting) {
        const auto model = parseLightingModel(*o.lighting);
        if (!model)
            throw InputError("--lighting: unknown value " + quoted(*o.lighting) +
                             "; expected one of phong, blinn-phong");
        scene.lighting = *model;
    }
    if (o.subdivisions) {
        const int level = parseLevel(*o.subdivisions);
        for (SceneObject& object : scene.objects) object.subdivisions = level;
    }
    if (o.depth) {
        const auto mode = parseDepthMode(*o.depth);
        if (!mode)
            throw InputError("--depth: unknown value " + quoted(*o.depth) +
                             "; expected one of standard, reversed, reversed-infinite");
        scene.depth = *mode;
    }
    if (o.tolerancePx) scene.tolerancePx = parseTolerance(*o.tolerancePx);
    if (o.size) composeSize(scene, *o.size);
    try {
        validateScene(scene);
    } catch (const InputError& e) { // name the file the values came from, as parsing does
        if (path.empty() || path == "-") throw;
        throw InputError(printable(path) + ": " + e.what());
    }
    return scene;
}

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
    if (request.backend == Backend::Osmesa && request.api == Api::Gles)
        throw InputError("--api gles: OSMesa offers desktop OpenGL only; use --backend egl for OpenGL ES");
    if (request.backend == Backend::Osmesa && request.eglDevice)
        throw InputError("--egl-device: a choice of the EGL backend; leave it out with --backend osmesa");
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
    renderer.setSpecialize(specialize);
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

} // namespace shadelab::app
