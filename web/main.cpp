// The browser's shadelab: the native demo's state, keys and renderer behind a WebGL 2 canvas. Emscripten's
// GLFW makes the context (an OpenGL ES 3.0 context to the renderer, DESIGN §7); the page (page.js) owns the
// canvas size, the keyboard, the mouse and the HTML control panel, and talks to the program only through the
// shadelab_* functions below and in panel.cpp (the panel's values and edits; page_state.h is what the two
// share). Every function that takes input returns "" or the error message, exactly as
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
#include "page_state.h"
#include "shadelab/errors.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/gl/loader.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/image/image.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/lesson.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_flags.h"

namespace shadelab::web {

using app::DemoState;

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

// Where the last frame drew the picture (above a presented lesson's band), what the pointer points in.
static app::PictureRect shownPicture() {
    const app::PictureRect& shown = page().picture.shown();
    return shown.width > 0 ? shown : pictureRect();
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

} // namespace shadelab::web

using namespace shadelab;
using namespace shadelab::web;

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
        state->setPresenting(page().state->presenting()); // the page's own setting, as a step keeps it
        state->setShowPanel(page().state->showPanel());
        state->openLesson(std::make_shared<const Lesson>(std::move(lesson)));
        page().state = std::move(state);
        page().sceneName = name;
        requestDraw();
    });
}

// The command-line flags applied to the shown scene through the same parser (scene/scene_flags.h):
// `flags` is a JSON object such as {"shading": "flat", "size": "256x256"}.
EMSCRIPTEN_KEEPALIVE const char* shadelab_apply_flags(const char* flags) {
    return guarded([&] {
        const nlohmann::json parsed = nlohmann::json::parse(flags);
        SceneOverrides o;
        for (const auto& [name, value] : parsed.items()) {
            std::optional<std::string>* into = overrideNamed(o, name);
            if (!into)
                throw InputError("unknown flag --" + printable(name) + "; the flags are " + flagList());
            *into = value.get<std::string>();
        }
        const Scene scene = applyOverrides(std::as_const(*page().state).scene(), o, page().sceneName);
        page().state = std::make_unique<DemoState>(scene);
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
    const app::PictureRect picture = shownPicture();
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
        const app::PictureRect picture = shownPicture();
        if (!picture.contains(x, y)) return;
        page().state->probeAt(x - picture.x, y - picture.y);
        requestDraw();
    });
}

EMSCRIPTEN_KEEPALIVE void shadelab_zoom(double steps) {
    page().state->zoom(steps);
    requestDraw();
}

// The canvas was resized (or must be redrawn for another reason).
EMSCRIPTEN_KEEPALIVE void shadelab_redraw() {
    requestDraw();
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
