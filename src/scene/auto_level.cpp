#include "shadelab/scene/auto_level.h"

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

} // namespace shadelab
