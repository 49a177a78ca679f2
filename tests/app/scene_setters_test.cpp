// One setter per value (src/app/demo/scene_setters.h): every row reads its value and takes it back; a bad
// value is refused with the message the scene file gets for it, whichever door it comes through — the
// window's panel (setValue with its float formatted by valueText), the page (shadelab_set calls setValue
// with the control's text) and the scene file (parseScene, validateScene); a refused value changes nothing.
#include "app/demo/scene_setters.h"

#include <functional>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "shadelab/errors.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app {
namespace {

// One object and a spot light (every light row applies to it), as the panels edit them.
Scene spotScene() {
    Scene scene;
    Light spot = Scene::defaultLight();
    spot.type = LightType::Spot;
    spot.position = {2, 2, 4};
    spot.direction = {-2, -2, -4};
    spot.cutoffDeg = 20;
    spot.exponent = 4;
    scene.lights = {spot};
    validateScene(scene);
    return scene;
}

// The scene file's message for `scene` written out, its text changed by `edit` (for a word no Scene holds),
// less the file's name that only a file's message starts with ("scene.json: ").
std::string sceneFileMessage(const Scene& scene, const std::function<std::string(std::string)>& edit = {}) {
    std::string text = sceneToJson(scene);
    if (edit) text = edit(text);
    try {
        validateScene(parseScene(text, "scene.json"));
    } catch (const InputError& e) {
        const std::string message = e.what();
        return message.starts_with("scene.json: ") ? message.substr(12) : message;
    }
    return "";
}

// `"key": "word"` of a scene file's text with `word` replaced.
std::function<std::string(std::string)> word(const std::string& key, const std::string& value) {
    return [=](const std::string& text) {
        return std::regex_replace(text, std::regex("\"" + key + "\": \"[^\"]*\""),
                                  "\"" + key + "\": \"" + value + "\"");
    };
}

TEST(SceneSetters, EveryRowTakesBackTheValueItReads) {
    DemoState state(spotScene());
    for (const ValueSetter& row : valueSetters()) {
        std::string name(row.name);
        if (name.starts_with("lights[]")) name.replace(0, 8, "lights[0]");
        const std::string value = readValue(state, name);
        EXPECT_EQ(setValue(state, name, value), "") << name << " = " << value;
        EXPECT_EQ(readValue(state, name), value) << name;
    }
    EXPECT_EQ(state.scene(), spotScene()) << "setting every value to itself changed the scene";
}

TEST(SceneSetters, SetValuesReachTheDrawnScene) {
    DemoState state(spotScene());
    EXPECT_EQ(setValue(state, "lighting", "phong"), "");
    EXPECT_EQ(state.drawn().lighting, LightingModel::Phong);
    EXPECT_EQ(state.drawn().objects[0].material.shininess, spotScene().objects[0].material.shininess / 4)
        << "B's rule holds for the setter as for the key";
    EXPECT_EQ(setValue(state, "term", "specular"), "");
    EXPECT_EQ(state.drawn().term, LightingTerm::Specular);
    EXPECT_EQ(setValue(state, "lights[0].cutoff_deg", "35.5"), "");
    EXPECT_EQ(state.drawn().lights[0].cutoffDeg, 35.5);
    EXPECT_EQ(setValue(state, "material.diffuse", "[0.25, 0.5, 0.75]"), "");
    EXPECT_EQ(state.drawn().objects[0].material.diffuse, glm::dvec3(0.25, 0.5, 0.75));
    EXPECT_EQ(setValue(state, "projection", "orthographic"), "");
    EXPECT_EQ(state.drawn().projection.type, ProjectionType::Orthographic);
    EXPECT_EQ(setValue(state, "view", "error"), "");
    EXPECT_EQ(state.drawn().view.kind, ViewKind::Error);
    EXPECT_EQ(setValue(state, "view", "split"), "");
    EXPECT_EQ(state.drawn().view.kind, ViewKind::Split);
    EXPECT_EQ(setValue(state, "view", "scene"), "");
    EXPECT_EQ(state.drawn().view.kind, ViewKind::Scene);
    EXPECT_EQ(setValue(state, "level", "2"), "");
    EXPECT_EQ(state.level(), 2);
    EXPECT_EQ(setValue(state, "auto_level", "true"), "");
    EXPECT_TRUE(state.autoLevel());
    EXPECT_EQ(setValue(state, "toon_bands", "6"), "");
    EXPECT_EQ(state.drawn().toonBands, 6);
    EXPECT_EQ(state.lastChange(), "automatic level on: level " + std::to_string(state.level()))
        << "the title says what the last setter with a key did, in the key's words";
}

struct Refusal {
    const char* name;
    std::string windowText, pageText; // as the window's panel formats it (a float), as the page sends it
    std::function<void(Scene&)> inFile;
    std::function<std::string(std::string)> fileText; // for a word
};

TEST(SceneSetters, ARefusedValueReadsTheSameFromEveryDoor) {
    const Refusal refusals[] = {
        {"material.shininess",
         valueText(0.5f),
         "0.5",
         [](Scene& s) { s.objects[0].material.shininess = 0.5; },
         {}},
        {"material.ambient",
         valueText(glm::dvec3(-0.25, 0, 0)),
         "-0.25 0 0",
         [](Scene& s) {
             s.objects[0].material.ambient = {-0.25, 0, 0};
         },
         {}},
        {"scale",
         valueText(glm::dvec3(1, 0, 1)),
         "1 0 1",
         [](Scene& s) {
             s.objects[0].scale = {1, 0, 1};
         },
         {}},
        {"toon_bands", "1", "1", [](Scene& s) { s.toonBands = 1; }, {}},
        {"lights[0].cutoff_deg", valueText(95.0f), "95", [](Scene& s) { s.lights[0].cutoffDeg = 95; }, {}},
        {"lights[0].exponent", valueText(-1.0f), "-1", [](Scene& s) { s.lights[0].exponent = -1; }, {}},
        {"lights[0].attenuation",
         valueText(glm::dvec3(0)),
         "0 0 0",
         [](Scene& s) { s.lights[0].attenuation = glm::dvec3(0); },
         {}},
        {"lights[0].direction",
         valueText(glm::dvec3(0)),
         "0 0 0",
         [](Scene& s) { s.lights[0].direction = glm::dvec3(0); },
         {}},
        {"projection.far", valueText(0.25f), "0.25", [](Scene& s) { s.projection.far = 0.25; }, {}},
        {"projection.fovy_deg", valueText(180.0f), "180", [](Scene& s) { s.projection.fovyDeg = 180; }, {}},
        {"lighting", "bogus", "bogus", {}, word("lighting", "bogus")},
        {"shading", "bogus", "bogus", {}, word("shading", "bogus")},
        {"term", "bogus", "bogus", {}, word("term", "bogus")},
        {"overlay", "bogus", "bogus", {}, word("overlay", "bogus")},
    };
    for (const Refusal& r : refusals) {
        Scene bad = spotScene();
        if (r.inFile) r.inFile(bad);
        const std::string fromFile = sceneFileMessage(bad, r.fileText);
        ASSERT_NE(fromFile, "") << r.name << ": the scene file takes it";
        DemoState window(spotScene()), page(spotScene());
        EXPECT_EQ(setValue(window, r.name, r.windowText), fromFile) << r.name << " from the window's panel";
        EXPECT_EQ(setValue(page, r.name, r.pageText), fromFile) << r.name << " from the page";
        EXPECT_EQ(window.drawn(), DemoState(spotScene()).drawn()) << r.name << ": a refused value changed it";
    }
}

// The NDC view with exact shading: the scene check's words, from a setter and from a scene file alike.
TEST(SceneSetters, TheNdcViewWithExactShadingIsRefusedInTheSceneChecksWords) {
    Scene exact = spotScene();
    exact.shading = ShadingMode::Exact;
    const std::string fromFile = sceneFileMessage(exact, word("view", "ndc"));
    ASSERT_NE(fromFile, "");
    DemoState state(exact);
    EXPECT_EQ(setValue(state, "view", "ndc"), fromFile);
    EXPECT_EQ(state.drawn().view.kind, ViewKind::Scene);
}

TEST(SceneSetters, TheirOwnSyntaxIsRefusedNamingTheValue) {
    DemoState state(spotScene());
    EXPECT_EQ(setValue(state, "toon_bands", "four"), "toon_bands: expected a number, got \"four\"");
    EXPECT_EQ(setValue(state, "lights[0].position", "1 2"),
              "lights[0].position: expected three numbers, got \"1 2\"");
    EXPECT_EQ(setValue(state, "lights[3].exponent", "2"), "lights[3]: the scene has 1 light(s)");
    EXPECT_EQ(setValue(state, "gamma", "2"), "unknown value \"gamma\"");
    EXPECT_EQ(setValue(state, "level", "11").rfind("level: ", 0), 0u) << setValue(state, "level", "11");
    EXPECT_EQ(state.scene(), spotScene());
}

} // namespace
} // namespace shadelab::app
