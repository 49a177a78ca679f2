#include "app/demo_state.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "shadelab/window.h"

namespace shadelab::app {
namespace {

constexpr double kDegree = std::numbers::pi / 180;
constexpr int kKeyMinus = '-', kKeyEqual = '='; // '+' is Shift + '=' on most layouts

const std::vector<KeyBinding>& bindings() {
    static const std::vector<KeyBinding> kBindings = {
        {{'1', 'F'}, "1 / F", "flat shading", Command::Flat},
        {{'2', 'G'}, "2 / G", "Gouraud shading", Command::Gouraud},
        {{'3', 'P'}, "3 / P", "Phong shading", Command::Phong},
        {{'4', 'T'}, "4 / T", "toon shading", Command::Toon},
        {{'B'}, "B", "Phong <-> Blinn-Phong lighting", Command::ToggleLighting},
        {{kKeyEqual, kKeyKeypadAdd}, "+", "subdivision level up", Command::LevelUp},
        {{kKeyMinus, kKeyKeypadSubtract}, "-", "subdivision level down", Command::LevelDown},
        {{'O'}, "O", "perspective <-> orthographic", Command::ToggleProjection},
        {{'N'}, "N", "averaged <-> exact vertex normals", Command::ToggleNormals},
        {{'M'}, "M", "next material preset", Command::NextMaterial},
        {{'L'}, "L", "next light set-up", Command::NextLights},
        {{'R'}, "R", "reset the view", Command::ResetView},
        {{'S'}, "S", "save a screenshot (PNG + scene JSON)", Command::Screenshot},
        {{'C'}, "C", "show / hide the control panel", Command::TogglePanel},
        {{'H', kKeyF1}, "H / F1", "show / hide this help", Command::ToggleHelp},
        {{kKeyEscape}, "Esc", "quit", Command::Quit},
    };
    return kBindings;
}

Light pointLight(glm::dvec3 position, glm::dvec3 color) {
    Light light;
    light.position = position;
    light.ambient = {0.1, 0.1, 0.1};
    light.diffuse = light.specular = color;
    return light;
}

// The extent of the scene's objects around the camera target, to keep zooming outside them and inside far.
double sceneExtent(const Scene& scene, const glm::dvec3& target) {
    double extent = 0;
    for (const SceneObject& o : scene.objects) {
        const double r = o.radius * std::max({std::abs(o.scale.x), std::abs(o.scale.y), std::abs(o.scale.z)});
        extent = std::max(extent, glm::length(o.center - target) + r);
    }
    return extent;
}

} // namespace

std::span<const KeyBinding> keyBindings() { return bindings(); }

std::optional<Command> commandForKey(int key) {
    for (const KeyBinding& binding : bindings())
        if (std::find(binding.keys.begin(), binding.keys.end(), key) != binding.keys.end()) return binding.command;
    return std::nullopt;
}

std::string keyHelpText() {
    std::string text;
    for (const KeyBinding& b : bindings()) {
        std::string label(b.label);
        label.resize(std::max<std::size_t>(label.size(), 8), ' ');
        text += label + " " + std::string(b.action) + "\n";
    }
    text += "drag    orbit around the target\nwheel   zoom\n";
    return text;
}

OrbitCamera OrbitCamera::looking(const glm::dvec3& eye, const glm::dvec3& target) {
    OrbitCamera camera;
    camera.target = target;
    const glm::dvec3 d = eye - target;
    camera.distance = glm::length(d);
    camera.azimuthRad = std::atan2(d.x, d.z);
    camera.elevationRad =
        std::clamp(std::asin(std::clamp(d.y / camera.distance, -1.0, 1.0)), -kMaxElevationRad, kMaxElevationRad);
    return camera;
}

glm::dvec3 OrbitCamera::eye() const {
    const double c = std::cos(elevationRad);
    return target + distance * glm::dvec3(c * std::sin(azimuthRad), std::sin(elevationRad), c * std::cos(azimuthRad));
}

void OrbitCamera::drag(double dxPixels, double dyPixels) {
    azimuthRad = std::remainder(azimuthRad - 0.5 * kDegree * dxPixels, 2 * std::numbers::pi);
    elevationRad = std::clamp(elevationRad + 0.5 * kDegree * dyPixels, -kMaxElevationRad, kMaxElevationRad);
}

void OrbitCamera::zoom(double wheelSteps) { distance *= std::pow(0.9, wheelSteps); }

std::span<const MaterialPreset> materialPresets() {
    static const MaterialPreset kPresets[] = {
        {"matte", {{0.1, 0.1, 0.1}, {0.2, 0.55, 0.25}, {0, 0, 0}, 1}},
        {"plastic", {{0.1, 0.1, 0.1}, {0.15, 0.3, 0.75}, {0.8, 0.8, 0.8}, 8}},
        {"metal", {{0.12, 0.1, 0.05}, {0.35, 0.28, 0.12}, {0.95, 0.8, 0.45}, 150}},
    };
    return kPresets;
}

std::span<const LightPreset> lightPresets() {
    static const std::vector<LightPreset> kPresets = [] {
        Light directional;
        directional.type = LightType::Directional;
        directional.direction = {-1, -1, -1.5};
        directional.ambient = {0.1, 0.1, 0.1};
        Light spot = pointLight({1.5, 1.5, 3}, {1, 1, 1});
        spot.type = LightType::Spot;
        spot.direction = {-1.5, -1.5, -3};
        spot.cutoffDeg = 18;
        spot.exponent = 10;
        return std::vector<LightPreset>{
            {"point", {pointLight({3, 3, 5}, {1, 1, 1})}},
            {"directional", {directional}},
            {"spot", {spot}},
            {"three coloured", {pointLight({3, 2, 4}, {0.9, 0.3, 0.3}), pointLight({-3, 2, 4}, {0.3, 0.9, 0.3}),
                                pointLight({0, -3, 4}, {0.3, 0.4, 1.0})}},
        };
    }();
    return kPresets;
}

DemoState::DemoState(Scene scene)
    : initial_(scene), scene_(std::move(scene)), initialCamera_(OrbitCamera::looking(scene_.eye, scene_.target)),
      camera_(initialCamera_), level_(scene_.objects.empty() ? 5 : scene_.objects[0].subdivisions),
      orthographic_(scene_.projection.type == ProjectionType::Orthographic) {}

Scene DemoState::current() const {
    Scene s = scene_;
    OrbitCamera camera = camera_;
    // Stay outside the objects and inside the far plane, whatever the wheel said.
    const double extent = sceneExtent(s, camera.target);
    const double closest = extent + s.projection.near * 1.5, farthest = s.projection.far - extent;
    camera.distance = farthest > closest ? std::clamp(camera.distance, closest, farthest) : camera.distance;
    s.eye = camera.eye();
    s.target = camera.target;
    s.up = {0, 1, 0};

    const Projection& own = initial_.projection;
    const double aspect = double(s.width) / s.height;
    // The half-height the view shows at the target: ties the two projections together so O keeps the size.
    const double zoom = camera.distance / initialCamera_.distance;
    double halfHeight = 0;
    if (own.type == ProjectionType::Orthographic)
        halfHeight = 0.5 * (own.top - own.bottom) * zoom;
    else if (own.type == ProjectionType::Perspective)
        halfHeight = camera.distance * std::tan(0.5 * own.fovyDeg * kDegree);
    else
        halfHeight = camera.distance * 0.5 * (own.top - own.bottom) / own.near;

    if (orthographic_ && own.type != ProjectionType::Orthographic) {
        s.projection = {ProjectionType::Orthographic, own.fovyDeg, -halfHeight * aspect, halfHeight * aspect,
                        -halfHeight, halfHeight, own.near, own.far};
    } else if (orthographic_) {
        s.projection.left = own.left * zoom;
        s.projection.right = own.right * zoom;
        s.projection.bottom = own.bottom * zoom;
        s.projection.top = own.top * zoom;
    } else if (own.type == ProjectionType::Orthographic) {
        s.projection.type = ProjectionType::Perspective;
        s.projection.fovyDeg = 2 * std::atan(halfHeight / camera.distance) / kDegree;
    }
    return s;
}

bool DemoState::apply(Command command) {
    switch (command) {
    case Command::Flat: scene_.shading = ShadingMode::Flat; break;
    case Command::Gouraud: scene_.shading = ShadingMode::Gouraud; break;
    case Command::Phong: scene_.shading = ShadingMode::Phong; break;
    case Command::Toon: scene_.shading = ShadingMode::Toon; break;
    case Command::ToggleLighting: {
        const bool toBlinn = scene_.lighting == LightingModel::Phong;
        scene_.lighting = toBlinn ? LightingModel::BlinnPhong : LightingModel::Phong;
        if (matchHighlight) // the half-vector angle is half the reflection angle: β ≈ 4α (DESIGN §3)
            for (SceneObject& o : scene_.objects)
                o.material.shininess = std::max(1.0, toBlinn ? o.material.shininess * 4 : o.material.shininess / 4);
        break;
    }
    case Command::LevelUp: setLevel(level_ + 1); break;
    case Command::LevelDown: setLevel(level_ - 1); break;
    case Command::ToggleProjection: orthographic_ = !orthographic_; break;
    case Command::ToggleNormals:
        scene_.vertexNormals =
            scene_.vertexNormals == VertexNormals::Averaged ? VertexNormals::Exact : VertexNormals::Averaged;
        break;
    case Command::NextMaterial:
        material_ = (material_ + 1) % int(materialPresets().size() + 1);
        for (std::size_t i = 0; i < scene_.objects.size(); ++i)
            scene_.objects[i].material =
                material_ == 0 ? initial_.objects[i].material : materialPresets()[std::size_t(material_ - 1)].material;
        break;
    case Command::NextLights:
        lights_ = (lights_ + 1) % int(lightPresets().size() + 1);
        scene_.lights = lights_ == 0 ? initial_.lights : lightPresets()[std::size_t(lights_ - 1)].lights;
        break;
    case Command::ResetView: camera_ = initialCamera_; break;
    case Command::TogglePanel: showPanel = !showPanel; break;
    case Command::ToggleHelp: showHelp = !showHelp; break;
    case Command::Screenshot:
    case Command::Quit: return false;
    }
    return true;
}

void DemoState::setLevel(int level) {
    level_ = std::clamp(level, 0, kMaxSubdivisions);
    for (SceneObject& o : scene_.objects) o.subdivisions = level_;
}

std::string DemoState::materialName() const {
    return material_ == 0 ? "scene's own" : std::string(materialPresets()[std::size_t(material_ - 1)].name);
}

std::string DemoState::lightsName() const {
    return lights_ == 0 ? "scene's own" : std::string(lightPresets()[std::size_t(lights_ - 1)].name);
}

std::size_t DemoState::triangleCount() const {
    std::size_t total = 0;
    for (const SceneObject& o : scene_.objects) total += sphereTriangleCount(o.subdivisions);
    return total;
}

} // namespace shadelab::app
