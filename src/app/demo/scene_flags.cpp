// The scene flags shared by every command and the page (DESIGN §5: flags override the scene file).
#include "app/demo/scene_flags.h"

#include <cmath>
#include <cstdlib>
#include <regex>

#include "shadelab/errors.h"
#include "shadelab/sphere.h"
#include "shadelab/text.h"
#include "shadelab/vocabulary.h"

namespace shadelab::app {

void composeSize(Scene& scene, const std::string& text) {
    static const std::regex kSize(R"(([0-9]{1,9})x([0-9]{1,9}))");
    std::smatch m;
    const std::string range = "1.." + std::to_string(kMaxImageSize);
    if (!std::regex_match(text, m, kSize))
        throw InputError("--size: expected WxH with W and H in " + range + " (e.g. 512x512), got " +
                         quotedValue(text));
    const long width = std::stol(m[1]), height = std::stol(m[2]);
    if (width < 1 || height < 1 || width > kMaxImageSize || height > kMaxImageSize)
        throw InputError("--size: W and H must be in " + range + ", got " + quotedValue(text));
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
                         " or auto, got " + quotedValue(text));
    const int level = std::stoi(text);
    checkSubdivisionLevel(level, "--subdivisions");
    return level;
}

// A positive decimal number of pixels: digits, an optional fraction and exponent. Not hex (0x10), not
// inf or nan, not empty, nothing after the number.
double parseTolerance(const std::string& text) {
    static const std::regex kDecimal(R"([+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?)");
    const std::string shown = quotedValue(printable(text));
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

Scene composeScene(const std::string& path, const SceneOverrides& overrides) {
    return applyOverrides(path.empty() ? Scene{} : loadScene(path), overrides, path);
}

Scene applyOverrides(Scene scene, const SceneOverrides& o, const std::string& path) {
    if (o.shading) scene.shading = parseNameOrThrow(*o.shading, "--shading", kAllShadingModes);
    if (o.lighting) scene.lighting = parseNameOrThrow(*o.lighting, "--lighting", kLightingModels);
    if (o.subdivisions) {
        const int level = parseLevel(*o.subdivisions);
        for (SceneObject& object : scene.objects) object.subdivisions = level;
    }
    if (o.depth) scene.depth = parseNameOrThrow(*o.depth, "--depth", kDepthModes);
    if (o.overlay) scene.overlay = parseNameOrThrow(*o.overlay, "--overlay", kOverlays);
    if (o.view) {
        ViewParse parsed = parseView(*o.view);
        if (!parsed.view) throw InputError("--view: " + quotedValue(*o.view) + ": " + parsed.error);
        const std::optional<double> at = scene.view.at;
        scene.view = *parsed.view;
        if (scene.view.kind == ViewKind::Split || scene.view.kind == ViewKind::Profile) scene.view.at = at;
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

} // namespace shadelab::app
