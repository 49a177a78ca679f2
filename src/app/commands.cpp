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
