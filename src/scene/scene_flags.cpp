// The scene flags shared by every command and the page (DESIGN §5: flags override the scene file).
#include "shadelab/scene/scene_flags.h"

#include <cmath>
#include <cstdlib>
#include <string_view>

#include "shadelab/errors.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/geometry/teapot.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/scene_file.h"
#include "shadelab/scene/scene_values.h"
#include "shadelab/vocabulary.h"

namespace shadelab {
namespace {

// "scene (the scene as the camera sees it), error (E: error view: ...), ...": every view named alone with
// its key and what it shows, from their one table (view.h kViewNames).
std::string viewHelp() {
    std::string text;
    for (const ViewName& view : kViewNames)
        if (view.kind != ViewKind::Split)
            text += (text.empty() ? "" : ", ") + std::string(view.name) + " (" +
                    (view.key.empty() ? "" : std::string(view.key) + ": ") + std::string(view.help) + ")";
    return text;
}

} // namespace

const std::vector<SceneFlag>& sceneFlags() {
    static const std::vector<SceneFlag> kFlags = {
        {"shading", &SceneOverrides::shading,
         "Shading mode: " + joinNames(kAllShadingModes) +
             " (exact: each sphere and teapot ray-cast per pixel, the analytic reference; a model: Phong of "
             "its "
             "own normals; overrides the scene)"},
        {"lighting", &SceneOverrides::lighting,
         "Lighting model: " + joinNames(kLightingModels) + " (overrides the scene)"},
        {"term", &SceneOverrides::term,
         "Term of the lighting sum drawn: " + joinNames(kLightingTerms) +
             " (ambient k_a*I_a, diffuse k_d*I_d*max(l.n,0), specular k_s*I_s*spec, each as the shading mode "
             "evaluates it; all: their sum)"},
        {"perspective-matrix", &SceneOverrides::perspectiveMatrix,
         "Perspective matrix: " + joinNames(kPerspectiveMatrices) +
             " (webgl: the lecture's matrix times -1, w > 0 in front of the eye; unnegated: before the -1, w "
             "< 0 "
             "in front, so everything is clipped and the picture is empty, on purpose)"},
        {"normal-matrix", &SceneOverrides::normalMatrix,
         "What transforms normals: " + joinNames(kNormalMatrixRules) +
             " (inverse-transpose: (M^-1)^T, which keeps them perpendicular to the surface; model: M itself, "
             "wrong wherever M scales unevenly, the lecture's wrong picture on purpose)"},
        {"subdivisions", &SceneOverrides::subdivisions,
         "Subdivision level of every sphere, 0.." + std::to_string(kMaxSubdivisions) + ", and teapot, 0.." +
             std::to_string(kMaxTeapotLevel) +
             ", or auto: the smallest level whose silhouette error stays below --tolerance-px"},
        {"tolerance-px", &SceneOverrides::tolerancePx,
         "Silhouette error auto subdivision allows (default 0.5)"},
        {"depth", &SceneOverrides::depth,
         "Depth mode: " + joinNames(kDepthModes) +
             " (standard: DESIGN's [-1,1] convention; reversed: reversed-Z, 32-bit float depth; "
             "reversed-infinite: reversed-Z with the far plane at infinity)"},
        {"overlay", &SceneOverrides::overlay,
         "Lines over the surface: " + joinNames(kOverlays) +
             " (wireframe: the mesh's edges; normals: edges, face and vertex normals)"},
        {"view", &SceneOverrides::view,
         "What the picture shows: " + viewHelp() +
             ", split:A,B or side-by-side:A,B (V: " + std::string(viewNamed(ViewKind::Split).help) +
             "; A, B each shading[/lighting][@level][{settings}], e.g. split:gouraud,phong, "
             "split:phong@4,phong@6, side-by-side:phong{shininess=8},phong{shininess=150}; settings: term, "
             "normal_matrix, ambient, diffuse, specular, shininess)"},
        {"size", &SceneOverrides::size, "Image size WxH, e.g. 512x512 (overrides the scene)"},
    };
    return kFlags;
}

std::optional<std::string>* overrideNamed(SceneOverrides& overrides, std::string_view name) {
    for (const SceneFlag& flag : sceneFlags())
        if (flag.name == name) return &(overrides.*flag.value);
    return nullptr;
}

std::string flagList() {
    std::string list;
    for (const SceneFlag& flag : sceneFlags())
        list += (list.empty() ? "--" : ", --") + std::string(flag.name);
    return list;
}

// The syntax is the flag's; each side's range is the scene's image.width and image.height (scene_values.h).
void composeSize(Scene& scene, const std::string& text) {
    const std::size_t x = text.find('x');
    const auto width = digitsValue(std::string_view(text).substr(0, x), 9);
    const auto height =
        x == std::string::npos ? std::nullopt : digitsValue(std::string_view(text).substr(x + 1), 9);
    if (!width || !height)
        throw InputError("--size: expected WxH with W and H in " + toString(kImageSizeRange) +
                         " (e.g. 512x512), got " + quotedValue(text));
    checkImageSize(*width, "--size width");
    checkImageSize(*height, "--size height");
    scene.width = *width;
    scene.height = *height;
}

namespace {

// "auto" or a whole number; its range is the scene's (checkSubdivisionLevel, which names the memory a
// level above the maximum would need).
int parseLevel(const std::string& text) {
    if (text == "auto") return kAutoSubdivisions;
    const bool negative = text.starts_with('-');
    const auto digits = digitsValue(std::string_view(text).substr(negative ? 1 : 0), 9);
    if (!digits)
        throw InputError("--subdivisions: expected a level " + toString(kSubdivisionRange) +
                         " or auto, got " + quotedValue(text));
    const int level = negative ? -*digits : *digits;
    checkSubdivisionLevel(level, "--subdivisions");
    return level;
}

// Every sphere's and teapot's level; a mesh has none (its triangles are the file's, DESIGN §4). A level
// beyond the teapot's range is the flag's error where the scene holds a teapot.
void setLevels(Scene& scene, int level) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        SceneObject& object = scene.objects[i];
        if (object.shape == Shape::Mesh) continue;
        if (object.shape == Shape::Teapot && level != kAutoSubdivisions) {
            try {
                checkTeapotLevel(level, "--subdivisions");
            } catch (const InputError& e) {
                throw InputError(std::string(e.what()) + " (objects[" + std::to_string(i) + "] is a teapot)");
            }
        }
        object.subdivisions = level;
    }
}

// A decimal number: an optional sign, digits, an optional fraction and exponent. Not hex (0x10), not inf or
// nan, not empty, nothing after the number. Scanned by hand: std::regex matches `[0-9]+` by recursion, one
// frame a character, and a 50,000-digit argument overflowed the stack.
bool isDecimal(std::string_view text) {
    std::size_t i = 0;
    auto sign = [&] {
        if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    };
    auto digits = [&] {
        const std::size_t start = i;
        while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
        return i - start;
    };
    sign();
    const std::size_t whole = digits();
    std::size_t fraction = 0;
    if (i < text.size() && text[i] == '.') {
        ++i;
        fraction = digits();
    }
    if (whole == 0 && fraction == 0) return false;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        sign();
        if (digits() == 0) return false;
    }
    return i == text.size();
}

// A decimal number of pixels. Its range is the scene's (checkTolerancePx), so a negative number is refused
// there, as tolerance_px's is.
double parseTolerance(const std::string& text) {
    if (!isDecimal(text))
        throw InputError("--tolerance-px: expected a positive decimal number of pixels such as 0.5, got " +
                         quotedValue(printable(text)));
    const double value = std::strtod(text.c_str(), nullptr);
    if (!std::isfinite(value)) failNotFinite("--tolerance-px", text); // 1e400, as a scene file's is refused
    checkTolerancePx(value, "--tolerance-px");
    return value;
}

} // namespace

Scene composeScene(const std::string& path, const SceneOverrides& overrides) {
    return applyOverrides(path.empty() ? Scene{} : loadScene(path), overrides, path);
}

Scene applyOverrides(Scene scene, const SceneOverrides& o, const std::string& path) {
    if (o.shading) scene.shading = parseNameOrThrow(*o.shading, "--shading", kAllShadingModes);
    if (o.lighting) scene.lighting = parseNameOrThrow(*o.lighting, "--lighting", kLightingModels);
    if (o.term) scene.term = parseNameOrThrow(*o.term, "--term", kLightingTerms);
    if (o.perspectiveMatrix)
        scene.perspectiveMatrix =
            parseNameOrThrow(*o.perspectiveMatrix, "--perspective-matrix", kPerspectiveMatrices);
    if (o.normalMatrix)
        scene.normalMatrix = parseNameOrThrow(*o.normalMatrix, "--normal-matrix", kNormalMatrixRules);
    if (o.subdivisions) setLevels(scene, parseLevel(*o.subdivisions));
    if (o.depth) scene.depth = parseNameOrThrow(*o.depth, "--depth", kDepthModes);
    if (o.overlay) scene.overlay = parseNameOrThrow(*o.overlay, "--overlay", kOverlays);
    if (o.view) {
        const std::optional<double> at = scene.view.at;
        scene.view = parseViewOrThrow(*o.view, "--view");
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

} // namespace shadelab
