#include <cstdio>

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

} // namespace shadelab::app
