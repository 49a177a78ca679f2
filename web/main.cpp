// The browser's shadelab: the native demo's state, keys and renderer behind a WebGL 2 canvas. Emscripten's
// GLFW makes the context (an OpenGL ES 3.0 context to the renderer, DESIGN §7); the page (page.js) owns the
// canvas size, the keyboard, the mouse and the HTML control panel, and talks to this file only through the
// shadelab_* functions below. Every function that takes input returns "" or the error message, exactly as
// the command line words it, so the page never shows a blank canvas for a bad scene.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#define GLFW_INCLUDE_NONE // GL comes from the one loader (gl/loader.h), never from the system headers
#include <GLFW/glfw3.h>
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
#include <nlohmann/json.hpp>

#include "app/demo/demo_draw.h"
#include "app/demo/demo_state.h"
#include "app/demo/matrices_text.h"
#include "app/demo/scene_flags.h"
#include "shadelab/context/window.h"
#include "shadelab/errors.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/gl/loader.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/image/image.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/lesson.h"
#include "shadelab/scene/scene.h"

namespace {

using namespace shadelab;
using app::DemoState;

struct Page {
    GLFWwindow* window = nullptr;
    std::unique_ptr<gl::Renderer> renderer;
    std::unique_ptr<DemoState> state;
    app::FramedPicture picture; // the scene's framing in the canvas, bars around it (as the window)
    std::string rendererString;
    std::string sceneName = "defaults";
    bool framePending = false;         // an animation frame is requested (requestDraw)
    double frameMs = 0;                // the last draw, glFinish-synchronized
    std::string drawError;             // why the last draw failed, shown on the page
    std::vector<std::string> warnings; // the loaded scene's, as the command line words them
    Image capture;                     // shadelab_capture's pixels, alive until the next capture
    ImageF captureFloat;               // shadelab_capture_float's
    std::string text;                  // the returned string of the last shadelab_* call
};

Page& page() {
    static Page p;
    return p;
}

const char* give(std::string text) {
    page().text = std::move(text);
    return page().text.c_str();
}

// Runs `f`; "" on success, else the message (InputError and RuntimeError alike: the page shows it).
template <typename F> const char* guarded(F&& f) {
    try {
        f();
        return give("");
    } catch (const std::exception& e) {
        return give(e.what());
    }
}

void canvasSize(int& width, int& height) {
    width = height = 0;
    emscripten_get_canvas_element_size("#canvas", &width, &height);
}

// Where the picture goes in the canvas (canvas pixels from its top left): the largest rectangle of the
// scene's aspect, centred, as the window places it beside its panel, so the page frames the scene as
// `render` does.
app::PictureRect pictureRect() {
    int width = 0, height = 0;
    canvasSize(width, height);
    return app::fitPicture(page().state->sceneWidth(), page().state->sceneHeight(), width, height);
}

void frame() {
    Page& p = page();
    int width = 0, height = 0;
    canvasSize(width, height);
    if (width <= 0 || height <= 0) return;
    try {
        const double start = emscripten_get_now();
        p.picture.draw(*p.renderer, *p.state, pictureRect(), width, height);
        gl::finish();
        p.frameMs = emscripten_get_now() - start;
        p.drawError.clear();
    } catch (const std::exception& e) {
        p.drawError = e.what();
    }
}

// The canvas is drawn on demand: every change asks for one animation frame, and an unchanged picture stays
// on the canvas with no frame requested at all. (A main loop that ran every frame kept the page busy doing
// nothing: in headless Chromium an idle page took 22 % of a core, 7 points of it this loop.)
void requestDraw() {
    Page& p = page();
    if (p.framePending) return;
    p.framePending = true;
    emscripten_request_animation_frame(
        [](double, void*) -> EM_BOOL {
            page().framePending = false;
            frame();
            return EM_FALSE; // one frame, not a loop
        },
        nullptr);
}

// Draws the canvas's picture, at width × height (the scene's image size for 0 × 0), into a framebuffer of
// the program's own and reads it back, rows top first (the same read-back as `shadelab render`). Returns
// false with the message in the ui's "error" on failure.
template <typename Read> bool captureInto(int width, int height, gl::ColorFormat format, Read read) {
    Page& p = page();
    try {
        const Scene scene = p.state->current(width, height);
        const gl::RenderTarget target(scene.width, scene.height, format, gl::depthFormatFor(scene.depth));
        target.bind();
        p.renderer->render(scene, scene.width, scene.height);
        read(target);
        gl::bindDefaultFramebuffer();
        requestDraw();
        p.drawError.clear();
        return true;
    } catch (const std::exception& e) {
        gl::bindDefaultFramebuffer();
        p.drawError = e.what();
        return false;
    }
}

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

} // namespace

extern "C" {

// Replaces the shown scene with `json` (named `name` in messages, as the command line names the file).
EMSCRIPTEN_KEEPALIVE const char* shadelab_load_scene(const char* json, const char* name) {
    return guarded([&] {
        checkSceneTextSize(std::strlen(json), name); // the command line's 16 MiB, with its message
        Scene scene = parseScene(json, name);
        validateScene(scene);
        // What the command line prints as "shadelab: warning: FILE: ...", shown on the page.
        page().warnings.clear();
        for (const std::string& warning : sceneWarnings(scene))
            page().warnings.push_back(std::string(name) + ": " + warning);
        page().state = std::make_unique<DemoState>(scene);
        page().sceneName = name;
        requestDraw();
    });
}

// Opens a lesson at its first step: `json` its text (named `name` in messages), `files` a JSON object of the
// scene files its steps name, each path as the lesson writes it → the text the page fetched (or was given
// beside the lesson), or null where it could not get it; the lesson parser then names the step and file.
EMSCRIPTEN_KEEPALIVE const char* shadelab_load_lesson(const char* json, const char* name, const char* files) {
    return guarded([&] {
        checkSceneTextSize(std::strlen(json), name);
        const nlohmann::json texts = nlohmann::json::parse(files);
        Lesson lesson = parseLesson(json, name, [&texts](const std::string& path) {
            const auto found = texts.find(path);
            if (found == texts.end() || !found->is_string())
                throw InputError("the page could not fetch it beside the lesson (open the lesson by its URL, "
                                 "or pick or drop its scene files together with it)");
            const std::string& text = found->get_ref<const std::string&>();
            checkSceneTextSize(text.size(), path);
            return text;
        });
        page().warnings.clear();
        for (std::size_t i = 0; i < lesson.steps.size(); ++i)
            for (const std::string& warning : sceneWarnings(lesson.steps[i].scene))
                page().warnings.push_back(std::string(name) + ": steps[" + std::to_string(i) +
                                          "]: " + warning);
        auto state = std::make_unique<DemoState>(lesson.steps.front().scene);
        state->presenting = page().state->presenting; // the page's own setting, as a step keeps it
        state->showPanel = page().state->showPanel;
        state->openLesson(std::make_shared<const Lesson>(std::move(lesson)));
        page().state = std::move(state);
        page().sceneName = name;
        requestDraw();
    });
}

// The command-line flags applied to the shown scene through the same parser (app/demo/scene_flags.h):
// `flags` is a JSON object such as {"shading": "flat", "size": "256x256"}.
EMSCRIPTEN_KEEPALIVE const char* shadelab_apply_flags(const char* flags) {
    return guarded([&] {
        const nlohmann::json parsed = nlohmann::json::parse(flags);
        app::SceneOverrides o;
        for (const auto& [name, value] : parsed.items()) {
            std::optional<std::string>* into = app::overrideNamed(o, name);
            if (!into)
                throw InputError("unknown flag --" + printable(name) + "; the flags are " + app::flagList());
            *into = value.get<std::string>();
        }
        const Scene scene = app::applyOverrides(page().state->scene(), o, page().sceneName);
        page().state = std::make_unique<DemoState>(scene);
        requestDraw();
    });
}

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

// A key by its GLFW code (printable keys: their upper-case ASCII). 0: no binding; 1: applied; 2: the page
// saves a screenshot (S); 3: quit (Esc), which a page cannot do; 4: full screen (F11), which the page does.
EMSCRIPTEN_KEEPALIVE int shadelab_key(int key) {
    const auto command = app::commandForKey(key);
    if (!command) return 0;
    if (page().state->apply(*command)) {
        requestDraw();
        return 1;
    }
    if (*command == app::Command::ToggleFullScreen) return 4;
    return *command == app::Command::Screenshot ? 2 : 3;
}

EMSCRIPTEN_KEEPALIVE void shadelab_drag(double dx, double dy) {
    page().state->drag(dx, dy);
    requestDraw();
}

// The pointer at canvas pixel (x, y), top left origin, on every move and left-button change: the profile
// view's row, the split view's divider (DemoState::pointer, in the picture's pixels, as in the window).
EMSCRIPTEN_KEEPALIVE void shadelab_pointer(double x, double y, int leftHeld) {
    const app::PictureRect picture = pictureRect();
    page().state->pointer(x - picture.x, y - picture.y, leftHeld != 0);
    requestDraw();
}

// Right-drag (or Shift + drag): the first light that is not ambient orbits the target.
EMSCRIPTEN_KEEPALIVE void shadelab_drag_light(double dx, double dy) {
    page().state->dragLight(dx, dy);
    requestDraw();
}

// A click at canvas pixel (x, y), top left origin: probe the surface point there (the background: no
// probe), which the panel then edits; a click on a bar changes nothing, as in the window.
EMSCRIPTEN_KEEPALIVE const char* shadelab_probe(double x, double y) {
    return guarded([&] {
        const app::PictureRect picture = pictureRect();
        if (!picture.contains(x, y)) return;
        page().state->probeAt(x - picture.x, y - picture.y);
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

EMSCRIPTEN_KEEPALIVE void shadelab_zoom(double steps) {
    page().state->zoom(steps);
    requestDraw();
}

EMSCRIPTEN_KEEPALIVE void shadelab_set_match_highlight(int on) {
    page().state->matchHighlight = on != 0;
}

// The canvas was resized (or must be redrawn for another reason).
EMSCRIPTEN_KEEPALIVE void shadelab_redraw() {
    requestDraw();
}

// The tables the page reads rather than repeats: the flags' names (app::sceneFlags, the command line's
// table), the highest subdivision level, and the browser's key names (KeyboardEvent.key, and .code for the
// keypad) as the GLFW codes of the window's bindings (demo_keys.cpp; a printable key is its upper-case
// ASCII, which the page forms itself; '+' is Shift + '=' as in the window).
EMSCRIPTEN_KEEPALIVE const char* shadelab_tables() {
    nlohmann::json flags = nlohmann::json::array();
    for (const app::SceneFlag& flag : app::sceneFlags()) flags.push_back(std::string(flag.name));
    const nlohmann::json keys = {{"Escape", kKeyEscape},
                                 {"F1", kKeyF1},
                                 {"F2", kKeyF2},
                                 {"F11", kKeyF11},
                                 {"PageDown", kKeyPageDown},
                                 {"PageUp", kKeyPageUp},
                                 {"Home", kKeyHome},
                                 {"End", kKeyEnd},
                                 {"ArrowRight", kKeyRight},
                                 {"ArrowLeft", kKeyLeft},
                                 {"Backspace", kKeyBackspace},
                                 {" ", kKeySpace},
                                 {"+", int('=')},
                                 {"=", int('=')},
                                 {"-", int('-')},
                                 {"_", int('-')}};
    const nlohmann::json codes = {{"NumpadAdd", kKeyKeypadAdd}, {"NumpadSubtract", kKeyKeypadSubtract}};
    return give(nlohmann::json{
        {"flags", flags}, {"maxSubdivisions", kMaxSubdivisions}, {"keys", keys}, {"codes", codes}}
                    .dump());
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

// 8-bit RGBA, alpha = coverage; null on failure.
EMSCRIPTEN_KEEPALIVE const std::uint8_t* shadelab_capture(int width, int height) {
    Page& p = page();
    const bool ok = captureInto(width, height, gl::ColorFormat::Rgba8,
                                [&](const gl::RenderTarget& target) { p.capture = target.readRgba8(); });
    return ok ? p.capture.rgba.data() : nullptr;
}

// Float RGBA through an RGBA32F target (EXT_color_buffer_float), unrounded; null on failure.
EMSCRIPTEN_KEEPALIVE const float* shadelab_capture_float(int width, int height) {
    Page& p = page();
    const bool ok = captureInto(width, height, gl::ColorFormat::Rgba32F, [&](const gl::RenderTarget& target) {
        p.captureFloat = target.readFloat();
        p.capture.width = p.captureFloat.width;
        p.capture.height = p.captureFloat.height;
    });
    return ok ? p.captureFloat.rgba.data() : nullptr;
}

EMSCRIPTEN_KEEPALIVE int shadelab_capture_width() {
    return page().capture.width;
}
EMSCRIPTEN_KEEPALIVE int shadelab_capture_height() {
    return page().capture.height;
}

} // extern "C"

int main() {
    Page& p = page();
    if (!glfwInit()) {
        std::fprintf(stderr, "shadelab: glfwInit failed\n");
        return 1;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    // An opaque canvas: the picture's alpha is coverage (0 on the background), and a canvas with alpha
    // blends such pixels with the page behind it, so the background would not be `render`'s.
    glfwWindowHint(GLFW_ALPHA_BITS, 0);
    int width = 0, height = 0;
    canvasSize(width, height);
    p.window =
        glfwCreateWindow(width > 0 ? width : 640, height > 0 ? height : 480, "shadelab", nullptr, nullptr);
    if (!p.window) { // page.js checked for WebGL 2 before starting this; say so anyway
        EM_ASM(shadelabFatal("WebGL 2 is not available in this browser: shadelab needs it to draw."));
        return 1;
    }
    glfwMakeContextCurrent(p.window);
    try {
        gl::loadGl(glfwGetProcAddress, "webgl", Api::Gles);
        p.rendererString = gl::rendererString();
        p.renderer = std::make_unique<gl::Renderer>();
        p.renderer->setSpecialization(gl::Specialization::Lights); // as the window: sliders recompile nothing
        p.state = std::make_unique<DemoState>(Scene{});
    } catch (const std::exception& e) {
        EM_ASM({ shadelabFatal(UTF8ToString($0)); }, e.what());
        return 1;
    }
    EM_ASM(shadelabStarted());
    requestDraw();
    return 0;
}
