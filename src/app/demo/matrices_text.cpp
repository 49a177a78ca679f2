#include "app/demo/matrices_text.h"

#include <cmath>
#include <cstdio>
#include <initializer_list>

#include "shadelab/errors.h"
#include "shadelab/scene/camera.h"

namespace shadelab::app {
namespace {

// printf into a string.
template <typename... Args> std::string printed(const char* format, Args... args) {
    char text[48];
    std::snprintf(text, sizeof text, format, args...);
    return text;
}

constexpr int kDecimals = 4;

// Fixed point where that shows the number in kEntryDigits characters (4 decimals, magnitudes 1e-3..999),
// otherwise exponent form (3 significant digits, 2 with a three-digit exponent); a whole number, or one
// within float noise of it (1e-12: -1.11e-16 is 0, never -0), as its digits alone, aligned with the units
// of the fixed-point entries.
std::string entryDigits(double x) {
    const double whole = std::round(x) + 0.0; // + 0.0 turns -0 into 0
    if (std::abs(x - whole) <= 1e-12 && std::abs(whole) < 1e3)
        return printed("%.0f", whole) + std::string(kDecimals + 1, ' ');
    if (std::abs(x) >= 1e-3) {
        std::string fixed = printed("%.*f", kDecimals, x);
        if (fixed.size() <= kEntryDigits) return fixed;
    }
    std::string exponent = printed("%.2e", x);
    return exponent.size() <= kEntryDigits ? exponent : printed("%.1e", x);
}

} // namespace

// Right-aligned after one space: columns line up and entries never touch, whatever their magnitude.
std::string matrixEntry(double x) {
    const std::string digits = entryDigits(x);
    return std::string(kEntryDigits + 1 - digits.size(), ' ') + digits;
}

namespace {

std::string row(std::initializer_list<double> values) {
    std::string text = "[";
    for (double v : values) text += matrixEntry(v);
    return text + " ]\n";
}

std::string vectorRow(const char* name, const glm::dvec3& v) {
    return std::string(name) + " = " + row({v.x, v.y, v.z});
}

// Rows of a column-major GLM matrix, as the lecture writes them.
std::string matrix(const glm::dmat4& m) {
    std::string text;
    for (int r = 0; r < 4; ++r) text += "  " + row({m[0][r], m[1][r], m[2][r], m[3][r]});
    return text;
}
std::string matrix(const glm::dmat3& m) {
    std::string text;
    for (int r = 0; r < 3; ++r) text += "  " + row({m[0][r], m[1][r], m[2][r]});
    return text;
}

std::string shortNumber(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", x);
    return text;
}

// What the projection matrix normalizes, in the lecture's terms (n and f are z-coordinates, DESIGN §2).
// Lines of at most 45 characters, as wide as a matrix row: the panel's column is narrow.
std::string projectionHeading(const Scene& scene, const SceneView& view) {
    const ViewVolume& v = view.volume;
    std::string text = std::string(view.orthographic ? "M_orth" : "M_proj") + ", " +
                       std::string(toString(scene.projection.type));
    if (scene.projection.type == ProjectionType::Perspective)
        text += ": fovy " + shortNumber(scene.projection.fovyDeg) + " deg, aspect " +
                shortNumber(double(scene.width) / scene.height);
    text += "\n  [l,r] = [" + shortNumber(v.left) + ", " + shortNumber(v.right) + "], [b,t] = [" +
            shortNumber(v.bottom) + ", " + shortNumber(v.top) + "]\n  n = " + shortNumber(-v.near) +
            ", f = " + shortNumber(-v.far) + " (z-coordinates)\n";
    if (scene.depth != DepthMode::Standard)
        text += "  " + std::string(toString(scene.depth)) + " depth: z in [0, 1], near -> 1\n";
    else if (leavesOutTheMinusOne(scene))
        text += "  unnegated (no -1): w = z < 0 in front,\n  so everything is clipped\n";
    else if (!view.orthographic)
        text += "  times -1 (WebGL): w = -z > 0 in front;\n  near -> z = +1, far -> z = -1\n";
    else
        text += "  near -> z = +1, far -> z = -1\n";
    return text;
}

} // namespace

std::string cameraMatricesText(const Scene& scene) {
    const SceneView view = sceneView(scene);
    const CameraFrame frame = cameraFrame(scene.eye, scene.target, scene.up);
    std::string text = "camera frame: w = normalize(e - g),\n  u = normalize(up x w), v = w x u\n";
    text += vectorRow("e", frame.eye) + vectorRow("u", frame.u) + vectorRow("v", frame.v) +
            vectorRow("w", frame.w);
    text += "M_cam = [u v w e]^-1: rows u, v, w\n  with -u.e, -v.e, -w.e\n" + matrix(view.viewFromWorld);
    return text + projectionHeading(scene, view) + matrix(view.clipFromView);
}

std::string objectMatricesText(const Scene& scene, std::size_t object) {
    const glm::dmat4 worldFromObjectM = worldFromObject(scene.objects.at(object));
    const glm::dmat4 viewFromWorldM = viewFromWorld(cameraFrame(scene.eye, scene.target, scene.up));
    const glm::dmat3 viewFromObject3(viewFromWorldM * worldFromObjectM);
    std::string text =
        "M (object " + std::to_string(object + 1) + "): translate(c) scale(r s)\n" + matrix(worldFromObjectM);
    if (scene.normalMatrix == NormalMatrixRule::InverseTranspose)
        text +=
            "normal matrix ((M_cam M)^-1)^T, 3x3\n" + matrix(glm::transpose(glm::inverse(viewFromObject3)));
    else
        text += "normal matrix M_cam M, 3x3: normals by M,\n  wrong on purpose\n" + matrix(viewFromObject3);
    return text;
}

std::string matricesPanelText(const Scene& scene, std::optional<std::size_t> object) {
    try {
        return cameraMatricesText(scene) + (object ? objectMatricesText(scene, *object) : "");
    } catch (const InputError& e) {
        return e.what();
    }
}

} // namespace shadelab::app
