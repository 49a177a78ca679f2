// libFuzzer target for the scene parser (DESIGN §4). For any bytes, parseScene either returns a scene or
// throws InputError; anything else (another exception, a sanitizer report, a hang) is a crash. A scene it
// returns must pass validateSceneValues (the two share their range checks; the scene-wide limits are
// validateScene's alone, checked after the command line's overrides) and survive sceneToJson →
// parseScene unchanged (the demo saves scenes that way beside its screenshots).
//
// SHADELAB_FUZZ_STRICT=1 adds two checks that known open bugs still fail (fuzz/README.md), so they are off
// by default to keep CI's budgeted run meaningful: an accepted scene whose matrices (sceneView) are not
// finite ("never a NaN matrix"; an InputError is allowed), and an InputError message
// longer than kMaxMessageBytes (user text must come back truncated).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>

#include "shadelab/errors.h"
#include "shadelab/scene/scene.h"

namespace {

using namespace shadelab;

// A message longer than this floods the terminal with the user's own bytes.
constexpr std::size_t kMaxMessageBytes = 1000;

bool strict = false;

[[noreturn]] void crash(std::string_view what, std::string_view detail) {
    std::fprintf(stderr, "scene_fuzzer: %.*s: %.*s\n", int(what.size()), what.data(), int(detail.size()),
                 detail.data());
    std::abort();
}

// Exact equality, -0 == 0 included: sceneToJson writes doubles in shortest round-trip form.
bool same(const glm::dvec3& a, const glm::dvec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

bool same(const Projection& a, const Projection& b) {
    return a.type == b.type && a.fovyDeg == b.fovyDeg && a.left == b.left && a.right == b.right &&
           a.bottom == b.bottom && a.top == b.top && a.near == b.near && a.far == b.far;
}

bool same(const Material& a, const Material& b) {
    return same(a.ambient, b.ambient) && same(a.diffuse, b.diffuse) && same(a.specular, b.specular) &&
           a.shininess == b.shininess;
}

bool same(const SceneObject& a, const SceneObject& b) {
    return a.shape == b.shape && a.mesh == b.mesh && a.closed == b.closed &&
           a.materialGiven == b.materialGiven && same(a.center, b.center) && a.radius == b.radius &&
           same(a.scale, b.scale) && a.subdivisions == b.subdivisions && same(a.material, b.material);
}

bool same(const Light& a, const Light& b) {
    return a.type == b.type && same(a.ambient, b.ambient) && same(a.diffuse, b.diffuse) &&
           same(a.specular, b.specular) && same(a.position, b.position) && same(a.direction, b.direction) &&
           a.cutoffDeg == b.cutoffDeg && a.exponent == b.exponent && same(a.attenuation, b.attenuation);
}

// The first field that differs, or empty.
std::string difference(const Scene& a, const Scene& b) {
    if (a.width != b.width || a.height != b.height) return "image size";
    if (!same(a.background, b.background)) return "image.background";
    if (!same(a.eye, b.eye) || !same(a.target, b.target) || !same(a.up, b.up)) return "camera";
    if (!same(a.projection, b.projection)) return "projection";
    if (a.shading != b.shading) return "shading";
    if (a.lighting != b.lighting) return "lighting";
    if (a.toonBands != b.toonBands) return "toon_bands";
    if (a.tolerancePx != b.tolerancePx) return "tolerance_px";
    if (a.depth != b.depth) return "depth";
    if (a.vertexNormals != b.vertexNormals) return "vertex_normals";
    if (a.objects.size() != b.objects.size()) return "objects count";
    for (std::size_t i = 0; i < a.objects.size(); ++i)
        if (!same(a.objects[i], b.objects[i])) return "objects[" + std::to_string(i) + "]";
    if (a.lights.size() != b.lights.size()) return "lights count";
    for (std::size_t i = 0; i < a.lights.size(); ++i)
        if (!same(a.lights[i], b.lights[i])) return "lights[" + std::to_string(i) + "]";
    return {};
}

bool allFinite(const glm::dmat4& m) {
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row)
            if (!std::isfinite(m[column][row])) return false;
    return true;
}

void checkAccepted(const Scene& scene) {
    try {
        validateSceneValues(scene);
    } catch (const InputError& e) {
        crash("parseScene accepted a scene that validateSceneValues rejects", e.what());
    }
    const std::string json = sceneToJson(scene);
    Scene again;
    try {
        again = parseScene(json, "round-trip");
    } catch (const InputError& e) {
        crash("sceneToJson wrote what parseScene rejects", std::string(e.what()) + "\n" + json);
    }
    if (const std::string field = difference(scene, again); !field.empty())
        crash("sceneToJson -> parseScene changed " + field, json);
    if (!strict) return;
    try {
        const SceneView view = sceneView(scene);
        if (!allFinite(view.viewFromWorld) || !allFinite(view.clipFromView))
            crash("sceneView of an accepted scene has a non-finite matrix", json);
    } catch (const InputError&) {
        // A degenerate camera or volume found late is still reported as bad input (exit 2).
    }
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const char* flag = std::getenv("SHADELAB_FUZZ_STRICT");
    strict = flag != nullptr && std::string_view(flag) == "1";
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    Scene scene;
    try {
        scene = parseScene(text, "fuzz");
    } catch (const InputError& e) {
        const std::string_view message = e.what();
        if (strict && message.size() > kMaxMessageBytes)
            crash("an unbounded message", std::string(message.substr(0, 300)) + "...");
        return 0; // bad input, reported as such
    } catch (const std::exception& e) {
        crash("parseScene threw something other than InputError", e.what());
    }
    try {
        checkAccepted(scene);
    } catch (const std::exception& e) {
        crash("a check of an accepted scene threw", e.what());
    }
    return 0;
}
