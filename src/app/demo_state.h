// What the demo window shows and how keys and the mouse change it: plain data and pure functions, no GL
// and no GLFW, so the key set is tested on the CPU and the screenshot state is exactly what is drawn.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "shadelab/scene.h"

namespace shadelab::app {

enum class Command {
    Flat, Gouraud, Phong, Toon, ToggleLighting, LevelUp, LevelDown, ToggleProjection, ToggleNormals,
    NextMaterial, NextLights, ResetView, Screenshot, ToggleHelp, TogglePanel, Quit
};

// One spelling of every key, shared by the window, the help overlay, --help and the README table.
struct KeyBinding {
    std::vector<int> keys;  // GLFW key codes (printable keys: their upper-case ASCII code)
    std::string_view label; // how the help text spells the keys, e.g. "1 / F"
    std::string_view action;
    Command command;
};
std::span<const KeyBinding> keyBindings();
std::optional<Command> commandForKey(int key);
std::string keyHelpText(); // one line per binding

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

struct MaterialPreset {
    std::string_view name;
    Material material;
};
struct LightPreset {
    std::string_view name;
    std::vector<Light> lights;
};
std::span<const MaterialPreset> materialPresets(); // matte (k_s = 0), plastic (α = 8), metal (α = 150)
std::span<const LightPreset> lightPresets();       // point, directional, spot, three coloured lights

class DemoState {
public:
    explicit DemoState(Scene scene);

    // The scene to draw: the edited scene with the orbit camera and the chosen projection.
    Scene current() const;
    Scene& scene() { return scene_; } // for the control panel's live edits
    OrbitCamera& camera() { return camera_; }

    // Applies a command; returns false for commands the window handles itself (screenshot, help, quit).
    bool apply(Command command);

    bool matchHighlight = true; // B keeps the highlight size: β = 4α going to Blinn-Phong, α = β/4 back
    bool showHelp = false;
    bool showPanel = true;
    int level() const { return level_; }
    std::string materialName() const;
    std::string lightsName() const;
    std::size_t triangleCount() const;
    bool orthographic() const { return orthographic_; }

private:
    void setLevel(int level);

    Scene initial_, scene_;
    OrbitCamera initialCamera_, camera_;
    int level_ = 0;
    bool orthographic_ = false;
    int material_ = 0; // 0: the scene's own, i: materialPresets()[i − 1]
    int lights_ = 0;   // 0: the scene's own, i: lightPresets()[i − 1]
};

} // namespace shadelab::app
