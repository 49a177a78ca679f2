// What the demo's tests share (tests/app/demo_*_test.cpp, built into one executable, demo_state_test): every
// command, a scene of three different objects, degrees, and a vector as text for a failure's message.
// Each test file's anonymous namespace says `using namespace demo_test;`.
#pragma once

#include <numbers>
#include <sstream>
#include <string>

#include "app/demo/demo_state.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app::demo_test {

inline constexpr double kDeg = std::numbers::pi / 180;

inline constexpr Command kAllCommands[] = {
    Command::Flat,
    Command::Gouraud,
    Command::Phong,
    Command::Toon,
    Command::Exact,
    Command::ToggleLighting,
    Command::LevelUp,
    Command::LevelDown,
    Command::ToggleProjection,
    Command::ToggleNormals,
    Command::ToggleOverlay,
    Command::ToggleShape,
    Command::AutoLevel,
    Command::NextMaterial,
    Command::NextLights,
    Command::ResetView,
    Command::Screenshot,
    Command::ToggleHelp,
    Command::TogglePanel,
    Command::Quit,
    Command::TogglePresentation,
    Command::ToggleFullScreen,
    Command::NextStep,
    Command::PreviousStep,
    Command::FirstStep,
    Command::LastStep,
};

inline std::string str(const glm::dvec3& v) {
    std::ostringstream out;
    out.precision(17);
    out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return out.str();
}

// A Phong-lit scene with three different objects (offsets, an ellipsoid, a mirrored scale, mixed levels).
inline Scene threeObjectScene() {
    Scene scene;
    scene.lighting = LightingModel::Phong;
    scene.eye = {1, 2, 9};
    scene.objects.clear();
    SceneObject a;
    a.material = {{0.1, 0.1, 0.1}, {0.7, 0.2, 0.2}, {1, 1, 1}, 32};
    a.subdivisions = 3;
    SceneObject b;
    b.center = {2.5, 0, 0};
    b.radius = 0.7;
    b.scale = {1, 1.5, -0.5};
    b.material = {{0.2, 0.1, 0.0}, {0.1, 0.6, 0.2}, {0.5, 0.5, 0.5}, 12};
    b.subdivisions = 3;
    SceneObject c;
    c.center = {-2, 1, -1};
    c.radius = 0.5;
    c.material = {{0.0, 0.0, 0.1}, {0.2, 0.2, 0.8}, {0.9, 0.9, 0.9}, 300};
    c.subdivisions = 3;
    scene.objects = {a, b, c};
    Light second = Scene::defaultLight();
    second.position = {-4, 1, 2};
    second.diffuse = {0.3, 0.3, 0.6};
    scene.lights.push_back(second);
    validateScene(scene);
    return scene;
}

} // namespace shadelab::app::demo_test
