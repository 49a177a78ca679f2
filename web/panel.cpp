// The page's control panel: what it shows (panelJson, twice a second), the edits its controls make, and
// the tables it reads instead of repeating them.
#include <cstring>
#include <string>

#include <emscripten/emscripten.h>
#include <nlohmann/json.hpp>

#include "app/demo/matrices_text.h"
#include "app/demo/scene_flags.h"
#include "app/demo/view_explanations.h"
#include "page_state.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/scene/lesson.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_file.h"

namespace shadelab::web {

// The scene as JSON without its objects: the panel's refresh runs twice a second, and the objects of a
// large scene are megabytes of JSON (10,000 of them: 2 s a call, and the page stopped answering).
nlohmann::json settingsJson(Scene scene) { // by value: DemoState::current's copy moves in
    scene.objects.clear();
    nlohmann::json json = nlohmann::json::parse(sceneToJson(scene));
    json.erase("objects");
    return json;
}

// Object `index`'s material as the scene file spells it.
nlohmann::json materialJson(const Scene& scene, std::size_t index) {
    Scene one; // the defaults, but for that object: its material is written the same in any scene
    one.objects = {scene.objects[index]};
    return nlohmann::json::parse(sceneToJson(one)).at("objects").at(0).at("material");
}

// The lesson being stepped through, as the panel shows it; null for a scene alone.
nlohmann::json lessonJson(const DemoState& s) {
    const Lesson* lesson = s.lesson();
    if (lesson == nullptr) return nullptr;
    const LessonStep& step = lesson->steps[s.step()];
    return {{"title", lesson->title},
            {"step", s.step() + 1},
            {"steps", lesson->steps.size()},
            {"stepTitle", step.title},
            {"caption", step.caption}};
}

// Everything the page shows besides the canvas, but the scenes' objects: title, status, the scene's values
// (as given and as drawn), the shown object's material, the help text, the renderer string, the last
// draw's error, the picture's place in the canvas and the object the material controls edit.
nlohmann::json panelJson() {
    const Page& p = page();
    const DemoState& s = *p.state;
    const Scene& scene = p.state->scene();
    const app::PictureRect picture = pictureRect();
    const auto shown = s.shownObject();
    const nlohmann::json material = shown ? materialJson(scene, *shown) : nullptr;
    return {
        {"title", app::windowTitle(s, p.frameMs)},
        {"status", app::statusText(s)},
        {"help", app::keyHelpText()},
        {"viewHelp", app::viewHelpText()}, // what each view and shading mode shows: the help's second table
        {"showHelp", s.showHelp},
        {"showPanel", s.showPanel},
        {"presenting", s.presenting},
        {"presentation", app::presentationLabel(s)},
        {"matchHighlight", s.matchHighlight},
        {"level", s.level()},
        {"autoLevel", s.autoLevel()},
        {"orthographic", s.orthographic()},
        {"material", s.materialName()},
        {"lights", s.lightsName()},
        {"overlay", toString(s.drawn().overlay)},
        {"view", toString(s.drawn().view)},
        {"viewReport", s.viewReport},
        {"seeing", app::whatYouAreSeeing(s.drawn())}, // one line: what is drawn, in which space, the formula
        {"probe", app::probeText(s)},
        {"matrices", app::matricesPanelText(s.current(picture.width, picture.height), shown)},
        {"settings", settingsJson(scene)}, // the scene less its objects
        {"currentSettings", settingsJson(s.current(picture.width, picture.height))}, // as drawn, likewise
        {"objectCount", scene.objects.size()},
        {"shownMaterial", material},
        {"shownScale",
         shown ? nlohmann::json::array({scene.objects[*shown].scale.x, scene.objects[*shown].scale.y,
                                        scene.objects[*shown].scale.z})
               : nlohmann::json(nullptr)},
        {"sceneName", p.sceneName},
        {"renderer", p.rendererString},
        {"error", p.drawError},
        {"warnings", p.warnings},
        {"picture",
         {{"x", picture.x}, {"y", picture.y}, {"width", picture.width}, {"height", picture.height}}},
        {"editedObject", s.editedObjectNumber()}, // 0: all objects
        {"editedObjectName", s.editedObjectName()},
        {"shownObject", shown ? nlohmann::json(*shown) : nlohmann::json(nullptr)}, // whose material shows
        {"lesson", lessonJson(s)},
    };
}

} // namespace shadelab::web

using namespace shadelab;
using namespace shadelab::web;

extern "C" {

// Panel edits (toon bands, the lights): `json` is the scene's values less its objects (the panel's
// "settings"), which replace the scene's; the objects and the view (orbit, presets) stay.
EMSCRIPTEN_KEEPALIVE const char* shadelab_edit_settings(const char* json) {
    return guarded([&] {
        checkSceneTextSize(std::strlen(json), "panel");
        Scene scene = parseScene(json, "panel");
        scene.objects = page().state->scene().objects;
        validateScene(scene);
        page().state->scene() = std::move(scene);
        requestDraw();
    });
}

// The panel's object chooser: 0 for all objects, i for object i (DemoState::chooseEditedObject).
EMSCRIPTEN_KEEPALIVE void shadelab_choose_object(int number) {
    page().state->chooseEditedObject(number);
}

// A material slider: `json` holds the properties it changed, e.g. {"shininess": 31.6}, for the shown
// material (DemoState::editMaterial: the chosen object's, or that property of every object). The values
// pass through the scene parser at the shown object's place, so a refused one reads as in a scene file.
EMSCRIPTEN_KEEPALIVE const char* shadelab_edit_material(const char* json) {
    return guarded([&] {
        DemoState& state = *page().state;
        const auto shown = state.shownObject();
        if (!shown) return;
        const nlohmann::json changes = nlohmann::json::parse(json);
        nlohmann::json material = materialJson(state.scene(), *shown);
        for (const auto& [key, value] : changes.items()) material[key] = value;
        const Material parsed = parseMaterial(material.dump(), *shown, "panel");
        // Only the properties the slider changed: the others stay exactly as they are (not as printed).
        Material edited = state.scene().objects[*shown].material;
        if (changes.contains("ambient")) edited.ambient = parsed.ambient;
        if (changes.contains("diffuse")) edited.diffuse = parsed.diffuse;
        if (changes.contains("specular")) edited.specular = parsed.specular;
        if (changes.contains("shininess")) edited.shininess = parsed.shininess;
        state.editMaterial(edited);
        requestDraw();
    });
}

// The panel's scale sliders: the shown object's scale (DemoState::editScale), or a message.
EMSCRIPTEN_KEEPALIVE const char* shadelab_edit_scale(double x, double y, double z) {
    return guarded([&] {
        page().state->editScale({x, y, z});
        requestDraw();
    });
}

// The panel's view-volume fields: the drawn projection with a value changed, written as the scene's
// "projection" ({"type": "perspective", "fovy_deg": 30, "near": 1, "far": 9}), read by the scene parser
// (its messages name projection.<field>) and applied by DemoState::editViewVolume; or a message.
EMSCRIPTEN_KEEPALIVE const char* shadelab_edit_view_volume(const char* projectionJson) {
    return guarded([&] {
        const nlohmann::json wrapped = {{"projection", nlohmann::json::parse(projectionJson)}};
        page().state->editViewVolume(parseScene(wrapped.dump(), "view volume").projection);
        requestDraw();
    });
}

EMSCRIPTEN_KEEPALIVE void shadelab_set_match_highlight(int on) {
    page().state->matchHighlight = on != 0;
}

// What the panel's refresh reads, twice a second: everything but the scenes' objects (panelJson).
EMSCRIPTEN_KEEPALIVE const char* shadelab_panel() {
    return give(panelJson().dump());
}

// The panel's values and the whole scenes: as given, as drawn in the picture, and as a capture at 0 × 0
// draws it (S, the tests, scripts/web.sh render).
EMSCRIPTEN_KEEPALIVE const char* shadelab_ui() {
    const DemoState& s = *page().state;
    const app::PictureRect picture = pictureRect();
    nlohmann::json ui = panelJson();
    ui["scene"] = nlohmann::json::parse(sceneToJson(page().state->scene()));
    ui["current"] = nlohmann::json::parse(sceneToJson(s.current(picture.width, picture.height)));
    ui["atImageSize"] = nlohmann::json::parse(sceneToJson(s.current()));
    return give(ui.dump());
}

} // extern "C"
