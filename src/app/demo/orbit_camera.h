// The demo's camera: an orbit around the target, moved by the mouse (demo_camera.cpp).
#pragma once

#include <glm/glm.hpp>

namespace shadelab::app {

// Orbits the target on a sphere: azimuth around +y, elevation clamped short of the poles so the camera
// frame (up = +y) is never degenerate.
struct OrbitCamera {
    glm::dvec3 target{0, 0, 0};
    double distance = 4;
    double azimuthRad = 0;   // 0: eye on +z of the target
    double elevationRad = 0; // 0: level with the target; ±kMaxElevation at most

    static constexpr double kMaxElevationRad = 1.5533430342749532; // 89°
    static OrbitCamera looking(const glm::dvec3& eye, const glm::dvec3& target);
    glm::dvec3 eye() const;
    void drag(double dxPixels, double dyPixels); // 0.5° per pixel
    void zoom(double wheelSteps);                // ×0.9 per step in, clamped to a sane range
};

} // namespace shadelab::app
