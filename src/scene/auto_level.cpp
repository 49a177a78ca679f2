#include "shadelab/scene/auto_level.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "shadelab/geometry/sphere.h"
#include "shadelab/geometry/teapot.h"
#include "shadelab/scene/model.h"

namespace shadelab {
namespace {

struct Projection2D {
    double radiusPx; // +infinity with the eye inside the bounding sphere
    double sinAlpha; // the bounding sphere's angular radius; 0 under orthographic projection
};

Projection2D project(const Scene& scene, const SceneObject& object) {
    const SceneView view = sceneView(scene);
    const double r = object.radius * boundingRadius(object) *
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

int sphereLevel(double radiusPx, double tolerancePx) {
    if (!(radiusPx > tolerancePx)) return 0;
    const double level = std::ceil(1 + 0.5 * std::log2(radiusPx / tolerancePx));
    return int(std::clamp(level, 0.0, double(kMaxSubdivisions)));
}

// R_px / B pixels per object unit (along the largest semi-axis, so never fewer than the teapot shows).
int teapotLevel(double radiusPx, double tolerancePx) {
    const double pixelsPerObjectUnit = radiusPx / teapotBoundingRadius();
    for (int level = 0; level < kMaxTeapotLevel; ++level)
        if (teapotMeshError(level) * pixelsPerObjectUnit <= tolerancePx) return level;
    return kMaxTeapotLevel;
}

} // namespace

double teapotBoundingRadius() {
    static const double radius = [] {
        double largest = 0;
        for (const TeapotPatch& patch : teapotPatches())
            for (const glm::dvec3& point : patch) largest = std::max(largest, glm::length(point));
        return largest;
    }();
    return radius;
}

double boundingRadius(const SceneObject& object) {
    switch (object.shape) {
    case Shape::Sphere:
        return 1;
    case Shape::Teapot:
        return teapotBoundingRadius();
    case Shape::Mesh:
        break;
    }
    if (!object.model || object.model->mesh.positions.empty()) return 1;
    double largest = 0;
    for (const glm::dvec3& p : object.model->mesh.positions) largest = std::max(largest, glm::length(p));
    return largest > 0 ? largest : 1;
}

double projectedRadiusPx(const Scene& scene, const SceneObject& object) {
    return project(scene, object).radiusPx;
}

int autoSubdivisionLevel(const Scene& scene, const SceneObject& object) {
    if (object.shape == Shape::Mesh) return 0;
    const int finest = object.shape == Shape::Teapot ? kMaxTeapotLevel : kMaxSubdivisions;
    const Projection2D p = project(scene, object);
    if (!std::isfinite(p.radiusPx)) return finest;
    // cos²α: the silhouette of an object that fills much of the view is seen at a slant, so its error
    // shows larger on the image plane.
    const double tolerance = scene.tolerancePx * (1 - p.sinAlpha * p.sinAlpha);
    return object.shape == Shape::Teapot ? teapotLevel(p.radiusPx, tolerance)
                                         : sphereLevel(p.radiusPx, tolerance);
}

std::size_t triangleCount(const SceneObject& object, int level) {
    switch (object.shape) {
    case Shape::Sphere:
        break;
    case Shape::Teapot:
        return teapotTriangleCount(level);
    case Shape::Mesh:
        return object.model ? object.model->mesh.triangles.size() : 0;
    }
    return sphereTriangleCount(level);
}

int subdivisionLevel(const Scene& scene, const SceneObject& object) {
    if (object.shape == Shape::Mesh) return 0;
    return object.subdivisions == kAutoSubdivisions ? autoSubdivisionLevel(scene, object)
                                                    : object.subdivisions;
}

} // namespace shadelab
