#include "shadelab/geometry/subdivision.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadelab {
namespace {

struct Projection2D {
    double radiusPx; // +infinity with the eye inside the bounding sphere
    double sinAlpha; // the bounding sphere's angular radius; 0 under orthographic projection
};

Projection2D project(const Scene& scene, const SceneObject& object) {
    const SceneView view = sceneView(scene);
    const double r = object.radius *
                     std::max({std::abs(object.scale.x), std::abs(object.scale.y), std::abs(object.scale.z)});
    // Pixels per view-space unit on the near plane (perspective) or anywhere (orthographic); the larger
    // of the two axes, so a stretched pixel aspect errs on the fine side.
    const ViewVolume& v = view.volume;
    const double pixelsPerUnit =
        std::max(scene.width / std::abs(v.right - v.left), scene.height / std::abs(v.top - v.bottom));
    if (view.orthographic) return {r * pixelsPerUnit, 0};
    const double distance = glm::length(glm::dvec3(view.viewFromWorld * glm::dvec4(object.center, 1.0)));
    if (distance <= r) return {std::numeric_limits<double>::infinity(), 1};
    const double sinAlpha = r / distance;
    return {v.near * pixelsPerUnit * sinAlpha / std::sqrt(1 - sinAlpha * sinAlpha), sinAlpha};
}

} // namespace

double projectedRadiusPx(const Scene& scene, const SceneObject& object) {
    return project(scene, object).radiusPx;
}

int autoSubdivisionLevel(const Scene& scene, const SceneObject& object) {
    const Projection2D p = project(scene, object);
    if (!std::isfinite(p.radiusPx)) return kMaxSubdivisions;
    // cos²α: the silhouette of a sphere that fills much of the view is seen at a slant, so its radial
    // error shows larger on the image plane.
    const double tolerance = scene.tolerancePx * (1 - p.sinAlpha * p.sinAlpha);
    if (!(p.radiusPx > tolerance)) return 0;
    const double level = std::ceil(1 + 0.5 * std::log2(p.radiusPx / tolerance));
    return int(std::clamp(level, 0.0, double(kMaxSubdivisions)));
}

int subdivisionLevel(const Scene& scene, const SceneObject& object) {
    return object.subdivisions == kAutoSubdivisions ? autoSubdivisionLevel(scene, object)
                                                    : object.subdivisions;
}

double maxRadialDeviation(const SphereMesh& mesh) {
    // Vertices lie on the sphere, so the deepest point of a face is the foot of the perpendicular from the
    // origin when it falls inside the face; otherwise it lies on an edge, whose deepest point is its
    // midpoint (both ends are at radius 1).
    double minDistance = 1;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3& t = mesh.triangles[i];
        const glm::dvec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
        const glm::dvec3 n = mesh.faceNormals[i];
        const glm::dvec3 foot = glm::dot(a, n) * n;
        const bool inside = glm::dot(glm::cross(b - a, foot - a), n) >= 0 &&
                            glm::dot(glm::cross(c - b, foot - b), n) >= 0 &&
                            glm::dot(glm::cross(a - c, foot - c), n) >= 0;
        const double d = inside ? glm::length(foot)
                                : std::min({glm::length((a + b) * 0.5), glm::length((b + c) * 0.5),
                                            glm::length((c + a) * 0.5)});
        minDistance = std::min(minDistance, d);
    }
    return 1 - minDistance;
}

} // namespace shadelab
