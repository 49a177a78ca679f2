// The page's control panel: what it shows (panelJson, twice a second), the edits its controls make, and
// the tables it reads instead of repeating them.
#include <optional>
#include <string>

#include <emscripten/emscripten.h>
#include <nlohmann/json.hpp>

#include "app/demo/matrices_text.h"
#include "app/demo/scene_setters.h"
#include "app/demo/view_explanations.h"
#include "page_state.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/scene/lesson.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_file.h"
#include "shadelab/scene/scene_flags.h"

namespace shadelab::web {

// The scene as JSON without its objects: the panel's refresh runs twice a second, and the objects of a
// large scene are megabytes of JSON (10,000 of them: 2 s a call, and the page stopped answering).
nlohmann::json settingsJson(const Scene& given) {
    Scene scene = given; // twice a second: a copy of the objects costs far less than their JSON would
    scene.objects.clear();
    nlohmann::json json = nlohmann::json::parse(sceneToJson(scene));
    json.erase("objects");
    return json;
}

// Object `index`'s material as the scene file spells it.
nlohmann::json materialJson(const Scene& scene, std::size_t index) {
    Scene one; // the defaults, but for that object: its material is written the same in any scene
    one.objects = {scene.objects[index]};
    one.objects[0].materialGiven = true; // a mesh object's material from its file is written only when asked
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
    const Scene& scene = s.scene();
    const app::PictureRect picture = pictureRect();
    // The scene as drawn in the picture: the kept one when it was drawn at the picture's size (presenting a
    // lesson, the picture above the band is smaller), else made for it.
    const Scene& drawn = s.drawn();
    std::optional<Scene> sized;
    if (drawn.width != picture.width || drawn.height != picture.height)
        sized = s.current(picture.width, picture.height);
    const Scene& current = sized ? *sized : drawn;
    const auto shown = s.shownObject();
    const nlohmann::json material = shown ? materialJson(scene, *shown) : nullptr;
    return {
        {"title", app::windowTitle(s, p.frameMs)},
        {"status", app::statusText(s)},
        {"help", app::keyHelpText()},
        {"viewHelp", app::viewHelpText()}, // what each view and shading mode shows: the help's second table
        {"showHelp", s.showHelp()},
        {"showPanel", s.showPanel()},
        {"presenting", s.presenting()},
        {"presentation", app::presentationLabel(s)},
        {"matchHighlight", s.matchHighlight()},
        {"level", s.level()},
        {"autoLevel", s.autoLevel()},
        {"orthographic", s.orthographic()},
        {"material", s.materialName()},
        {"lights", s.lightsName()},
        {"overlay", toString(drawn.overlay)},
        {"view", toString(drawn.view)},
        {"viewReport", s.viewReport()},
        {"seeing", app::whatYouAreSeeing(drawn)}, // one line: what is drawn, in which space, the formula
        {"probe", app::probeText(s)},
        {"matrices", app::matricesPanelText(current, shown)},
        {"settings", settingsJson(scene)},          // the scene less its objects
        {"currentSettings", settingsJson(current)}, // as drawn, likewise
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
        // Its shape, and for a mesh object the model file as the scene names it (the shape menu's row).
        {"shownShape", shown ? nlohmann::json(std::string(toString(scene.objects[*shown].shape)))
                             : nlohmann::json(nullptr)},
        {"shownMesh", shown ? nlohmann::json(scene.objects[*shown].mesh) : nlohmann::json(nullptr)},
        {"lesson", lessonJson(s)},
    };
}

} // namespace shadelab::web

using namespace shadelab;
using namespace shadelab::web;

extern "C" {

// Every control of the page's panel: the value `name` set to `text` through the setter the window's panel
// uses too (app/demo/scene_setters.h), e.g. ("lighting", "phong"), ("material.shininess", "31.6"),
// ("lights[0].cutoff_deg", "20"); "" when set, else the refusal, in the words of the scene file's check.
EMSCRIPTEN_KEEPALIVE const char* shadelab_set(const char* name, const char* text) {
    std::string refusal = app::setValue(*page().state, name, text);
    if (refusal.empty()) requestDraw();
    return give(std::move(refusal));
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
    ui["scene"] = nlohmann::json::parse(sceneToJson(s.scene()));
    ui["current"] = nlohmann::json::parse(sceneToJson(s.current(picture.width, picture.height)));
    ui["atImageSize"] = nlohmann::json::parse(sceneToJson(s.current()));
    return give(ui.dump());
}

} // extern "C"
