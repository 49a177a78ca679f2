// What the page's two C++ files share (main.cpp: the canvas, loading, keys, the mouse and captures;
// panel.cpp: the control panel's values and edits): the page's state and the helpers of every shadelab_*
// entry point.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <GLFW/glfw3.h>

#include "app/demo/demo_draw.h"
#include "app/demo/demo_state.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/image/image.h"

namespace shadelab::web {

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

inline Page& page() {
    static Page p;
    return p;
}

inline const char* give(std::string text) {
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

// Where the picture goes in the canvas (canvas pixels from its top left): the largest rectangle of the
// scene's aspect, centred, as the window places it beside its panel (main.cpp).
app::PictureRect pictureRect();
// Asks for one animation frame to draw the canvas (main.cpp).
void requestDraw();

} // namespace shadelab::web
