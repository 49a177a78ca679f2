// B, +/-, M and L in the demo (src/app/demo/demo_state.h) against DESIGN §3 and the issue: B switches Phong
// and Blinn-Phong with β = 4α and back, + and - change every object's level (clamped, the drawn level under
// auto, refused past the scene's work limit), M cycles the material presets and L the light presets, each
// back to the scene's own.
#include "app/demo/demo_state.h"

#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "demo_test_support.h"
#include "shadelab/errors.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/scene/auto_level.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_values.h"

namespace shadelab::app {
namespace {

using namespace demo_test;

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

Scene phongScene() {
    Scene scene;
    scene.lighting = LightingModel::Phong;
    return scene;
}

// ---- B: Phong <-> Blinn-Phong, β = 4α (DESIGN §3) ----

TEST(DemoLighting, BFromPhongMultipliesEveryShininessByFourAndBackDivides) {
    const Scene scene = threeObjectScene(); // Phong lighting; shininess 32, 12, 300
    DemoState state(scene);
    ASSERT_TRUE(state.matchHighlight()) << "the issue: the matching is on by default in the demo";
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
    state.setMatchHighlight(false);
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
    EXPECT_NE(state.levelRefusal().find("level 10 refused"), std::string::npos) << state.levelRefusal();
    EXPECT_NE(state.levelRefusal().find("triangles per frame"), std::string::npos) << state.levelRefusal();
    EXPECT_NE(statusText(state).find("level 10 refused"), std::string::npos) << statusText(state);
    state.apply(Command::LevelDown);
    EXPECT_EQ(state.current().objects.at(0).subdivisions, 8);
    EXPECT_EQ(state.levelRefusal(), "");

    // A split draws every object once per side: at level 9 that is twice the limit, so V is refused too,
    // and a split's own @levels count (render --view split:phong@10,gouraud@10 drew 2 × 268 M triangles).
    DemoState split(scene);
    split.apply(Command::ToggleSplitView);
    EXPECT_EQ(split.current().view.kind, ViewKind::Scene);
    EXPECT_NE(split.levelRefusal().find("split view refused"), std::string::npos) << split.levelRefusal();
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
    ASSERT_TRUE(state.matchHighlight());
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

} // namespace
} // namespace shadelab::app
