// The demo's pure logic (src/app/demo/demo_state.h) against README "The demo window" and DESIGN §2–§3: the
// key table, the orbit camera, the material and light presets and DemoState::apply/current. Expected values
// come from the issue, DESIGN and GLFW's key codes, not from demo_state.cpp.
#include "app/demo/demo_state.h"
#include "app/demo/matrices_text.h"
#include "app/demo/scene_flags.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h> // only for the GLFW_KEY_* constants: the window reports GLFW key codes
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "shadelab/context/window.h"
#include "shadelab/errors.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/geometry/subdivision.h"
#include "shadelab/scene/camera.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_values.h"

namespace shadelab::app {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

constexpr Command kAllCommands[] = {
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

std::string str(const glm::dvec3& v) {
    std::ostringstream out;
    out.precision(17);
    out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return out.str();
}

template <int C, int R> bool allFinite(const glm::mat<C, R, double>& m) {
    for (int c = 0; c < C; ++c)
        for (int r = 0; r < R; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

double maxAbsDifference(const glm::dmat4& a, const glm::dmat4& b) {
    double worst = 0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) worst = std::max(worst, std::abs(a[c][r] - b[c][r]));
    return worst;
}

bool sameMaterial(const Material& a, const Material& b) {
    return a.ambient == b.ambient && a.diffuse == b.diffuse && a.specular == b.specular &&
           a.shininess == b.shininess;
}

bool sameLight(const Light& a, const Light& b) {
    return a.type == b.type && a.ambient == b.ambient && a.diffuse == b.diffuse && a.specular == b.specular &&
           a.position == b.position && a.direction == b.direction && a.cutoffDeg == b.cutoffDeg &&
           a.exponent == b.exponent && a.attenuation == b.attenuation;
}

bool sameLights(const std::vector<Light>& a, const std::vector<Light>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!sameLight(a[i], b[i])) return false;
    return true;
}

bool sameProjection(const Projection& a, const Projection& b) {
    return a.type == b.type && a.fovyDeg == b.fovyDeg && a.left == b.left && a.right == b.right &&
           a.bottom == b.bottom && a.top == b.top && a.near == b.near && a.far == b.far;
}

double boundingRadius(const SceneObject& o) {
    return o.radius * std::max({std::abs(o.scale.x), std::abs(o.scale.y), std::abs(o.scale.z)});
}

// A Phong-lit scene with three different objects (offsets, an ellipsoid, a mirrored scale, mixed levels).
Scene threeObjectScene() {
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

Scene phongScene() {
    Scene scene;
    scene.lighting = LightingModel::Phong;
    return scene;
}

glm::dvec3 ndc(const SceneView& view, const glm::dvec3& world) {
    const glm::dvec4 clip = view.clipFromView * view.viewFromWorld * glm::dvec4(world, 1);
    return glm::dvec3(clip) / clip.w;
}

// The vertical NDC distance from the projected centre of a sphere to its silhouette, computed from the
// geometry: under perspective the silhouette point is where a ray from the eye grazes the sphere.
double projectedRadiusNdc(const Scene& scene, const glm::dvec3& centre, double radius) {
    const SceneView view = sceneView(scene);
    const CameraFrame frame = cameraFrame(scene.eye, scene.target, scene.up);
    glm::dvec3 silhouette;
    if (view.orthographic) {
        silhouette = centre + radius * frame.v;
    } else {
        const glm::dvec3 toCentre = centre - scene.eye;
        const double d = glm::length(toCentre);
        const double sinB = radius / d, cosB = std::sqrt(1 - sinB * sinB);
        const glm::dvec3 forward = toCentre / d;
        const glm::dvec3 up = glm::normalize(frame.v - glm::dot(frame.v, forward) * forward);
        silhouette = scene.eye + std::sqrt(d * d - radius * radius) * (cosB * forward + sinB * up);
    }
    return std::abs(ndc(view, silhouette).y - ndc(view, centre).y);
}

// ---- keys ----

// The key codes GLFW reports, and the command README's key table gives each.
const std::vector<std::pair<int, Command>>& issueKeys() {
    static const std::vector<std::pair<int, Command>> kKeys = {
        {GLFW_KEY_1, Command::Flat},
        {GLFW_KEY_F, Command::Flat},
        {GLFW_KEY_2, Command::Gouraud},
        {GLFW_KEY_G, Command::Gouraud},
        {GLFW_KEY_3, Command::Phong},
        {GLFW_KEY_P, Command::Phong},
        {GLFW_KEY_4, Command::Toon},
        {GLFW_KEY_T, Command::Toon},
        {GLFW_KEY_5, Command::Exact},
        {GLFW_KEY_X, Command::Exact},
        {GLFW_KEY_B, Command::ToggleLighting},
        {GLFW_KEY_EQUAL, Command::LevelUp}, // '+' is Shift + '=' (US layout); GLFW reports the key, '='
        {GLFW_KEY_KP_ADD, Command::LevelUp},
        {GLFW_KEY_MINUS, Command::LevelDown},
        {GLFW_KEY_KP_SUBTRACT, Command::LevelDown},
        {GLFW_KEY_O, Command::ToggleProjection},
        {GLFW_KEY_N, Command::ToggleNormals},
        {GLFW_KEY_M, Command::NextMaterial},
        {GLFW_KEY_L, Command::NextLights},
        {GLFW_KEY_R, Command::ResetView},
        {GLFW_KEY_S, Command::Screenshot},
        {GLFW_KEY_H, Command::ToggleHelp},
        {GLFW_KEY_F1, Command::ToggleHelp},
        {GLFW_KEY_ESCAPE, Command::Quit},
        {GLFW_KEY_C, Command::TogglePanel},
        {GLFW_KEY_F2, Command::TogglePresentation}, // Presentation mode
        {GLFW_KEY_W, Command::ToggleOverlay},       // wireframe and normals overlay
        {GLFW_KEY_F11, Command::ToggleFullScreen},
        // A lesson's steps.
        {GLFW_KEY_PAGE_DOWN, Command::NextStep},
        {GLFW_KEY_SPACE, Command::NextStep},
        {GLFW_KEY_RIGHT, Command::NextStep},
        {GLFW_KEY_PAGE_UP, Command::PreviousStep},
        {GLFW_KEY_BACKSPACE, Command::PreviousStep},
        {GLFW_KEY_LEFT, Command::PreviousStep},
        {GLFW_KEY_HOME, Command::FirstStep},
        {GLFW_KEY_END, Command::LastStep},
    };
    return kKeys;
}

TEST(DemoKeys, WindowKeyConstantsAreGlfwKeyCodes) {
    EXPECT_EQ(kKeyEscape, GLFW_KEY_ESCAPE);
    EXPECT_EQ(kKeyF1, GLFW_KEY_F1);
    EXPECT_EQ(kKeyF2, GLFW_KEY_F2);
    EXPECT_EQ(kKeyF11, GLFW_KEY_F11);
    EXPECT_EQ(kKeyKeypadSubtract, GLFW_KEY_KP_SUBTRACT);
    EXPECT_EQ(kKeyKeypadAdd, GLFW_KEY_KP_ADD);
    EXPECT_EQ(kKeyPageDown, GLFW_KEY_PAGE_DOWN);
    EXPECT_EQ(kKeyEnd, GLFW_KEY_END);
}

// A lesson's step keys move through it, each step as written with the window's own settings kept;
// a key works inside a step, and R returns to the step as written (not only its camera).
TEST(DemoLesson, StepKeysMoveThroughTheStepsAndRReturnsToTheStep) {
    auto lesson = std::make_shared<Lesson>();
    lesson->title = "Two steps";
    Scene first, second;
    first.shading = ShadingMode::Flat;
    second.shading = ShadingMode::Toon;
    second.lighting = LightingModel::Phong;
    second.objects[0].subdivisions = 2;
    lesson->steps = {{"One", "the first", "", first, "", {}}, {"Two", "", "", second, "", {}}};
    DemoState state(Scene{});
    EXPECT_TRUE(state.apply(Command::NextStep));
    EXPECT_NE(state.lastChange().find("no lesson open"), std::string::npos) << state.lastChange();
    state.presenting = true;
    state.showPanel = false;
    state.openLesson(lesson);
    EXPECT_EQ(state.step(), 0u);
    EXPECT_EQ(state.scene().shading, ShadingMode::Flat);
    EXPECT_NE(windowTitle(state, 0).find("shadelab — step 1 of 2 | flat shading"), std::string::npos)
        << windowTitle(state, 0);
    state.apply(Command::PreviousStep);
    EXPECT_EQ(state.step(), 0u);
    EXPECT_EQ(state.lastChange(), "already at the first step");
    state.apply(Command::NextStep);
    EXPECT_EQ(state.step(), 1u);
    EXPECT_EQ(state.lastChange(), "step 2 of 2: Two");
    EXPECT_EQ(state.scene().shading, ShadingMode::Toon);
    EXPECT_EQ(state.level(), 2);
    EXPECT_TRUE(state.presenting) << "the window's settings are kept";
    EXPECT_FALSE(state.showPanel);
    // Inside the step: keys and the mouse change it; R gives the step back as written.
    state.apply(Command::Phong);
    state.apply(Command::LevelUp);
    state.apply(Command::NextMaterial);
    state.drag(40, 10);
    EXPECT_EQ(state.scene().shading, ShadingMode::Phong);
    state.apply(Command::ResetView);
    EXPECT_EQ(state.scene().shading, ShadingMode::Toon);
    EXPECT_EQ(state.level(), 2);
    EXPECT_EQ(state.materialName(), DemoState(second).materialName());
    EXPECT_EQ(state.drawn().eye, DemoState(second).drawn().eye) << "the camera too";
    state.apply(Command::FirstStep);
    EXPECT_EQ(state.step(), 0u);
    state.apply(Command::LastStep);
    EXPECT_EQ(state.step(), 1u);
    state.apply(Command::NextStep);
    EXPECT_EQ(state.lastChange(), "already at the last step");
}

TEST(DemoKeys, EveryKeyTheIssueListsMapsToItsCommand) {
    for (const auto& [key, command] : issueKeys()) {
        const auto got = commandForKey(key);
        ASSERT_TRUE(got.has_value()) << "key code " << key << " is not bound";
        EXPECT_EQ(*got, command) << "key code " << key;
    }
}

TEST(DemoKeys, EveryBindingsKeysMapToItsCommand) {
    ASSERT_FALSE(keyBindings().empty());
    for (const KeyBinding& binding : keyBindings()) {
        EXPECT_FALSE(binding.keys.empty()) << binding.label;
        for (int key : binding.keys) {
            const auto got = commandForKey(key);
            ASSERT_TRUE(got.has_value()) << binding.label << ": key " << key;
            EXPECT_EQ(*got, binding.command) << binding.label << ": key " << key;
        }
    }
}

TEST(DemoKeys, NoKeyIsBoundTwice) {
    std::map<int, std::string> seen;
    for (const KeyBinding& binding : keyBindings())
        for (int key : binding.keys) {
            const auto [it, inserted] = seen.emplace(key, std::string(binding.label));
            EXPECT_TRUE(inserted) << "key " << key << " is bound by both '" << it->second << "' and '"
                                  << binding.label << "'";
        }
}

TEST(DemoKeys, EveryCommandHasExactlyOneBinding) {
    for (Command command : kAllCommands) {
        const auto count = std::count_if(keyBindings().begin(), keyBindings().end(),
                                         [&](const KeyBinding& b) { return b.command == command; });
        EXPECT_EQ(count, 1) << "command " << int(command);
    }
}

TEST(DemoKeys, UnboundKeysGiveNoCommand) {
    for (int key : {GLFW_KEY_Z, GLFW_KEY_D, GLFW_KEY_6, GLFW_KEY_F3, GLFW_KEY_ENTER, GLFW_KEY_UNKNOWN, 0})
        EXPECT_FALSE(commandForKey(key).has_value()) << "key " << key;
}

TEST(DemoKeys, HelpTextListsEveryBindingsLabelAndActionOnOneLine) {
    const std::string help = keyHelpText();
    std::vector<std::string> lines;
    std::istringstream in(help);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    for (const KeyBinding& binding : keyBindings()) {
        ASSERT_FALSE(binding.label.empty());
        ASSERT_FALSE(binding.action.empty());
        const bool found = std::any_of(lines.begin(), lines.end(), [&](const std::string& line) {
            return line.find(binding.label) != std::string::npos &&
                   line.find(binding.action) != std::string::npos;
        });
        EXPECT_TRUE(found) << "no help line has both '" << binding.label << "' and '" << binding.action
                           << "':\n"
                           << help;
    }
    // The mouse is part of "every key in the window" too.
    EXPECT_NE(help.find("drag"), std::string::npos) << help;
    EXPECT_NE(help.find("wheel"), std::string::npos) << help;
}

TEST(DemoKeys, HelpLabelsNameTheIssuesKeys) {
    // The labels are what the overlay, --help and the README show: each listed key appears in some label.
    std::string labels;
    for (const KeyBinding& binding : keyBindings()) labels += std::string(binding.label) + " | ";
    for (const char* key : {"1", "2", "3", "4", "F", "G", "P",  "T",   "B", "+",  "-",  "O",
                            "N", "M", "L", "R", "S", "H", "F1", "Esc", "C", "F2", "F11"})
        EXPECT_NE(labels.find(key), std::string::npos) << key << " not in labels: " << labels;
}

// ---- apply(): modes and toggles ----

TEST(DemoApply, DigitsSetTheShadingModes) {
    DemoState state(Scene{});
    const std::pair<Command, ShadingMode> cases[] = {
        {Command::Flat, ShadingMode::Flat},       {Command::Toon, ShadingMode::Toon},
        {Command::Gouraud, ShadingMode::Gouraud}, {Command::Phong, ShadingMode::Phong},
        {Command::Exact, ShadingMode::Exact},     {Command::Flat, ShadingMode::Flat}};
    for (const auto& [command, mode] : cases) {
        EXPECT_TRUE(state.apply(command));
        EXPECT_EQ(state.current().shading, mode);
        EXPECT_EQ(state.current().lighting, LightingModel::BlinnPhong)
            << "a shading key changed the lighting";
    }
    for (const auto& [key, command] : issueKeys()) {
        if (command != Command::Gouraud) continue;
        state.apply(*commandForKey(key));
        EXPECT_EQ(state.current().shading, ShadingMode::Gouraud);
    }
}

TEST(DemoApply, WindowCommandsReturnFalseAndChangeNothing) {
    DemoState state(threeObjectScene());
    const std::string before = sceneToJson(state.current());
    EXPECT_FALSE(state.apply(Command::Screenshot));
    EXPECT_FALSE(state.apply(Command::Quit));
    EXPECT_EQ(sceneToJson(state.current()), before);
}

TEST(DemoApply, HelpAndPanelToggle) {
    DemoState state(Scene{});
    const bool help = state.showHelp, panel = state.showPanel;
    state.apply(Command::ToggleHelp);
    state.apply(Command::TogglePanel);
    EXPECT_NE(state.showHelp, help);
    EXPECT_NE(state.showPanel, panel);
    state.apply(Command::ToggleHelp);
    state.apply(Command::TogglePanel);
    EXPECT_EQ(state.showHelp, help);
    EXPECT_EQ(state.showPanel, panel);
}

TEST(DemoApply, NTogglesVertexNormals) {
    DemoState state(Scene{});
    EXPECT_EQ(state.current().vertexNormals, VertexNormals::Averaged); // DESIGN §1: averaged is the default
    EXPECT_TRUE(state.apply(Command::ToggleNormals));
    EXPECT_EQ(state.current().vertexNormals, VertexNormals::Exact);
    state.apply(Command::ToggleNormals);
    EXPECT_EQ(state.current().vertexNormals, VertexNormals::Averaged);
}

// ---- B: Phong <-> Blinn-Phong, β = 4α (DESIGN §3) ----

TEST(DemoLighting, BFromPhongMultipliesEveryShininessByFourAndBackDivides) {
    const Scene scene = threeObjectScene(); // Phong lighting; shininess 32, 12, 300
    DemoState state(scene);
    ASSERT_TRUE(state.matchHighlight) << "the issue: the matching is on by default in the demo";
    EXPECT_TRUE(state.apply(Command::ToggleLighting));
    Scene s = state.current();
    EXPECT_EQ(s.lighting, LightingModel::BlinnPhong);
    for (std::size_t i = 0; i < s.objects.size(); ++i)
        EXPECT_DOUBLE_EQ(s.objects[i].material.shininess, 4 * scene.objects[i].material.shininess) << i;
    state.apply(Command::ToggleLighting);
    s = state.current();
    EXPECT_EQ(s.lighting, LightingModel::Phong);
    for (std::size_t i = 0; i < s.objects.size(); ++i)
        EXPECT_EQ(s.objects[i].material.shininess, scene.objects[i].material.shininess) << i;
}

TEST(DemoLighting, BFromBlinnPhongDividesByFour) {
    Scene scene; // blinn-phong, β = 32
    DemoState state(scene);
    state.apply(Command::ToggleLighting);
    EXPECT_EQ(state.current().lighting, LightingModel::Phong);
    EXPECT_DOUBLE_EQ(state.current().objects[0].material.shininess, 8);
}

TEST(DemoLighting, BWithoutMatchingLeavesShininessAlone) {
    const Scene scene = threeObjectScene();
    DemoState state(scene);
    state.matchHighlight = false;
    for (LightingModel expected :
         {LightingModel::BlinnPhong, LightingModel::Phong, LightingModel::BlinnPhong}) {
        state.apply(Command::ToggleLighting);
        const Scene s = state.current();
        EXPECT_EQ(s.lighting, expected);
        for (std::size_t i = 0; i < s.objects.size(); ++i)
            EXPECT_EQ(s.objects[i].material.shininess, scene.objects[i].material.shininess);
    }
}

TEST(DemoLighting, ShininessNeverGoesBelowOne) {
    for (double shininess : {1.0, 1.5, 2.0, 3.0, 3.99}) {
        Scene scene; // blinn-phong: B divides
        scene.objects[0].material.shininess = shininess;
        DemoState state(scene);
        state.apply(Command::ToggleLighting);
        EXPECT_GE(state.current().objects[0].material.shininess, 1) << "from β = " << shininess;
        EXPECT_NO_THROW(validateScene(state.current()));
    }
}

// Pressing B twice gives back the scene: from either model, for every valid shininess (>= 1).
TEST(DemoLighting, BTwiceRestoresTheOriginalShininess) {
    for (LightingModel start : kLightingModels)
        for (double shininess : {1.0, 2.0, 3.0, 4.0, 5.0, 8.0, 32.0, 100.0, 1000.0}) {
            Scene scene;
            scene.lighting = start;
            scene.objects[0].material.shininess = shininess;
            DemoState state(scene);
            state.apply(Command::ToggleLighting);
            state.apply(Command::ToggleLighting);
            EXPECT_EQ(state.current().lighting, start);
            EXPECT_EQ(state.current().objects[0].material.shininess, shininess)
                << "B twice from " << toString(start) << " with shininess " << shininess << " gave "
                << state.current().objects[0].material.shininess;
        }
}

// ---- +/-: subdivision level ----

TEST(DemoLevel, PlusAndMinusChangeEveryObjectAndClampAtBothEnds) {
    Scene scene = threeObjectScene(); // all at level 3
    DemoState state(scene);
    EXPECT_EQ(state.level(), 3);
    EXPECT_TRUE(state.apply(Command::LevelUp));
    for (const SceneObject& o : state.current().objects) EXPECT_EQ(o.subdivisions, 4);
    EXPECT_EQ(state.level(), 4);
    for (int i = 0; i < 3 * kMaxSubdivisions; ++i) state.apply(Command::LevelUp);
    EXPECT_EQ(state.level(), kMaxSubdivisions);
    for (const SceneObject& o : state.current().objects) EXPECT_EQ(o.subdivisions, kMaxSubdivisions);
    EXPECT_NO_THROW(validateScene(state.current()));
    for (int i = 0; i < 3 * kMaxSubdivisions; ++i) state.apply(Command::LevelDown);
    EXPECT_EQ(state.level(), 0);
    for (const SceneObject& o : state.current().objects) EXPECT_EQ(o.subdivisions, 0);
    EXPECT_NO_THROW(validateScene(state.current()));
    state.apply(Command::LevelUp);
    EXPECT_EQ(state.level(), 1) << "level down below 0 must not be remembered";
}

// "+" is "level up": it must not lower any object's level. With objects at different levels each goes
// one up (clamped), keeping the scene's relative detail.
TEST(DemoLevel, PlusNeverLowersAnObjectsLevel) {
    Scene scene = threeObjectScene();
    scene.objects[0].subdivisions = 2;
    scene.objects[1].subdivisions = 6;
    scene.objects[2].subdivisions = 4;
    DemoState state(scene);
    state.apply(Command::LevelUp);
    const Scene s = state.current();
    for (std::size_t i = 0; i < s.objects.size(); ++i)
        EXPECT_EQ(s.objects[i].subdivisions, scene.objects[i].subdivisions + 1)
            << "object " << i << " was at level " << scene.objects[i].subdivisions;
}

// The title's level is the drawn one. "auto" chooses by the projected size, so after the window
// grows from the scene's 256×256 to 1000×800 the drawn level is higher; the title, the triangle count and
// "+" follow the drawn size, not the scene's image size. A again leaves auto at the level shown.
TEST(DemoLevel, AutoLevelAndTitleFollowTheDrawnSize) {
    Scene scene; // the DESIGN §4 defaults: one unit sphere
    scene.width = scene.height = 256;
    DemoState state(scene);
    state.apply(Command::AutoLevel);
    const int atImageSize = subdivisionLevel(state.current(256, 256), state.current().objects[0]);
    state.setViewport(1000, 800);
    const int drawnLevel = subdivisionLevel(state.current(1000, 800), state.current().objects[0]);
    ASSERT_GT(drawnLevel, atImageSize) << "the test needs a size at which auto chooses another level";
    EXPECT_EQ(state.level(), drawnLevel);
    EXPECT_EQ(state.triangleCount(), sphereTriangleCount(drawnLevel));
    EXPECT_NE(windowTitle(state, 0).find("level " + std::to_string(drawnLevel) + " (auto)"),
              std::string::npos)
        << windowTitle(state, 0);
    EXPECT_NE(statusText(state).find("level " + std::to_string(drawnLevel)), std::string::npos);

    state.apply(Command::AutoLevel); // leaves auto where it was
    EXPECT_FALSE(state.autoLevel());
    EXPECT_EQ(state.level(), drawnLevel);
    EXPECT_EQ(state.current().objects[0].subdivisions, drawnLevel);
    state.apply(Command::AutoLevel);
    EXPECT_TRUE(state.autoLevel()) << "A toggles";
    state.apply(Command::LevelUp);
    EXPECT_EQ(state.level(), drawnLevel + 1) << "+ from auto is one above the level shown";
}

// With the panel hidden, what O, N, M, L (and the other keys) changed is in the title's end.
TEST(DemoTitle, SaysWhatTheLastKeyChanged) {
    DemoState state{Scene{}};
    EXPECT_EQ(windowTitle(state, 0).find("| H: keys |"), std::string::npos) << "nothing changed yet";
    const std::pair<Command, const char*> steps[] = {{Command::ToggleProjection, "orthographic projection"},
                                                     {Command::ToggleProjection, "perspective projection"},
                                                     {Command::ToggleNormals, "exact vertex normals"},
                                                     {Command::ToggleNormals, "averaged vertex normals"},
                                                     {Command::NextMaterial, "material: matte"},
                                                     {Command::NextLights, "lights: point"},
                                                     {Command::ToggleOverlay, "overlay: wireframe"},
                                                     {Command::Flat, "flat shading"},
                                                     {Command::Exact, "exact shading"},
                                                     {Command::ResetView, "view reset"}};
    for (const auto& [command, words] : steps) {
        state.apply(command);
        const std::string title = windowTitle(state, 0);
        EXPECT_TRUE(title.ends_with(std::string("| H: keys | ") + words)) << title;
    }
}

// Presentation mode: F2 toggles the large label; it names the mode, the lighting model, the
// drawn level and the exponent by its model's letter. F11 (full screen) is the window's to carry out.
TEST(DemoPresentation, LabelNamesModeLightingLevelAndExponent) {
    Scene scene;
    scene.objects[0].material.shininess = 32;
    DemoState state(scene);
    EXPECT_FALSE(state.presenting);
    EXPECT_TRUE(state.apply(Command::TogglePresentation));
    EXPECT_TRUE(state.presenting);
    EXPECT_EQ(presentationLabel(state), "PHONG SHADING\nBLINN-PHONG LIGHTING\nLEVEL 5 | BETA = 32");
    state.apply(Command::Gouraud);
    state.matchHighlight = false;
    state.apply(Command::ToggleLighting);
    state.apply(Command::LevelDown);
    EXPECT_EQ(presentationLabel(state), "GOURAUD SHADING\nPHONG LIGHTING\nLEVEL 4 | ALPHA = 32");
    EXPECT_FALSE(state.apply(Command::ToggleFullScreen)) << "the window's to carry out";
    state.apply(Command::TogglePresentation);
    EXPECT_FALSE(state.presenting);
}

TEST(DemoLevel, TriangleCountIsFourToTheLevelPlusOnePerObject) {
    auto expected = [](const Scene& s) {
        std::size_t total = 0;
        for (const SceneObject& o : s.objects)
            total += std::size_t(1) << (2 * (o.subdivisions + 1)); // 4^(n+1)
        return total;
    };
    Scene scene = threeObjectScene();
    scene.objects[1].subdivisions = 5;
    DemoState state(scene);
    EXPECT_EQ(state.triangleCount(), expected(state.current()));
    EXPECT_EQ(state.triangleCount(), 256u + 4096u + 256u);
    for (int i = 0; i <= kMaxSubdivisions + 1; ++i) {
        EXPECT_EQ(state.triangleCount(), expected(state.current())) << "level " << state.level();
        state.apply(Command::LevelDown);
    }
    EXPECT_EQ(state.triangleCount(), 3u * 4u);
    DemoState single(Scene{});
    EXPECT_EQ(single.triangleCount(), 4096u); // level 5: 4^6
    Scene empty;
    empty.objects.clear();
    EXPECT_EQ(DemoState(empty).triangleCount(), 0u);
}

// ---- O: perspective <-> orthographic ----

TEST(DemoProjection, OTogglesOrthographicAndTwiceRestoresExactly) {
    for (const Scene& scene : {Scene{}, threeObjectScene()}) {
        DemoState state(scene);
        const Projection original = state.current().projection;
        EXPECT_TRUE(sameProjection(original, scene.projection))
            << "the first frame uses the scene's projection";
        EXPECT_FALSE(state.orthographic());
        EXPECT_TRUE(state.apply(Command::ToggleProjection));
        EXPECT_TRUE(state.orthographic());
        EXPECT_EQ(state.current().projection.type, ProjectionType::Orthographic);
        EXPECT_EQ(state.current().projection.near, original.near);
        EXPECT_EQ(state.current().projection.far, original.far);
        state.apply(Command::ToggleProjection);
        EXPECT_FALSE(state.orthographic());
        EXPECT_TRUE(sameProjection(state.current().projection, original));
    }
}

// The issue: O keeps the sphere's size on screen. The orthographic box shows the perspective view's height
// at the target, so the sphere's projected radius differs only by the perspective bulge d/√(d²−r²).
TEST(DemoProjection, OKeepsTheSpheresSizeOnScreen) {
    struct Move {
        double dx, dy, wheel;
    };
    for (const Move& move : {Move{0, 0, 0}, Move{140, -60, 0}, Move{-300, 90, -6}, Move{45, 10, 3}}) {
        DemoState state(Scene{});
        state.drag(move.dx, move.dy);
        state.zoom(move.wheel);
        const Scene perspective = state.current();
        state.apply(Command::ToggleProjection);
        const Scene orthographic = state.current();
        ASSERT_EQ(orthographic.projection.type, ProjectionType::Orthographic);
        EXPECT_EQ(orthographic.eye, perspective.eye);
        const double rp = projectedRadiusNdc(perspective, {0, 0, 0}, 1);
        const double ro = projectedRadiusNdc(orthographic, {0, 0, 0}, 1);
        EXPECT_NEAR(ro / rp, 1.0, 0.10) << "perspective " << rp << ", orthographic " << ro << " (drag "
                                        << move.dx << "," << move.dy << ", wheel " << move.wheel << ")";
        // Same half-height at the target: the ratio is exactly the perspective bulge √(d²−r²)/d.
        const double d = glm::length(perspective.eye);
        EXPECT_NEAR(ro / rp, std::sqrt(d * d - 1) / d, 1e-9) << "d = " << d;
    }
}

TEST(DemoProjection, OFromAnOrthographicSceneKeepsTheSpheresSize) {
    Scene scene;
    scene.projection = {ProjectionType::Orthographic, 40, -1.5, 1.5, -1.5, 1.5, 0.5, 20};
    scene.eye = {0, 0, 5};
    DemoState state(scene);
    EXPECT_TRUE(state.orthographic());
    const Scene orthographic = state.current();
    EXPECT_TRUE(sameProjection(orthographic.projection, scene.projection));
    state.apply(Command::ToggleProjection);
    const Scene perspective = state.current();
    ASSERT_EQ(perspective.projection.type, ProjectionType::Perspective);
    EXPECT_NO_THROW(validateScene(perspective));
    const double rp = projectedRadiusNdc(perspective, {0, 0, 0}, 1);
    const double ro = projectedRadiusNdc(orthographic, {0, 0, 0}, 1);
    EXPECT_NEAR(ro / rp, 1.0, 0.10) << "orthographic " << ro << ", perspective " << rp;
    EXPECT_NEAR(ro / rp, std::sqrt(24.0) / 5, 1e-9) << "same half-height at the target distance 5";
    state.apply(Command::ToggleProjection);
    EXPECT_TRUE(sameProjection(state.current().projection, scene.projection));
}

// The window draws current(width, height) at the framebuffer's size. Robustness: a resized
// window must not distort the picture. Perspective recomputes its aspect from the size; the orthographic
// box must too, or the sphere becomes an ellipse.
TEST(DemoProjection, SphereStaysRoundWhenTheWindowAspectDiffersFromTheScenes) {
    for (bool orthographic : {false, true}) {
        Scene scene; // 512×512
        DemoState state(scene);
        if (orthographic) state.apply(Command::ToggleProjection);
        const Scene s = state.current(800, 600); // a window resized to 800×600
        const SceneView view = sceneView(s);
        const CameraFrame frame = cameraFrame(s.eye, s.target, s.up);
        const glm::dvec3 centre = ndc(view, {0, 0, 0});
        // Silhouette points left-right and up-down; at the target distance the bulge is the same both ways.
        const double rx = std::abs(ndc(view, frame.u).x - centre.x) * s.width / 2;
        const double ry = std::abs(ndc(view, frame.v).y - centre.y) * s.height / 2;
        EXPECT_NEAR(rx / ry, 1.0, 0.01) << (orthographic ? "orthographic" : "perspective") << ": " << rx
                                        << " px wide, " << ry << " px high";
    }
}

// ---- M: material presets ----

enum class Kind { Matte, Plastic, Metal, Other };
Kind materialKind(const Material& m) {
    if (m.specular == glm::dvec3(0)) return Kind::Matte;
    if (m.shininess >= 5 && m.shininess <= 10) return Kind::Plastic;
    if (m.shininess >= 100 && m.shininess <= 200) return Kind::Metal;
    return Kind::Other;
}

TEST(DemoMaterials, MCyclesMattePlasticMetalAndBackToTheScenesOwn) {
    const Scene scene = threeObjectScene(); // Phong lighting: shininess is α
    DemoState state(scene);
    std::set<Kind> seen;
    int presses = 0;
    for (;;) {
        ASSERT_LT(presses, 20) << "M never returns to the scene's own materials";
        EXPECT_TRUE(state.apply(Command::NextMaterial));
        ++presses;
        const Scene s = state.current();
        EXPECT_NO_THROW(validateScene(s));
        bool original = true;
        for (std::size_t i = 0; i < s.objects.size(); ++i)
            original = original && sameMaterial(s.objects[i].material, scene.objects[i].material);
        if (original) break;
        for (std::size_t i = 1; i < s.objects.size(); ++i) // a preset applies to every object
            EXPECT_TRUE(sameMaterial(s.objects[i].material, s.objects[0].material)) << "object " << i;
        const Kind kind = materialKind(s.objects[0].material);
        EXPECT_NE(kind, Kind::Other) << state.materialName() << ": k_s "
                                     << str(s.objects[0].material.specular) << ", α "
                                     << s.objects[0].material.shininess;
        EXPECT_TRUE(seen.insert(kind).second) << state.materialName() << " seen twice";
        EXPECT_FALSE(state.materialName().empty());
    }
    EXPECT_EQ(seen, (std::set<Kind>{Kind::Matte, Kind::Plastic, Kind::Metal}));
    EXPECT_EQ(presses, 4);
    // Other state is not touched by M.
    EXPECT_EQ(state.current().lighting, scene.lighting);
    EXPECT_EQ(state.current().shading, scene.shading);
}

TEST(DemoMaterials, PresetsNameTheirKind) {
    DemoState state(phongScene());
    std::set<std::string> names;
    for (int i = 0; i < 3; ++i) {
        state.apply(Command::NextMaterial);
        names.insert(state.materialName());
    }
    EXPECT_EQ(names, (std::set<std::string>{"matte", "plastic", "metal"}));
}

// The presets' exponents are Phong α (the issue: plastic α ≈ 5–10, metal α ≈ 100–200). In the demo's
// default Blinn-Phong lighting with the β = 4α matching on, choosing "plastic" and pressing B to compare
// with Phong must show the plastic α, not a quarter of it.
TEST(DemoMaterials, PresetChosenUnderBlinnPhongIsItsAlphaAfterB) {
    DemoState state(Scene{}); // blinn-phong
    ASSERT_TRUE(state.matchHighlight);
    for (int preset = 0; preset < 3; ++preset) {
        state.apply(Command::NextMaterial);
        const std::string name = state.materialName();
        state.apply(Command::ToggleLighting); // -> Phong
        const Material m = state.current().objects[0].material;
        ASSERT_EQ(state.current().lighting, LightingModel::Phong);
        if (name == "plastic") {
            EXPECT_GE(m.shininess, 5) << "plastic under Phong after B: α = " << m.shininess;
            EXPECT_LE(m.shininess, 10) << "plastic under Phong after B: α = " << m.shininess;
        }
        if (name == "metal") {
            EXPECT_GE(m.shininess, 100) << "metal under Phong after B: α = " << m.shininess;
            EXPECT_LE(m.shininess, 200) << "metal under Phong after B: α = " << m.shininess;
        }
        state.apply(Command::ToggleLighting); // back to Blinn-Phong for the next preset
    }
}

// B, then a full M cycle back to the scene's own, then B again: the scene must be what it was. (The
// scene's own β = 32 is α = 8 under Phong; restoring β = 32 while Phong is on makes the next B give 128.)
TEST(DemoMaterials, ScenesOwnMaterialRestoredInTheCurrentLightingModel) {
    const Scene scene; // blinn-phong, β = 32
    DemoState state(scene);
    state.apply(Command::ToggleLighting); // Phong, α = 8
    ASSERT_EQ(state.current().objects[0].material.shininess, 8);
    for (int i = 0; i < 4; ++i) state.apply(Command::NextMaterial);
    ASSERT_EQ(state.materialName(), "scene's own");
    EXPECT_EQ(state.current().objects[0].material.shininess, 8)
        << "the scene's own material under Phong lighting (matched from β = 32)";
    state.apply(Command::ToggleLighting);
    EXPECT_EQ(state.current().lighting, LightingModel::BlinnPhong);
    EXPECT_EQ(state.current().objects[0].material.shininess, 32)
        << "B, M×4, B did not give back the scene's β";
}

// ---- L: light presets ----

bool chromatic(const glm::dvec3& c) {
    return c.x != c.y || c.y != c.z;
}

TEST(DemoLights, LCyclesPointDirectionalSpotColouredAndBackToTheScenesOwn) {
    const Scene scene = threeObjectScene();
    DemoState state(scene);
    bool point = false, directional = false, spot = false, coloured = false;
    int presses = 0;
    for (;;) {
        ASSERT_LT(presses, 20) << "L never returns to the scene's own lights";
        EXPECT_TRUE(state.apply(Command::NextLights));
        ++presses;
        const Scene s = state.current();
        EXPECT_NO_THROW(validateScene(s)) << state.lightsName();
        if (sameLights(s.lights, scene.lights)) break;
        EXPECT_FALSE(state.lightsName().empty());
        ASSERT_FALSE(s.lights.empty()) << state.lightsName();
        if (s.lights.size() == 1) {
            point = point || s.lights[0].type == LightType::Point;
            directional = directional || s.lights[0].type == LightType::Directional;
            spot = spot || s.lights[0].type == LightType::Spot;
        } else {
            std::set<std::vector<double>> colours;
            for (const Light& l : s.lights)
                if (chromatic(l.diffuse)) colours.insert({l.diffuse.x, l.diffuse.y, l.diffuse.z});
            coloured = coloured || colours.size() >= 2;
        }
        // Materials, shading and the camera are not touched by L.
        for (std::size_t i = 0; i < s.objects.size(); ++i)
            EXPECT_TRUE(sameMaterial(s.objects[i].material, scene.objects[i].material));
    }
    EXPECT_TRUE(point);
    EXPECT_TRUE(directional);
    EXPECT_TRUE(spot);
    EXPECT_TRUE(coloured) << "no preset with several coloured lights";
    EXPECT_GE(presses, 5);
    EXPECT_EQ(state.lightsName(), "scene's own");
}

TEST(DemoLights, SpotPresetLightsTheSphere) {
    // A spot set-up whose cone misses the default sphere would show a black picture.
    for (const LightPreset& preset : lightPresets())
        for (const Light& l : preset.lights) {
            if (l.type != LightType::Spot) continue;
            const glm::dvec3 toCentre = glm::dvec3(0) - l.position;
            const double angleToCentre =
                std::acos(glm::dot(glm::normalize(toCentre), glm::normalize(l.direction))) / kDeg;
            EXPECT_LT(angleToCentre, l.cutoffDeg) << preset.name;
        }
}

// ---- R and the orbit camera ----

TEST(DemoCamera, RRestoresTheViewAfterDragsAndZooms) {
    for (const Scene& scene : {Scene{}, threeObjectScene()}) {
        DemoState state(scene);
        const Scene before = state.current();
        state.drag(123, -45);
        state.zoom(3);
        state.drag(1e6, 1e6);
        state.zoom(-7.5);
        state.apply(Command::Flat);
        ASSERT_NE(state.current().eye, before.eye);
        EXPECT_TRUE(state.apply(Command::ResetView));
        const Scene after = state.current();
        EXPECT_EQ(after.eye, before.eye) << str(after.eye) << " vs " << str(before.eye);
        EXPECT_EQ(after.target, before.target);
        EXPECT_EQ(after.up, before.up);
        EXPECT_TRUE(sameProjection(after.projection, before.projection));
        EXPECT_EQ(after.shading, ShadingMode::Flat) << "R resets the view only";
    }
}

// For the default scene (and the showcase), the demo's first frame is exactly `shadelab render`'s view.
TEST(DemoCamera, FirstFrameIsTheScenesCamera) {
    Scene showcase;
    showcase.objects[0].radius = 1.1;
    showcase.objects[0].subdivisions = 3;
    for (const Scene& scene : {Scene{}, showcase, threeObjectScene()}) {
        DemoState state(scene);
        const Scene s = state.current();
        EXPECT_LT(glm::length(s.eye - scene.eye), 1e-12) << str(s.eye) << " vs " << str(scene.eye);
        EXPECT_EQ(s.target, scene.target);
        EXPECT_LT(maxAbsDifference(sceneView(s).viewFromWorld, sceneView(scene).viewFromWorld), 1e-12);
        EXPECT_TRUE(sameProjection(s.projection, scene.projection));
    }
}

// A scene file's camera is part of the scene: `shadelab SCENE.json` should first show what
// `shadelab render SCENE.json` shows. These are valid scenes (DESIGN §4) whose camera the demo changes.
void expectFirstFrameIsTheScenesView(const Scene& scene) {
    validateScene(scene);
    DemoState state(scene);
    const Scene s = state.current();
    const double diff = maxAbsDifference(sceneView(s).viewFromWorld, sceneView(scene).viewFromWorld);
    EXPECT_LT(diff, 1e-9) << "view matrix differs by " << diff << "; eye " << str(s.eye) << " (scene "
                          << str(scene.eye) << "), up " << str(s.up) << " (scene " << str(scene.up) << ")";
}

TEST(DemoCamera, FirstFrameKeepsTheScenesUpVector) {
    Scene scene;
    scene.up = {1, 0, 0}; // a camera rolled by 90°
    expectFirstFrameIsTheScenesView(scene);
}

TEST(DemoCamera, FirstFrameKeepsATopDownCamera) {
    Scene scene;
    scene.eye = {0, 5, 0};
    scene.up = {0, 0, -1};
    expectFirstFrameIsTheScenesView(scene);
}

TEST(DemoCamera, FirstFrameKeepsACameraThatIsAlreadyOutsideEveryObject) {
    Scene scene;
    scene.eye = {0, 0, 4};
    scene.objects[0].center = {3, 0, 0}; // the eye is 5 from its centre; nothing near the near plane
    SceneObject other = scene.objects[0];
    other.center = {-3, 0, 0};
    scene.objects.push_back(other);
    expectFirstFrameIsTheScenesView(scene);
}

TEST(OrbitCamera, EyeIsAtDistanceFromTheTarget) {
    std::mt19937_64 rng(20240603);
    std::uniform_real_distribution<double> any(-50, 50), angle(-3 * std::numbers::pi, 3 * std::numbers::pi),
        elevation(-OrbitCamera::kMaxElevationRad, OrbitCamera::kMaxElevationRad), distance(0.01, 100);
    for (int i = 0; i < 1000; ++i) {
        OrbitCamera c;
        c.target = {any(rng), any(rng), any(rng)};
        c.distance = distance(rng);
        c.azimuthRad = angle(rng);
        c.elevationRad = elevation(rng);
        EXPECT_NEAR(glm::length(c.eye() - c.target), c.distance, 1e-12 * (1 + c.distance));
    }
    OrbitCamera c; // azimuth 0, elevation 0: on +z of the target
    c.target = {1, 2, 3};
    EXPECT_LT(glm::length(c.eye() - glm::dvec3(1, 2, 3 + c.distance)), 1e-15);
}

TEST(OrbitCamera, LookingRoundTripsTheEye) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> any(-20, 20), unit(-1, 1), distance(0.1, 50);
    int tested = 0;
    while (tested < 2000) {
        const glm::dvec3 dir{unit(rng), unit(rng), unit(rng)};
        if (glm::length(dir) < 0.1) continue;
        if (std::abs(glm::normalize(dir).y) > std::sin(OrbitCamera::kMaxElevationRad)) continue; // poles
        const glm::dvec3 target{any(rng), any(rng), any(rng)};
        const glm::dvec3 eye = target + distance(rng) * glm::normalize(dir);
        const OrbitCamera c = OrbitCamera::looking(eye, target);
        EXPECT_LT(glm::length(c.eye() - eye), 1e-12) << str(eye) << " -> " << str(c.eye());
        EXPECT_EQ(c.target, target);
        ++tested;
    }
}

TEST(OrbitCamera, DraggingNeverReachesThePoles) {
    const glm::dvec3 up{0, 1, 0};
    for (double dy : {1e6, -1e6, 1e9, -1e9, 359.0, -359.0}) {
        OrbitCamera c;
        c.drag(0, dy);
        EXPECT_LE(std::abs(c.elevationRad), OrbitCamera::kMaxElevationRad);
        EXPECT_GT(std::abs(c.elevationRad), 80 * kDeg) << "dy " << dy << " should reach the clamp";
        EXPECT_NO_THROW(cameraFrame(c.eye(), c.target, up));
        const glm::dvec3 w = glm::normalize(c.eye() - c.target);
        EXPECT_LT(std::abs(glm::dot(w, up)), std::sin(89.5 * kDeg)) << "dy " << dy;
    }
    // Many small drags past the pole do not accumulate beyond the clamp either.
    OrbitCamera c;
    for (int i = 0; i < 10000; ++i) c.drag(3, 1);
    EXPECT_LE(std::abs(c.elevationRad), OrbitCamera::kMaxElevationRad);
    c.drag(0, -1); // and the first drag back moves away from the pole at once
    EXPECT_LT(c.elevationRad, OrbitCamera::kMaxElevationRad);
    EXPECT_TRUE(std::isfinite(c.azimuthRad));
    EXPECT_LE(std::abs(c.azimuthRad), std::numbers::pi + 1e-12) << "azimuth kept in one turn";
}

TEST(OrbitCamera, CurrentSceneFrameNeverThrowsAfterHugeDrags) {
    for (double dy : {1e6, -1e6}) {
        DemoState state(Scene{});
        state.drag(12345.6, dy);
        const Scene s = state.current();
        EXPECT_NO_THROW(cameraFrame(s.eye, s.target, s.up));
        EXPECT_NO_THROW(sceneView(s));
        EXPECT_NO_THROW(validateScene(s));
    }
}

TEST(OrbitCamera, ZoomScalesTheDistance) {
    OrbitCamera c;
    const double d0 = c.distance;
    c.zoom(1);
    EXPECT_NEAR(c.distance, 0.9 * d0, 1e-12) << "positive steps zoom in";
    c.zoom(-1);
    EXPECT_NEAR(c.distance, d0, 1e-12);
    c.zoom(-2);
    EXPECT_NEAR(c.distance, d0 / 0.81, 1e-12);
    c.zoom(0.5);
    EXPECT_NEAR(c.distance, d0 / 0.81 * std::sqrt(0.9), 1e-12) << "fractional (touchpad) steps";
    const glm::dvec3 az{c.azimuthRad, c.elevationRad, 0};
    EXPECT_EQ(az, glm::dvec3(0, 0, 0)) << "zoom moves along the view direction only";
}

// demo_state.h: "×0.9 per step in, clamped to a sane range". Without a clamp the distance underflows to
// 0 or overflows to ∞ and the wheel then stops working in that direction for good.
TEST(OrbitCamera, ZoomStaysInASaneRange) {
    for (double steps : {1e4, -1e4}) {
        OrbitCamera c;
        c.zoom(steps);
        EXPECT_TRUE(std::isfinite(c.distance) && c.distance > 0) << "zoom(" << steps << "): " << c.distance;
        const double after = c.distance;
        c.zoom(steps > 0 ? -1 : 1);
        EXPECT_NE(c.distance, after) << "zoom(" << steps << ") then one step back does nothing";
    }
}

// Over-zooming must not create a dead zone: one wheel step out after zooming in far must move the eye.
TEST(DemoCamera, OneStepOutAfterOverZoomingInMovesTheEye) {
    DemoState state(Scene{});
    state.zoom(100);
    const double closest = glm::length(state.current().eye - state.current().target);
    state.zoom(-1);
    const double after = glm::length(state.current().eye - state.current().target);
    EXPECT_GT(after, closest) << "the wheel had to be turned back past the 100 steps the view ignored";
    DemoState out(Scene{});
    out.zoom(-100);
    const double farthest = glm::length(out.current().eye - out.current().target);
    out.zoom(1);
    EXPECT_LT(glm::length(out.current().eye - out.current().target), farthest);
}

void expectEyeOutsideObjectsAndObjectsInsideFar(const Scene& s, const std::string& context) {
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
        const double d = glm::length(s.eye - s.objects[i].center), r = boundingRadius(s.objects[i]);
        EXPECT_GT(d, r) << context << ": eye inside object " << i << " (" << d << " from its centre)";
        EXPECT_LE(d + r, s.projection.far) << context << ": object " << i << " reaches past the far plane";
    }
}

TEST(DemoCamera, ZoomKeepsTheEyeOutsideObjectsAndInsideFar) {
    for (const Scene& scene : {Scene{}, threeObjectScene()})
        for (double steps : {1000.0, -1000.0, 30.0, -30.0}) {
            DemoState state(scene);
            state.zoom(steps);
            const Scene s = state.current();
            expectEyeOutsideObjectsAndObjectsInsideFar(s, "zoom(" + std::to_string(steps) + ")");
            EXPECT_NO_THROW(sceneView(s));
        }
}

// A valid scene with a tight far plane (eye 2 from a unit sphere, far 2.6): the eye can still be kept
// outside the sphere (distance in (1.5, 1.6] clears the near plane and keeps the sphere before far).
TEST(DemoCamera, ZoomKeepsTheEyeOutsideTheSphereWithATightFarPlane) {
    Scene scene;
    scene.eye = {0, 0, 2};
    scene.projection.far = 2.6;
    validateScene(scene);
    for (double steps : {1000.0, 1e4}) {
        DemoState state(scene);
        state.zoom(steps);
        const Scene s = state.current();
        EXPECT_GT(glm::length(s.eye - s.objects[0].center), s.objects[0].radius)
            << "zoom(" << steps << "): eye " << str(s.eye);
        EXPECT_NO_THROW(sceneView(s)) << "zoom(" << steps << ")";
    }
}

// ---- everything at once ----

TEST(DemoStateRandom, RandomCommandsDragsAndZoomsAlwaysGiveAValidScene) {
    Scene orthographic;
    orthographic.projection = {ProjectionType::Orthographic, 40, -1.6, 1.6, -1.2, 1.2, 0.5, 20};
    Scene frustum = threeObjectScene();
    frustum.projection = {ProjectionType::Frustum, 40, -0.2, 0.25, -0.2, 0.2, 0.5, 30};
    frustum.width = 640;
    frustum.height = 480;
    int sceneIndex = 0;
    for (const Scene& scene : {Scene{}, threeObjectScene(), orthographic, frustum}) {
        std::mt19937 rng(1234 + sceneIndex++);
        std::uniform_int_distribution<int> what(0, 9), commandIndex(0, int(std::size(kAllCommands)) - 1);
        std::uniform_real_distribution<double> pixels(-2000, 2000), steps(-30, 30), unit(0, 1);
        DemoState state(scene);
        for (int op = 0; op < 2000; ++op) {
            std::ostringstream context;
            context << "scene " << sceneIndex - 1 << ", op " << op << ": ";
            const int kind = what(rng);
            if (kind < 6) {
                const Command command = kAllCommands[commandIndex(rng)];
                context << "command " << int(command);
                state.apply(command);
            } else if (kind < 8) {
                const double dx = unit(rng) < 0.05 ? 1e6 : pixels(rng),
                             dy = unit(rng) < 0.05 ? -1e6 : pixels(rng);
                context << "drag " << dx << ", " << dy;
                state.drag(dx, dy);
            } else if (kind < 9) {
                const double s = steps(rng);
                context << "zoom " << s;
                state.zoom(s);
            } else {
                state.matchHighlight = !state.matchHighlight;
                context << "matchHighlight " << state.matchHighlight;
            }
            const Scene s = state.current();
            ASSERT_NO_THROW(validateScene(s)) << context.str();
            SceneView view;
            ASSERT_NO_THROW(view = sceneView(s)) << context.str();
            ASSERT_TRUE(allFinite(view.viewFromWorld)) << context.str();
            ASSERT_TRUE(allFinite(view.clipFromView)) << context.str();
            ASSERT_NO_THROW(cameraFrame(s.eye, s.target, s.up)) << context.str();
            ASSERT_GE(state.level(), 0);
            ASSERT_LE(state.level(), kMaxSubdivisions);
            for (const SceneObject& o : s.objects) {
                const double d = glm::length(s.eye - o.center), r = boundingRadius(o);
                ASSERT_GT(d, r) << context.str() << ": eye inside an object";
                ASSERT_LE(d + r, s.projection.far) << context.str() << ": object past the far plane";
                ASSERT_GE(o.material.shininess, 1) << context.str();
            }
            ASSERT_EQ(s.objects.size(), scene.objects.size());
        }
    }
}

} // namespace
} // namespace shadelab::app

namespace shadelab::app {
namespace {

// Teaching instruments: W cycles the overlay through the scene (so S saves it and `render`
// draws it): none, wireframe, wireframe with face and vertex normals, the lights' markers, none.
TEST(DemoOverlay, WCyclesWireframeNormalsNoneAndTheSceneCarriesIt) {
    DemoState state{Scene{}};
    EXPECT_EQ(commandForKey('W'), Command::ToggleOverlay);
    const Overlay expected[] = {Overlay::Wireframe, Overlay::Normals, Overlay::Lights, Overlay::None};
    for (Overlay overlay : expected) {
        EXPECT_TRUE(state.apply(Command::ToggleOverlay));
        EXPECT_EQ(state.drawn().overlay, overlay);
        EXPECT_EQ(parseScene(sceneToJson(state.drawn())).overlay, overlay) << "the saved scene keeps it";
    }
}

Scene sceneWithLight(const Light& light) {
    Scene scene;
    scene.lights = {light};
    return scene;
}

// Right-drag orbits a point light around the target: its distance to the target stays, dragging right
// moves it towards the camera's right (+x seen from +z), dragging up raises it.
TEST(DemoLightDrag, PointLightOrbitsTheTargetKeepingItsDistance) {
    Light light = Scene::defaultLight(); // at (3, 3, 5)
    DemoState state{sceneWithLight(light)};
    const double distance = glm::length(light.position);
    state.dragLight(40, 0);
    const glm::dvec3 right = state.drawn().lights[0].position;
    EXPECT_NEAR(glm::length(right), distance, 1e-9);
    EXPECT_GT(right.x, light.position.x);
    EXPECT_NEAR(right.y, light.position.y, 1e-9) << "a horizontal drag keeps the height";
    state.dragLight(0, -40);
    EXPECT_GT(state.drawn().lights[0].position.y, right.y) << "dragging up raises the light";
    EXPECT_NE(windowTitle(state, 0).find("light 1 (point) at ("), std::string::npos) << windowTitle(state, 0);
    // The moved light is part of the scene the screenshot saves.
    EXPECT_EQ(parseScene(sceneToJson(state.drawn())).lights[0].position, state.drawn().lights[0].position);
}

// A spot's direction turns with its position, so it keeps lighting the same side of the target; a
// directional light's direction turns as if its source orbited.
TEST(DemoLightDrag, SpotDirectionTurnsWithItAndDirectionalLightTurns) {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0, 0, 5};
    spot.direction = {0, 0, -1};
    spot.cutoffDeg = 20;
    DemoState state{sceneWithLight(spot)};
    state.dragLight(180, 0); // 90° around +y
    const Light moved = state.drawn().lights[0];
    EXPECT_NEAR(moved.position.x, 5, 1e-9);
    EXPECT_NEAR(moved.position.z, 0, 1e-9);
    EXPECT_NEAR(glm::dot(glm::normalize(moved.direction), glm::dvec3(-1, 0, 0)), 1, 1e-12)
        << "still aimed at the target";

    Light directional;
    directional.type = LightType::Directional;
    directional.direction = {0, 0, -2};
    DemoState sun{sceneWithLight(directional)};
    sun.dragLight(180, 0);
    EXPECT_NEAR(glm::dot(sun.drawn().lights[0].direction, glm::dvec3(-1, 0, 0)), 1, 1e-12);
}

TEST(DemoLightDrag, OnlyAmbientLightSaysThereIsNothingToMove) {
    Light ambient;
    ambient.type = LightType::Ambient;
    ambient.ambient = {0.3, 0.3, 0.3};
    DemoState state{sceneWithLight(ambient)};
    state.dragLight(10, 10);
    EXPECT_EQ(state.lastChange(), "no light to move (only ambient light)");
    EXPECT_EQ(state.drawn().lights[0].ambient, ambient.ambient);
}

// A click on the sphere pins the probe; it follows the drawn scene (a mode change re-evaluates it) and a
// click on the background removes it.
TEST(DemoProbe, ClickPinsTheProbeAndTheBackgroundRemovesIt) {
    Scene scene;
    scene.width = scene.height = 200;
    DemoState state{scene};
    state.setViewport(200, 200);
    EXPECT_FALSE(state.probe().has_value());
    ASSERT_TRUE(state.probeAt(100, 100));
    const auto phong = state.probe();
    ASSERT_TRUE(phong.has_value());
    EXPECT_NEAR(phong->exact.pointView.normal.z, 1, 1e-3) << "the centre of the sphere faces the camera";
    EXPECT_NE(state.lastChange().find("probe: phong differs from exact by "), std::string::npos);
    state.apply(Command::Flat);
    const auto flat = state.probe();
    ASSERT_TRUE(flat.has_value());
    EXPECT_NE(flat->mode.pointView.position, phong->mode.pointView.position) << "flat lights the centroid";
    const std::string text = probeText(*flat, ShadingMode::Flat, LightingModel::BlinnPhong);
    for (const char* word : {"ambient", "diffuse", "specular", "pixel", "exact", "n (white)", "h (magenta)"})
        EXPECT_NE(text.find(word), std::string::npos) << word << " in\n" << text;
    EXPECT_FALSE(state.probeAt(2, 2));
    EXPECT_FALSE(state.probe().has_value());
}

// The point tracer: the probe's text follows the exact point through object, world, camera, clip, NDC and
// window coordinates, and the window row is the pixel that was clicked (read back from the text).
TEST(DemoProbe, TheProbeTextTracesThePointToThePixelClicked) {
    Scene scene;
    scene.eye = {1.5, 1, 3.5};
    DemoState state{scene};
    state.setViewport(300, 200);
    ASSERT_TRUE(state.probeAt(170.5, 80.5));
    const std::string text = probeText(state);
    for (const char* stage : {"object p", "world  α = M·p", "camera β = M_cam·α", "clip   M_proj·β",
                              "NDC    clip/w", "window x, y (px), depth"})
        EXPECT_NE(text.find(stage), std::string::npos) << stage << " in\n" << text;
    const std::size_t window = text.find("window x, y (px), depth");
    ASSERT_NE(window, std::string::npos);
    double x = 0, y = 0, depth = 0;
    ASSERT_EQ(std::sscanf(text.c_str() + window + std::strlen("window x, y (px), depth"), "%lf %lf %lf", &x,
                          &y, &depth),
              3)
        << text;
    EXPECT_NEAR(x, 170.5, 1e-3);
    EXPECT_NEAR(y, 80.5, 1e-3);
    EXPECT_TRUE(depth > 0 && depth < 1) << depth;
}

// + goes through the scene's work limit (kMaxTrianglesPerFrame), as --subdivisions does: 64 objects at level
// 9 draw 64 × 4^10 = 67.1 M triangles, the limit itself; level 10 would draw four times that. + then
// changes nothing and the status line says why (it drew 268 M triangles and took 45 s to quit).
TEST(DemoState, LevelUpBeyondTheWorkLimitIsRefused) {
    Scene scene;
    scene.objects.assign(64, scene.objects.at(0));
    for (SceneObject& o : scene.objects) o.subdivisions = 9;
    DemoState state(scene);
    state.apply(Command::LevelUp);
    EXPECT_EQ(state.current().objects.at(0).subdivisions, 9);
    EXPECT_NE(state.levelRefusal.find("level 10 refused"), std::string::npos) << state.levelRefusal;
    EXPECT_NE(state.levelRefusal.find("triangles per frame"), std::string::npos) << state.levelRefusal;
    EXPECT_NE(statusText(state).find("level 10 refused"), std::string::npos) << statusText(state);
    state.apply(Command::LevelDown);
    EXPECT_EQ(state.current().objects.at(0).subdivisions, 8);
    EXPECT_EQ(state.levelRefusal, "");

    // A split draws every object once per side: at level 9 that is twice the limit, so V is refused too,
    // and a split's own @levels count (render --view split:phong@10,gouraud@10 drew 2 × 268 M triangles).
    DemoState split(scene);
    split.apply(Command::ToggleSplitView);
    EXPECT_EQ(split.current().view.kind, ViewKind::Scene);
    EXPECT_NE(split.levelRefusal.find("split view refused"), std::string::npos) << split.levelRefusal;
    Scene sides = scene;
    for (SceneObject& o : sides.objects) o.subdivisions = 0;
    sides.view = parseViewOrThrow("split:phong@10,gouraud@10", "--view");
    try {
        checkSceneLimits(sides);
        ADD_FAILURE() << "a split of 64 level-10 spheres passed the work limit";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("once per side of the split"), std::string::npos) << e.what();
    }
}

// ---- Y: the outside view ----

TEST(DemoOutsideView, YShowsItDragOrbitsTheObserverAndTheCameraStays) {
    DemoState state{Scene{}};
    ASSERT_EQ(commandForKey('Y'), Command::ToggleOutsideView);
    ASSERT_TRUE(state.apply(Command::ToggleOutsideView));
    EXPECT_EQ(state.current().view.kind, ViewKind::Outside);
    EXPECT_EQ(state.lastChange(), "view: outside");
    const Scene before = state.current();
    state.drag(40, -20);
    state.zoom(2);
    const Scene after = state.current();
    EXPECT_EQ(after.eye, before.eye) << "the drag orbits the observer, not the camera";
    EXPECT_EQ(after.view.observer.azimuthDeg, before.view.observer.azimuthDeg - 20);
    EXPECT_EQ(after.view.observer.elevationDeg, before.view.observer.elevationDeg - 10);
    EXPECT_NEAR(after.view.observer.zoom, 0.81, 1e-12);
    EXPECT_FALSE(state.probeAt(256, 256)) << "the picture is the observer's: no probe";
    // S saves the observer with the view, and the saved scene reads back the same.
    EXPECT_EQ(parseScene(sceneToJson(after)).view, after.view);
    for (int i = 0; i < 400; ++i) state.drag(0, 10);
    EXPECT_EQ(state.current().view.observer.elevationDeg, kMaxObserverElevationDeg);
    EXPECT_NO_THROW(validateScene(state.current()));
    ASSERT_TRUE(state.apply(Command::ToggleOutsideView));
    EXPECT_EQ(state.current().view.kind, ViewKind::Scene);
    state.drag(40, 0);
    EXPECT_NE(state.current().eye, before.eye) << "back in the scene view, the drag orbits the camera";
}

// ---- Q: the NDC view ----

TEST(DemoNdcView, QShowsItUnlessTheShadingIsExactWhichHasNoMesh) {
    DemoState state{Scene{}};
    ASSERT_EQ(commandForKey('Q'), Command::ToggleNdcView);
    ASSERT_TRUE(state.apply(Command::ToggleNdcView));
    EXPECT_EQ(state.current().view.kind, ViewKind::Ndc);
    EXPECT_NO_THROW(validateScene(state.current()));
    const Scene before = state.current();
    state.drag(-20, 0);
    EXPECT_EQ(state.current().eye, before.eye) << "the drag orbits the observer, not the camera";
    EXPECT_EQ(state.current().view.observer.azimuthDeg, before.view.observer.azimuthDeg + 10);
    // 5 (exact) leaves the NDC view: the pair would be refused (exact has no mesh to transform).
    state.apply(Command::Exact);
    EXPECT_EQ(state.current().view.kind, ViewKind::Scene);
    EXPECT_NO_THROW(validateScene(state.current()));
    ASSERT_TRUE(state.apply(Command::ToggleNdcView));
    EXPECT_EQ(state.current().view.kind, ViewKind::Scene) << "Q under exact shading";
    EXPECT_NE(state.lastChange().find("exact shading has none"), std::string::npos) << state.lastChange();
    Scene refused = before;
    refused.shading = ShadingMode::Exact;
    EXPECT_THROW(validateScene(refused), InputError);
}

// ---- the view volume on the panel and the page ----

TEST(DemoViewVolume, AnEditBecomesTheDrawnProjectionAndARefusalNamesTheField) {
    DemoState state{Scene{}};
    const Projection narrow{ProjectionType::Perspective, 30, -1, 1, -1, 1, 1, 9};
    state.editViewVolume(narrow);
    EXPECT_EQ(state.current().projection, narrow);
    EXPECT_EQ(parseScene(sceneToJson(state.current())).projection, narrow) << "S saves the edited volume";
    Projection backwards = narrow;
    backwards.far = 0.5;
    try {
        state.editViewVolume(backwards);
        ADD_FAILURE() << "far < near was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("projection.far"), std::string::npos) << e.what();
    }
    EXPECT_EQ(state.current().projection, narrow) << "a refused edit changed the volume";

    // An orthographic box, off-centre and not of the picture's aspect, is drawn as edited; zooming out
    // scales it about the axis by the distance, as the demo's orthographic zoom always has.
    const Projection box{ProjectionType::Orthographic, 40, -2, 1, -1.5, 1.5, 0.5, 20};
    state.editViewVolume(box);
    EXPECT_TRUE(state.orthographic());
    EXPECT_EQ(state.current().projection, box);
    const double before = glm::length(state.current().eye - state.current().target);
    state.zoom(-2);
    const double ratio = glm::length(state.current().eye - state.current().target) / before;
    ASSERT_GT(ratio, 1.1);
    const Projection zoomed = state.current().projection;
    EXPECT_NEAR(zoomed.left, box.left * ratio, 1e-12);
    EXPECT_NEAR(zoomed.right, box.right * ratio, 1e-12);
    EXPECT_NEAR(zoomed.top, box.top * ratio, 1e-12);
    EXPECT_EQ(zoomed.near, box.near);
    // O goes to perspective from the edited box, showing the same height at the target.
    state.apply(Command::ToggleProjection);
    const Scene perspective = state.current();
    EXPECT_EQ(perspective.projection.type, ProjectionType::Perspective);
    EXPECT_NEAR(std::tan(perspective.projection.fovyDeg * kDeg / 2) * glm::length(perspective.eye),
                box.top * ratio, 1e-9);
}

// Reads the rows "[ a b c d ]" after the line that starts with `heading`.
std::vector<std::vector<double>> matrixAfter(const std::string& text, const std::string& heading, int rows) {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line) && line.rfind(heading, 0) != 0) {
    }
    std::vector<std::vector<double>> out;
    while (int(out.size()) < rows && std::getline(in, line)) {
        const std::size_t open = line.find('[');
        if (open == std::string::npos || std::isalpha(static_cast<unsigned char>(line[open + 1])))
            continue; // a note under the heading: "[l,r] = ..."
        std::istringstream numbers(line.substr(line.find('[') + 1));
        std::vector<double> row;
        for (double x; numbers >> x;) row.push_back(x);
        out.push_back(row);
    }
    return out;
}

void expectMatrix(const std::vector<std::vector<double>>& shown, const glm::dmat4& expected,
                  const std::string& name) {
    ASSERT_EQ(shown.size(), 4u) << name;
    for (int r = 0; r < 4; ++r) {
        ASSERT_EQ(shown[std::size_t(r)].size(), 4u) << name << " row " << r;
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(shown[std::size_t(r)][std::size_t(c)], expected[c][r], 5e-5)
                << name << " [" << r << "][" << c << "]";
    }
}

TEST(MatricesText, ShowsMCamAndTheWebGlMatrixAsTheLectureWritesThem) {
    Scene scene;
    scene.eye = {1, 2, 3};
    scene.target = {0, 0.5, 0};
    scene.width = 400;
    scene.height = 200;
    const std::string text = cameraMatricesText(scene);
    // M_cam is glm::lookAt (DESIGN §2); the projection is DESIGN §2's matrix written out with n = -near,
    // f = -far and the window of fovy and the aspect.
    expectMatrix(matrixAfter(text, "M_cam", 4), glm::lookAt(scene.eye, scene.target, scene.up), "M_cam");
    const double n = -0.5, f = -20, t = 0.5 * std::tan(20 * kDeg), r = 2 * t;
    glm::dmat4 webGl(0.0);
    webGl[0][0] = -2 * n / (2 * r);
    webGl[1][1] = -2 * n / (2 * t);
    webGl[2][2] = -(n + f) / (n - f);
    webGl[3][2] = 2 * f * n / (n - f);
    webGl[2][3] = -1;
    expectMatrix(matrixAfter(text, "M_proj", 4), webGl, "M_proj");
    EXPECT_NE(text.find("w = -z > 0"), std::string::npos) << text;
    scene.perspectiveMatrix = PerspectiveMatrix::Unnegated;
    const std::string unnegated = cameraMatricesText(scene);
    expectMatrix(matrixAfter(unnegated, "M_proj", 4), -webGl, "unnegated M_proj");
    EXPECT_NE(unnegated.find("w = z < 0"), std::string::npos) << unnegated;
}

TEST(MatricesText, TheNormalMatrixIsTheInverseTransposeOrMItself) {
    Scene scene;
    scene.objects[0].scale = {2, 1, 1};
    scene.objects[0].center = {0.5, 0, 0};
    const auto normal = [&] { return matrixAfter(objectMatricesText(scene, 0), "normal matrix", 3); };
    // The camera looks down -z from +z: M_cam's upper 3x3 is the identity, so the normal matrix of
    // scale(2, 1, 1) is diag(1/2, 1, 1), and M itself is diag(2, 1, 1).
    ASSERT_EQ(normal().size(), 3u);
    EXPECT_NEAR(normal()[0][0], 0.5, 1e-9);
    EXPECT_NEAR(normal()[1][1], 1, 1e-9);
    EXPECT_NE(objectMatricesText(scene, 0).find("((M_cam M)^-1)^T"), std::string::npos);
    scene.normalMatrix = NormalMatrixRule::Model;
    EXPECT_NEAR(normal()[0][0], 2, 1e-9);
    EXPECT_NE(objectMatricesText(scene, 0).find("wrong on purpose"), std::string::npos);
    const auto model = matrixAfter(objectMatricesText(scene, 0), "M (object 1", 4);
    ASSERT_EQ(model.size(), 4u);
    EXPECT_EQ(model[0], (std::vector<double>{2, 0, 0, 0.5}));
}

// Every matrix and vector row of `text`: "[", then entries of kEntryDigits + 1 characters, then " ]".
std::vector<std::string> matrixRows(const std::string& text) {
    std::vector<std::string> rows;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        const std::size_t open = line.find('[');
        if (open != std::string::npos && line.ends_with(" ]") && !std::isalpha(line[open + 1]))
            rows.push_back(line.substr(open + 1, line.size() - open - 3));
    }
    return rows;
}

// True when some entry of the scene's M_cam is float noise around a whole number (not one exactly).
bool mCamHasNoise(const Scene& scene) {
    const glm::dmat4 m = sceneView(scene).viewFromWorld;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (m[c][r] != std::round(m[c][r]) && std::abs(m[c][r] - std::round(m[c][r])) <= 1e-12)
                return true;
    return false;
}

// The panel, the page and render --print-matrices share this text. Entries stand in columns of one width
// with a space before each, up to 1e29 and negative; float noise around a whole number shows as
// that number, and 0 never as -0.
TEST(MatricesText, EntriesStandInFixedWidthColumnsWithASpaceBetween) {
    Scene far;
    far.eye = {1e29, 0, -1e29}; // M_cam's -w.e is -1.41e+29, beside 0.7071
    far.projection = {ProjectionType::Frustum, 40, -1e20, 1e20, -1e20, 1e20, 1e29, 1e30};
    Scene noisy;
    noisy.eye = {-3, 0, 1}; // an entry of M_cam is -1.11e-16
    noisy.target = {0, 0.5, 0};
    ASSERT_TRUE(mCamHasNoise(noisy)) << "this scene no longer shows float noise: choose another eye";
    for (const Scene& scene : {far, noisy}) {
        const std::string text = cameraMatricesText(scene) + objectMatricesText(scene, 0);
        const std::vector<std::string> rows = matrixRows(text);
        ASSERT_EQ(rows.size(), 4u + 4 + 4 + 4 + 3) << text; // e u v w, M_cam, M_proj, M, normal matrix
        for (const std::string& row : rows) {
            ASSERT_EQ(row.size() % (kEntryDigits + 1), 0u) << "columns of one width:\n" << text;
            for (std::size_t at = 0; at < row.size(); at += kEntryDigits + 1) {
                const std::string entry = row.substr(at, kEntryDigits + 1);
                EXPECT_EQ(entry[0], ' ') << "an entry touches the one before it: [" << row << "]\n" << text;
                std::istringstream in(entry);
                std::string token, rest;
                in >> token >> rest;
                EXPECT_TRUE(rest.empty()) << "one number per column: [" << row << "]";
                EXPECT_NE(token, "-0") << row;
                EXPECT_EQ(token.find("e-1"), std::string::npos) << "float noise shown as a number: " << row;
            }
        }
    }
    EXPECT_NE(cameraMatricesText(far).find("-1.41e+29"), std::string::npos);
}

TEST(MatricesText, FloatNoiseShowsAsTheWholeNumberAndZeroHasNoSign) {
    auto shown = [](double x) {
        std::istringstream in(matrixEntry(x));
        std::string token;
        in >> token;
        return token;
    };
    EXPECT_EQ(shown(-1.11e-16), "0");
    EXPECT_EQ(shown(-0.0), "0");
    EXPECT_EQ(shown(1 - 2e-16), "1");
    EXPECT_EQ(shown(-1 - 1e-13), "-1");
    EXPECT_EQ(shown(0.70710678), "0.7071");
    EXPECT_EQ(shown(-0.1919), "-0.1919");
    EXPECT_EQ(shown(-1e-11), "-1.00e-11") << "beyond 1e-12 of a whole number the value shows";
    EXPECT_EQ(shown(-1e300), "-1.0e+300");
    EXPECT_EQ(shown(-999.99996), "-1.00e+03") << "rounding to 4 decimals would take 10 characters";
    for (double x : {-1e300, -1.11e-16, -999.99996, 1e-300, -0.1919, 12345.678, 4.9e-324})
        EXPECT_EQ(matrixEntry(x).size(), kEntryDigits + 1) << x;
}

} // namespace
} // namespace shadelab::app

// The window keeps the scene's framing. grid.json (800x600) beside the panel in a 1280x800 window
// (an 860x800 area) is letterboxed, not cropped to its two middle columns.
TEST(FitPicture, KeepsTheScenesAspectCentredInTheArea) {
    using shadelab::app::fitPicture;
    const auto wide = fitPicture(800, 600, 860, 800);
    EXPECT_EQ(wide.width, 860);
    EXPECT_EQ(wide.height, 645); // 860 * 600 / 800
    EXPECT_EQ(wide.x, 0);
    EXPECT_EQ(wide.y, 77); // (800 - 645) / 2: bars above and below
    const auto tall = fitPicture(512, 1024, 1000, 600);
    EXPECT_EQ(tall.width, 300);
    EXPECT_EQ(tall.height, 600);
    EXPECT_EQ(tall.x, 350); // bars at the sides
    EXPECT_EQ(tall.y, 0);
    const auto same = fitPicture(640, 480, 1280, 960);
    EXPECT_EQ(same.x, 0);
    EXPECT_EQ(same.y, 0);
    EXPECT_EQ(same.width, 1280);
    EXPECT_EQ(same.height, 960);
    const auto sliver = fitPicture(1, 10000, 100, 100);
    EXPECT_EQ(sliver.width, 1) << "never narrower than a pixel";
    EXPECT_EQ(sliver.height, 100);
    const auto none = fitPicture(800, 600, 0, 800);
    EXPECT_EQ(none.width, 0);
    EXPECT_EQ(none.height, 0);
    EXPECT_TRUE(wide.contains(10, 77));
    EXPECT_FALSE(wide.contains(10, 76)) << "the bar above is not the picture";
    EXPECT_FALSE(wide.contains(10, 77 + 645)) << "the bar below is not the picture";
}

// The panel's material edits apply to one chosen object, or to all only when chosen so. A probe
// click picks the object it hits; the status line names what the edits apply to, and the material's name
// says it was edited.
TEST(DemoPanelEdits, AProbeClickChoosesTheObjectThePanelEdits) {
    shadelab::Scene scene;
    scene.width = 200;
    scene.height = 100;
    scene.objects.resize(2);
    scene.objects[0].center = {-1.2, 0, 0};
    scene.objects[1].center = {1.2, 0, 0};
    scene.objects[0].radius = scene.objects[1].radius = 0.8;
    shadelab::app::DemoState state(scene);
    state.setViewport(200, 100);
    EXPECT_EQ(state.editedObjectName(), "object 1 of 2");
    ASSERT_TRUE(state.probeAt(150, 50)) << "the right sphere is under (150, 50)";
    EXPECT_EQ(state.editedObject, 1);
    EXPECT_EQ(state.editedObjectName(), "object 2 of 2");
    EXPECT_NE(shadelab::app::statusText(state).find("panel edits: object 2 of 2"), std::string::npos)
        << shadelab::app::statusText(state);
    ASSERT_TRUE(state.probeAt(50, 50));
    EXPECT_EQ(state.editedObject, 0);

    state.editedObject = shadelab::app::DemoState::kAllObjects; // chosen explicitly: a click keeps it
    EXPECT_EQ(state.editedObjectName(), "all 2 objects");
    ASSERT_TRUE(state.probeAt(150, 50));
    EXPECT_EQ(state.editedObject, shadelab::app::DemoState::kAllObjects);

    EXPECT_EQ(state.materialName(), "scene's own");
    shadelab::Material edited = state.scene().objects[0].material;
    edited.shininess = 7;
    state.editMaterial(edited);
    EXPECT_EQ(state.materialName(), "scene's own, edited in the panel");
    state.apply(shadelab::app::Command::NextMaterial);
    EXPECT_EQ(state.materialName().find("edited"), std::string::npos)
        << "M sets a preset: " << state.materialName();

    shadelab::Scene one = scene;
    one.objects.resize(1);
    EXPECT_EQ(shadelab::app::DemoState(one).editedObjectName(), "the object");
}

// The window's panel and the page edit materials through DemoState: the chosen object alone, or with all
// objects chosen, the property that changed on every object while each keeps its others (grid.json's
// spheres differ in shininess and specular); the chooser's numbers (0: all) are clamped to the objects.
TEST(DemoPanelEdits, AnEditChangesTheChosenObjectOrThatPropertyOfAll) {
    using shadelab::app::DemoState;
    shadelab::Scene scene;
    scene.objects.resize(3);
    const double shininess[3] = {5, 20, 60};
    for (std::size_t i = 0; i < 3; ++i) {
        scene.objects[i].center = {double(i) * 2.5 - 2.5, 0, 0};
        scene.objects[i].material.shininess = shininess[i];
        scene.objects[i].material.specular = glm::dvec3(0.25 * double(i + 1));
    }
    DemoState state(scene);
    EXPECT_EQ(state.editedObjectNumber(), 1);
    state.chooseEditedObject(3);
    EXPECT_EQ(state.editedObject, 2);
    ASSERT_EQ(state.shownObject(), std::optional<std::size_t>(2));
    shadelab::Material m = state.scene().objects[2].material;
    m.shininess = 31.6;
    m.diffuse = {0.1, 0.9, 0.1};
    state.editMaterial(m);
    EXPECT_EQ(state.scene().objects[2].material, m);
    EXPECT_EQ(state.scene().objects[0].material, scene.objects[0].material);
    EXPECT_EQ(state.scene().objects[1].material, scene.objects[1].material);
    EXPECT_EQ(state.materialName(), "scene's own, edited in the panel");

    state.chooseEditedObject(0);
    EXPECT_EQ(state.editedObject, DemoState::kAllObjects);
    EXPECT_EQ(state.editedObjectNumber(), 0);
    ASSERT_EQ(state.shownObject(), std::optional<std::size_t>(0)); // all: the first object's values show
    m = state.scene().objects[0].material;
    m.shininess = 100;
    state.editMaterial(m);
    for (std::size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(state.scene().objects[i].material.shininess, 100);
        EXPECT_EQ(state.scene().objects[i].material.specular, scene.objects[i].material.specular)
            << "an unchanged property was copied from the first object";
    }
    EXPECT_EQ(state.scene().objects[2].material.diffuse, glm::dvec3(0.1, 0.9, 0.1));

    state.chooseEditedObject(7);
    EXPECT_EQ(state.editedObject, 2) << "past the last object: the last";
    state.chooseEditedObject(-3);
    EXPECT_EQ(state.editedObject, DemoState::kAllObjects);
    shadelab::Scene none = scene;
    none.objects.clear();
    DemoState empty(none);
    EXPECT_FALSE(empty.shownObject().has_value());
    empty.editMaterial(m); // nothing to edit, and no crash
    EXPECT_EQ(empty.materialName(), "scene's own");
}

// The panel's scale: the chosen object's, or every object's with all chosen; a zero or non-finite
// component is refused with a message naming the object's place and changes nothing. J then toggles the
// normal matrix, and the title says so.
TEST(DemoObjects, ScaleEditsTheChosenObjectOrAllAndJTogglesTheNormalMatrix) {
    using namespace shadelab::app;
    shadelab::Scene scene =
        shadelab::parseScene(R"({"objects": [{"center": [-2, 0, 0]}, {"center": [2, 0, 0]}]})");
    DemoState state(scene);
    state.chooseEditedObject(2);
    state.editScale({1.5, 0.5, 1});
    EXPECT_EQ(state.scene().objects[1].scale, glm::dvec3(1.5, 0.5, 1));
    EXPECT_EQ(state.scene().objects[0].scale, glm::dvec3(1));
    try {
        state.editScale({1, 0, 1});
        ADD_FAILURE() << "a zero scale was accepted";
    } catch (const shadelab::InputError& e) {
        EXPECT_STREQ(e.what(), "objects[1].scale[1]: must be finite and non-zero, got 0");
    }
    EXPECT_THROW(state.editScale({std::nan(""), 1, 1}), shadelab::InputError);
    // What 32-bit float cannot carry is refused as a scene file's scale is (exact shading drew nothing).
    try {
        state.editScale({1, 1, 1e-20});
        ADD_FAILURE() << "a scale of 1e-20 was accepted";
    } catch (const shadelab::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("objects[1]"), std::string::npos) << e.what();
    }
    EXPECT_EQ(state.scene().objects[1].scale, glm::dvec3(1.5, 0.5, 1)) << "a refused edit changed the scale";
    state.chooseEditedObject(0); // all: the first object's scale shows; y changes on both, x stays each's
    state.editScale({1, 2, 1});
    EXPECT_EQ(state.scene().objects[0].scale, glm::dvec3(1, 2, 1));
    EXPECT_EQ(state.scene().objects[1].scale, glm::dvec3(1.5, 2, 1));

    EXPECT_EQ(state.scene().normalMatrix, shadelab::NormalMatrixRule::InverseTranspose);
    ASSERT_TRUE(state.apply(*commandForKey('J')));
    EXPECT_EQ(state.scene().normalMatrix, shadelab::NormalMatrixRule::Model);
    EXPECT_NE(windowTitle(state, 1.0).find("normals by M"), std::string::npos) << windowTitle(state, 1.0);
    EXPECT_NE(presentationLabel(state).find("NORMALS BY M"), std::string::npos) << presentationLabel(state);
    EXPECT_EQ(state.lastChange(), "normals transformed by M: wrong wherever M scales unevenly");
    ASSERT_TRUE(state.apply(*commandForKey('J')));
    EXPECT_EQ(state.scene().normalMatrix, shadelab::NormalMatrixRule::InverseTranspose);
    EXPECT_EQ(windowTitle(state, 1.0).find("normals by M"), std::string::npos);
}

// Exact shading draws no mesh, so the title, the status and the presentation label name the ray
// cast instead of a level and a triangle count; back on a mesh mode they show the level again.
TEST(DemoTitle, ExactShadingNamesTheRayCastNotALevel) {
    using namespace shadelab::app;
    DemoState state{shadelab::Scene{}};
    state.apply(Command::Exact);
    const std::string title = windowTitle(state, 0);
    EXPECT_NE(title.find("exact shading, blinn-phong lighting | ray-cast per pixel, no mesh | "),
              std::string::npos)
        << title;
    EXPECT_EQ(title.find("level"), std::string::npos) << title;
    EXPECT_EQ(title.find("triangles"), std::string::npos) << title;
    EXPECT_EQ(statusText(state).find("level"), std::string::npos) << statusText(state);
    EXPECT_NE(presentationLabel(state).find("RAY-CAST"), std::string::npos) << presentationLabel(state);
    state.apply(Command::Phong);
    EXPECT_NE(windowTitle(state, 0).find("| level 5 | "), std::string::npos) << windowTitle(state, 0);
}

// After an orbit of 180° the probed point is on the far side of the sphere: the table says the
// probe is hidden behind the object (and the window draws no vectors for it: probeFacesAway); orbiting
// back shows it again.
TEST(DemoProbe, AProbeBehindTheObjectIsSaidToBeHidden) {
    using namespace shadelab::app;
    DemoState state{shadelab::Scene{}};
    state.setViewport(200, 200);
    ASSERT_TRUE(state.probeAt(100, 100));
    ASSERT_TRUE(state.probe());
    EXPECT_FALSE(probeFacesAway(*state.probe()));
    EXPECT_EQ(probeText(state).find("probe hidden"), std::string::npos);
    state.drag(360, 0); // 0.5° a pixel: half a turn around the target
    ASSERT_TRUE(state.probe());
    EXPECT_TRUE(probeFacesAway(*state.probe()));
    EXPECT_TRUE(probeText(state).starts_with("probe hidden: behind the object")) << probeText(state);
    state.drag(-360, 0);
    EXPECT_FALSE(probeFacesAway(*state.probe()));
}

// The presentation label is laid out from the picture's size alone (stable from frame to frame),
// large for a class (lines a twelfth of the height: 55 px at 1280x720), never wider than the picture less
// its margins (smaller text in a narrow picture instead of a clipped line), and its box holds all three
// lines.
TEST(DemoPresentation, LabelImageIsLargeStableAndNeverClipped) {
    using shadelab::app::presentationLabelImage;
    const std::string label = "PHONG SHADING\nBLINN-PHONG LIGHTING\nLEVEL 5 | BETA = 96";
    const auto wide = presentationLabelImage(label, 1280, 720);
    EXPECT_GE(wide.image.height, 3 * shadelab::textLineHeight(5)) << "three lines of 55 px at 720 high";
    EXPECT_LE(wide.image.width + 2 * wide.margin, 1280);
    const auto again = presentationLabelImage(label, 1280, 720);
    EXPECT_EQ(again.image.rgba, wide.image.rgba) << "the same size must give the same label";
    for (const auto& [w, h] : {std::pair{860, 720}, std::pair{480, 720}, std::pair{1920, 1080}}) {
        const auto fitted = presentationLabelImage(label, w, h);
        EXPECT_LE(fitted.image.width + 2 * fitted.margin, w) << w << "x" << h << ": a line would be clipped";
        EXPECT_LE(fitted.image.height + 2 * fitted.margin, h);
    }
    EXPECT_GT(presentationLabelImage(label, 1920, 1080).image.height, wide.image.height)
        << "scaled with the window";
}

// The normals overlay past level 3 is thinned (overlay.h); the status line (window and page) says how, and
// says nothing at level 3 or without the overlay.
TEST(DemoStatus, SaysWhichNormalsTheThinnedOverlayShows) {
    shadelab::Scene scene =
        shadelab::parseScene(R"({"overlay": "normals", "objects": [{"subdivisions": 6}]})");
    EXPECT_NE(shadelab::app::statusText(shadelab::app::DemoState(scene))
                  .find("normals shown: level 3's vertices and 1 face in 64 (of level 6)"),
              std::string::npos)
        << shadelab::app::statusText(shadelab::app::DemoState(scene));
    scene.objects[0].subdivisions = 3;
    EXPECT_EQ(shadelab::app::statusText(shadelab::app::DemoState(scene)).find("normals shown"),
              std::string::npos);
    scene.objects[0].subdivisions = 6;
    scene.overlay = shadelab::Overlay::Wireframe;
    EXPECT_EQ(shadelab::app::statusText(shadelab::app::DemoState(scene)).find("normals shown"),
              std::string::npos);
}
