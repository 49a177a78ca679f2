// The demo's camera and mouse: the orbit camera, the mouse's orbit and zoom, the right button's light orbit,
// and DemoState::current(), which makes the scene to draw from the edited scene, the orbit and the chosen
// projection.
#include "app/demo/demo_state.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "app/demo/demo_format.h"

namespace shadelab::app {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

// The extent of the scene's objects around the camera target, to keep zooming outside them and inside far.
double sceneExtent(const Scene& scene, const glm::dvec3& target) {
    double extent = 0;
    for (const SceneObject& o : scene.objects) {
        const double r = o.radius * std::max({std::abs(o.scale.x), std::abs(o.scale.y), std::abs(o.scale.z)});
        extent = std::max(extent, glm::length(o.center - target) + r);
    }
    return extent;
}

// `v` turned by the rotation that takes unit `from` to unit `to` (about their common perpendicular).
glm::dvec3 rotateLike(const glm::dvec3& v, const glm::dvec3& from, const glm::dvec3& to) {
    const glm::dvec3 axis = glm::cross(from, to);
    const double sine = glm::length(axis), cosine = glm::dot(from, to);
    if (!(sine > 1e-15)) return v;
    const glm::dvec3 k = axis / sine; // Rodrigues' formula
    return v * cosine + glm::cross(k, v) * sine + k * glm::dot(k, v) * (1 - cosine);
}

} // namespace

OrbitCamera OrbitCamera::looking(const glm::dvec3& eye, const glm::dvec3& target) {
    OrbitCamera camera;
    camera.target = target;
    const glm::dvec3 d = eye - target;
    camera.distance = glm::length(d);
    camera.azimuthRad = std::atan2(d.x, d.z);
    camera.elevationRad = std::clamp(std::asin(std::clamp(d.y / camera.distance, -1.0, 1.0)),
                                     -kMaxElevationRad, kMaxElevationRad);
    return camera;
}

glm::dvec3 OrbitCamera::eye() const {
    const double c = std::cos(elevationRad);
    return target +
           distance * glm::dvec3(c * std::sin(azimuthRad), std::sin(elevationRad), c * std::cos(azimuthRad));
}

void OrbitCamera::drag(double dxPixels, double dyPixels) {
    azimuthRad = std::remainder(azimuthRad - 0.5 * kDegree * dxPixels, 2 * std::numbers::pi);
    elevationRad = std::clamp(elevationRad + 0.5 * kDegree * dyPixels, -kMaxElevationRad, kMaxElevationRad);
}

void OrbitCamera::zoom(double wheelSteps) {
    distance = std::clamp(distance * std::pow(0.9, wheelSteps), 1e-12, 1e12); // finite and non-zero
}

void DemoState::drag(double dxPixels, double dyPixels) {
    if (holdingDivider_) return; // the drag moves the split's divider (pointer())
    drawn_.stale = true;
    if (observed(scene_.view.kind)) { // the observer orbits; the camera keeps its own keys
        Observer& o = scene_.view.observer;
        o.azimuthDeg = std::remainder(o.azimuthDeg - 0.5 * dxPixels, 360.0);
        o.elevationDeg =
            std::clamp(o.elevationDeg + 0.5 * dyPixels, -kMaxObserverElevationDeg, kMaxObserverElevationDeg);
        return;
    }
    camera_.drag(dxPixels, dyPixels);
    cameraMoved_ = true;
}

void DemoState::zoom(double wheelSteps) {
    drawn_.stale = true;
    if (observed(scene_.view.kind)) {
        Observer& o = scene_.view.observer;
        o.zoom = std::clamp(o.zoom * std::pow(0.9, wheelSteps), kMinObserverZoom, kMaxObserverZoom);
        return;
    }
    camera_.zoom(wheelSteps);
    // Clamp the stored distance itself, so the wheel never has to unwind steps it had no effect with.
    // Outside the objects comes first; inside the far plane where both fit.
    const double extent = sceneExtent(scene_, camera_.target);
    const double closest = extent + scene_.projection.near * 1.5;
    // A millionth of the far distance short of it: at exactly far - extent the eye, rebuilt from its angles,
    // can land an ulp beyond, and the object's back would touch the far plane.
    const double farthest = std::max(closest, scene_.projection.far * (1 - 1e-6) - extent);
    camera_.distance = std::clamp(camera_.distance, closest, farthest);
    cameraMoved_ = true;
}

void DemoState::dragLight(double dxPixels, double dyPixels) {
    const auto light = std::find_if(scene_.lights.begin(), scene_.lights.end(),
                                    [](const Light& l) { return l.type != LightType::Ambient; });
    if (light == scene_.lights.end()) {
        lastChange_ = "no light to move (only ambient light)";
        return;
    }
    const std::size_t index = std::size_t(light - scene_.lights.begin());
    drawn_.stale = true;
    const bool positional = light->type != LightType::Directional;
    const glm::dvec3 target = camera_.target;
    const glm::dvec3 offset = positional ? light->position - target : -unitDirection(light->direction);
    if (!(glm::length(offset) > 0)) {
        lastChange_ = "light " + std::to_string(index + 1) + " sits at the target: nothing to orbit";
        return;
    }
    // The camera's orbit, the other way round: dragging right moves the light right on the screen.
    OrbitCamera orbit = OrbitCamera::looking(target + offset, target);
    orbit.drag(-dxPixels, -dyPixels);
    const glm::dvec3 moved = orbit.eye() - target;
    const glm::dvec3 from = glm::normalize(offset), to = glm::normalize(moved);
    if (positional) {
        light->position = target + moved;
        if (light->type == LightType::Spot) light->direction = rotateLike(light->direction, from, to);
        lastChange_ = "light " + std::to_string(index + 1) + " (" + std::string(toString(light->type)) +
                      ") at " + formatVector(light->position);
    } else {
        light->direction = -to;
        lastChange_ = "light " + std::to_string(index + 1) + " (directional) travelling " +
                      formatVector(light->direction);
    }
}

PictureRect fitPicture(int sceneWidth, int sceneHeight, int areaWidth, int areaHeight) {
    if (areaWidth <= 0 || areaHeight <= 0 || sceneWidth <= 0 || sceneHeight <= 0) return {};
    PictureRect rect{0, 0, areaWidth, areaHeight};
    // Compared as products of integers: exact, so an area of the scene's own aspect gets no bar at all.
    if (std::int64_t(areaWidth) * sceneHeight > std::int64_t(areaHeight) * sceneWidth)
        rect.width =
            std::clamp(int(std::lround(double(areaHeight) * sceneWidth / sceneHeight)), 1, areaWidth);
    else
        rect.height =
            std::clamp(int(std::lround(double(areaWidth) * sceneHeight / sceneWidth)), 1, areaHeight);
    rect.x = (areaWidth - rect.width) / 2;
    rect.y = (areaHeight - rect.height) / 2;
    return rect;
}

Scene DemoState::current(int width, int height) const {
    Scene s = scene_;
    if (width > 0 && height > 0) {
        s.width = width;
        s.height = height;
    }
    if (cameraMoved_) {
        s.eye = camera_.eye();
        s.target = camera_.target;
        s.up = {0, 1, 0}; // the orbit's elevation stays short of the poles: never parallel
    }

    // The view volume the scene came with, or the one last edited on the panel (editViewVolume).
    const Projection& own = initial_.projection;
    const double aspect = double(s.width) / s.height;
    const double distance = glm::length(s.eye - s.target);
    // The half-height the view shows at the target: ties the two projections together so O keeps the size.
    const double zoom = distance / volumeDistance_;
    double halfHeight = 0;
    if (own.type == ProjectionType::Orthographic)
        halfHeight = 0.5 * (own.top - own.bottom) * zoom;
    else if (own.type == ProjectionType::Perspective)
        halfHeight = distance * std::tan(0.5 * own.fovyDeg * kDegree);
    else
        halfHeight = distance * 0.5 * (own.top - own.bottom) / own.near;

    if (orthographic_ && own.type != ProjectionType::Orthographic) {
        s.projection = {ProjectionType::Orthographic,
                        own.fovyDeg,
                        -halfHeight * aspect,
                        halfHeight * aspect,
                        -halfHeight,
                        halfHeight,
                        own.near,
                        own.far};
    } else if (orthographic_) {
        // The scene's own box, zoomed, and widened or narrowed by as much as the framebuffer's aspect
        // differs from the scene's (a window of another shape must not stretch the picture).
        const double widening = aspect / (double(scene_.width) / scene_.height);
        const double centreX = 0.5 * (own.left + own.right);
        const double halfWidth = 0.5 * (own.right - own.left) * zoom * widening;
        const double centreY = 0.5 * (own.bottom + own.top) * zoom;
        s.projection.left = centreX * zoom - halfWidth;
        s.projection.right = centreX * zoom + halfWidth;
        s.projection.bottom = centreY - halfHeight;
        s.projection.top = centreY + halfHeight;
    } else if (own.type == ProjectionType::Orthographic) {
        s.projection.type = ProjectionType::Perspective;
        s.projection.fovyDeg = 2 * std::atan(halfHeight / distance) / kDegree;
    }
    return s;
}

} // namespace shadelab::app
