#include "shadelab/scene/camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <utility>

#include "shadelab/errors.h"
#include "shadelab/shading/lighting.h"

namespace shadelab {
namespace {

std::string str(const glm::dvec3& v) {
    std::ostringstream out;
    out << "[" << v.x << ", " << v.y << ", " << v.z << "]";
    return out.str();
}

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

CameraFrame cameraFrame(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up) {
    if (!finite(eye) || !finite(target) || !finite(up))
        throw InputError("camera: eye, target and up must be finite");
    const glm::dvec3 back = eye - target;
    if (!finite(back))
        throw InputError("camera: eye " + str(eye) + " and target " + str(target) +
                         " are too far apart for double precision; move them closer together");
    if (back == glm::dvec3(0))
        throw InputError("camera: eye " + str(eye) + " equals target " + str(target) +
                         "; move the eye away from the target");
    // Both made unit scale-free (divided by their largest component first): |e − t|² would overflow for an
    // eye at 1.4e154 and underflow for a tiny up. |û × w| = sin θ, and 1e-9 rad is far below any usable
    // camera and far above rounding noise.
    const glm::dvec3 w = unitDirection(back);
    if (up == glm::dvec3(0)) throw InputError("camera.up: must be non-zero, got " + str(up));
    const glm::dvec3 side = glm::cross(unitDirection(up), w);
    if (!(glm::length(side) > 1e-9))
        throw InputError("camera: up " + str(up) + " is parallel to the view direction " + str(-w) +
                         "; choose an up vector not parallel to target − eye");
    const glm::dvec3 u = glm::normalize(side);
    return CameraFrame{u, glm::cross(w, u), w, eye};
}

glm::dmat4 viewFromWorld(const CameraFrame& f) {
    // Rows (uᵀ, −u·e), (vᵀ, −v·e), (wᵀ, −w·e), (0,0,0,1); GLM is column-major: m[column][row].
    glm::dmat4 m(1.0);
    for (int i = 0; i < 3; ++i) {
        m[i][0] = f.u[i];
        m[i][1] = f.v[i];
        m[i][2] = f.w[i];
    }
    m[3] = glm::dvec4(-glm::dot(f.u, f.eye), -glm::dot(f.v, f.eye), -glm::dot(f.w, f.eye), 1.0);
    return m;
}

void validateViewVolume(const ViewVolume& vv) {
    const std::pair<const char*, double> planes[] = {{"left", vv.left},     {"right", vv.right},
                                                     {"bottom", vv.bottom}, {"top", vv.top},
                                                     {"near", vv.near},     {"far", vv.far}};
    for (const auto& [name, value] : planes)
        if (!std::isfinite(value))
            throw InputError(std::string("projection.") + name + ": must be a finite number, got " +
                             std::to_string(value));
    if (!(vv.near > 0))
        throw InputError("projection.near: must be > 0 (a distance in front of the eye), got " +
                         std::to_string(vv.near));
    if (!(vv.near < vv.far))
        throw InputError("projection.far: must be > near (" + std::to_string(vv.near) + "), got " +
                         std::to_string(vv.far));
    if (vv.left == vv.right)
        throw InputError("projection: left and right are both " + std::to_string(vv.left) +
                         "; they must differ");
    if (vv.bottom == vv.top)
        throw InputError("projection: bottom and top are both " + std::to_string(vv.bottom) +
                         "; they must differ");
}

ViewVolume viewVolumeFromFovy(double fovyDeg, double aspect, double near, double far) {
    if (!(fovyDeg > 0 && fovyDeg < 180))
        throw InputError("projection.fovy_deg: must be in (0, 180), got " + std::to_string(fovyDeg));
    validateViewVolume({-1, 1, -1, 1, near, far}); // near and far first: they scale every other plane
    if (!(aspect > 0) || !std::isfinite(aspect))
        throw InputError("image: aspect ratio must be positive and finite");
    const double top = near * std::tan(fovyDeg * std::numbers::pi / 360.0);
    ViewVolume vv{-top * aspect, top * aspect, -top, top, near, far};
    validateViewVolume(vv);
    return vv;
}

glm::dmat4 orthographicClipFromView(const ViewVolume& vv) {
    validateViewVolume(vv);
    const double l = vv.left, r = vv.right, b = vv.bottom, t = vv.top;
    const double n = -vv.near, f = -vv.far; // DESIGN §2's z-coordinates
    glm::dmat4 m(1.0);
    m[0][0] = 2 / (r - l);
    m[1][1] = 2 / (t - b);
    m[2][2] = 2 / (n - f);
    m[3] = glm::dvec4(-(r + l) / (r - l), -(t + b) / (t - b), -(n + f) / (n - f), 1.0);
    return m;
}

glm::dmat4 perspectiveClipFromView(const ViewVolume& vv) {
    validateViewVolume(vv);
    const double l = vv.left, r = vv.right, b = vv.bottom, t = vv.top;
    const double n = -vv.near, f = -vv.far; // DESIGN §2's z-coordinates
    glm::dmat4 m(0.0);                      // DESIGN §2, written row by row: m[column][row]
    m[0][0] = -2 * n / (r - l);
    m[2][0] = (r + l) / (r - l);
    m[1][1] = -2 * n / (t - b);
    m[2][1] = (t + b) / (t - b);
    m[2][2] = -(n + f) / (n - f);
    m[3][2] = 2 * f * n / (n - f);
    m[2][3] = -1;
    return m;
}

glm::dmat4 reversedPerspectiveClipFromView(const ViewVolume& vv, bool infiniteFar) {
    glm::dmat4 m = perspectiveClipFromView(vv); // x, y and w rows as in the standard matrix
    // z_clip = A·w + B with w = −z: depth = A + B/(−z), 1 at −near, 0 at −far (or at infinity).
    const double b = infiniteFar ? vv.near : vv.near * vv.far / (vv.far - vv.near);
    const double a = infiniteFar ? 0.0 : -vv.near / (vv.far - vv.near);
    m[2][2] = -a; // the z column: z_clip = −a·z + b
    m[3][2] = b;
    return m;
}

glm::dmat4 reversedOrthographicClipFromView(const ViewVolume& vv) {
    glm::dmat4 m = orthographicClipFromView(vv);
    m[2][2] = 1 / (vv.far - vv.near);
    m[3][2] = vv.far / (vv.far - vv.near);
    return m;
}

glm::dmat3 normalMatrix(const glm::dmat4& viewFromObject) {
    const glm::dmat3 m(viewFromObject);
    // Cofactor matrix: its columns are cross products of M's columns; equals det(M)·M⁻ᵀ.
    glm::dmat3 cof(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
    const double det = glm::dot(m[0], cof[0]);
    return det < 0 ? -cof : cof;
}

std::string_view toString(PerspectiveMatrix matrix) {
    return matrix == PerspectiveMatrix::Unnegated ? "unnegated" : "webgl";
}

std::string_view toString(NormalMatrixRule rule) {
    return rule == NormalMatrixRule::Model ? "model" : "inverse-transpose";
}

double largestAbsEntry(const glm::dmat3& m) {
    double k = 0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) k = std::max(k, std::abs(m[c][r]));
    return k;
}

glm::dmat3 normalViewFromObject(const glm::dmat4& viewFromObject, NormalMatrixRule rule) {
    const glm::dmat3 linear(viewFromObject);
    const double k = largestAbsEntry(linear);
    const glm::dmat3 unit = k > 0 ? linear / k : linear;
    const glm::dmat3 normal = rule == NormalMatrixRule::Model ? unit : normalMatrix(glm::dmat4(unit));
    const double n = largestAbsEntry(normal);
    return n > 0 ? normal / n : normal;
}

} // namespace shadelab
