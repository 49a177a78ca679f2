#include "shadelab/scene/observer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <tuple>

#include "shadelab/errors.h"
#include "shadelab/scene/camera.h"

namespace shadelab {
namespace {

constexpr double kDegree = std::numbers::pi / 180;
constexpr double kObserverFovyDeg = 40;

// The view volume is the same set of points whichever matrix draws it: the −1 cancels in the divide, and
// reversed-Z only renumbers depth. Its corners come from the standard WebGL matrix (DESIGN §2), whose NDC
// cube is [−1, 1]³.
Scene standardVolume(const Scene& scene) {
    Scene standard = scene;
    standard.depth = DepthMode::Standard;
    standard.perspectiveMatrix = PerspectiveMatrix::WebGl;
    return standard;
}

// Where the objects reach along the view direction, from the eye: the deepest object point's distance.
double objectsReach(const Scene& scene, const CameraFrame& frame) {
    double reach = 0;
    for (const SceneObject& o : scene.objects) {
        const double extent =
            o.radius * std::max({std::abs(o.scale.x), std::abs(o.scale.y), std::abs(o.scale.z)});
        reach = std::max(reach, -glm::dot(o.center - frame.eye, frame.w) + extent);
    }
    return reach;
}

// The points the observer frames: e, the near plane, the volume as deep as the objects reach (and to the
// far plane when that is at most twice as deep), the objects' boxes, the lights' positions; with the
// unnegated matrix, the point reflection of the volume through e too.
std::vector<glm::dvec3> framedPoints(const Scene& scene) {
    const CameraFrame frame = cameraFrame(scene.eye, scene.target, scene.up);
    const auto corners = viewVolumeCornersWorld(scene);
    const double near = scene.projection.near, far = scene.projection.far;
    const double depth = std::max(objectsReach(scene, frame), glm::length(scene.eye - scene.target));
    const double shown = far <= 2 * depth ? far : std::clamp(1.2 * depth, near, far);
    std::vector<glm::dvec3> points{scene.eye};
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::dvec3 nearCorner = corners[i + 4], farCorner = corners[i];
        // Along the edge from near to far, linear in view depth for both projections.
        const glm::dvec3 deep = nearCorner + (farCorner - nearCorner) * ((shown - near) / (far - near));
        points.insert(points.end(), {nearCorner, deep});
    }
    if (leavesOutTheMinusOne(scene)) {
        const std::size_t count = points.size();
        for (std::size_t i = 1; i < count; ++i) points.push_back(2.0 * scene.eye - points[i]);
    }
    for (const SceneObject& o : scene.objects) {
        const glm::dvec3 half = o.radius * glm::abs(o.scale);
        for (int i = 0; i < 8; ++i)
            points.push_back(o.center + glm::dvec3(i & 1 ? half.x : -half.x, i & 2 ? half.y : -half.y,
                                                   i & 4 ? half.z : -half.z));
    }
    for (const Light& light : scene.lights)
        if (light.type == LightType::Point || light.type == LightType::Spot) points.push_back(light.position);
    return points;
}

} // namespace

std::array<glm::dvec3, 8> viewVolumeCornersWorld(const Scene& scene) {
    const SceneView view = sceneView(standardVolume(scene));
    const glm::dmat4 worldFromClip = glm::inverse(view.clipFromView * view.viewFromWorld);
    std::array<glm::dvec3, 8> corners;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 p = worldFromClip * glm::dvec4(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1, 1);
        corners[std::size_t(i)] = glm::dvec3(p) / p.w;
    }
    return corners;
}

// Where an observer stands: `zoom` times the distance at which a sphere of `framedRadius` fits the
// narrower of its two fields of view, away from `centre` in the direction view_observer gives in the axes
// (right, up, back); the plain view, the WebGL matrix and standard depth. The caller sets its depth range.
struct Standpoint {
    Scene observer;
    glm::dvec3 direction;
    double distance;
};
Standpoint standpoint(const Scene& scene, const glm::dvec3& centre, double framedRadius,
                      const glm::dvec3& right, const glm::dvec3& up, const glm::dvec3& back) {
    const Observer& o = scene.view.observer;
    const double azimuth = o.azimuthDeg * kDegree, elevation = o.elevationDeg * kDegree;
    const glm::dvec3 direction =
        std::cos(elevation) * (std::sin(azimuth) * right + std::cos(azimuth) * back) +
        std::sin(elevation) * up;
    const double halfY = 0.5 * kObserverFovyDeg * kDegree;
    const double halfX = std::atan(std::tan(halfY) * scene.width / scene.height);
    const double distance = o.zoom * framedRadius / std::sin(std::min(halfX, halfY));
    Scene observer = scene;
    observer.eye = centre + distance * direction;
    observer.target = centre;
    observer.up = up;
    observer.view = View{};
    observer.perspectiveMatrix = PerspectiveMatrix::WebGl;
    observer.depth = DepthMode::Standard;
    return {observer, direction, distance};
}

Scene observerScene(const Scene& scene) {
    const CameraFrame frame = cameraFrame(scene.eye, scene.target, scene.up);
    const std::vector<glm::dvec3> points = framedPoints(scene);
    glm::dvec3 low = points[0], high = points[0];
    for (const glm::dvec3& p : points) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    const glm::dvec3 centre = 0.5 * (low + high);
    double radius = 0;
    for (const glm::dvec3& p : points) radius = std::max(radius, glm::length(p - centre));

    auto [observer, direction, distance] = standpoint(scene, centre, radius, frame.u, frame.v, frame.w);
    // Depth from just short of the framed sphere (or a thousandth of the distance, zoomed into it) to the
    // real far plane's corners, which are drawn even when not framed, but at most a million near distances:
    // a far plane at 1e6 must not push the near plane past the objects.
    double deepest = distance + radius;
    for (const glm::dvec3& corner : viewVolumeCornersWorld(scene))
        deepest = std::max(deepest, glm::dot(centre - corner, direction) + distance);
    const double near = std::max(distance - 1.05 * radius, distance * 1e-3);
    observer.projection = {ProjectionType::Perspective,         kObserverFovyDeg, -1, 1, -1, 1, near,
                           std::min(1.05 * deepest, 1e6 * near)};
    return observer;
}

void checkOutsideView(const Scene& scene) {
    const View& view = scene.view;
    const bool split = view.kind == ViewKind::Split;
    const bool outside =
        view.kind == ViewKind::Outside ||
        (split && (view.left.view == ViewKind::Outside || view.right.view == ViewKind::Outside));
    if (!outside) return;
    Scene sized = scene; // a split side is half the picture wide, which changes the observer's framing
    if (split) sized.width = std::max(1, scene.width / 2);
    try {
        (void)sceneView(observerScene(sized));
    } catch (const InputError& e) {
        throw InputError("view: the outside view's observer frames the eye, the view volume and every object "
                         "and light, and its own camera leaves 32-bit float range (" +
                         std::string(e.what()) +
                         "); bring the objects and lights nearer the camera, or choose another view");
    }
}

Scene ndcObserverScene(const Scene& scene) {
    const double radius = std::sqrt(3.0); // the cube's circumscribed sphere
    auto [observer, direction, distance] =
        standpoint(scene, {0, 0, 0}, 1.05 * radius, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
    observer.projection = {ProjectionType::Perspective,
                           kObserverFovyDeg,
                           -1,
                           1,
                           -1,
                           1,
                           std::max(distance - 1.1 * radius, distance * 1e-3),
                           distance + 1.1 * radius};
    return observer;
}

} // namespace shadelab
