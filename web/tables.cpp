// The tables the page builds its menus and key map from instead of repeating them (page_core.js `tables`).
#include <string>

#include <emscripten/emscripten.h>
#include <nlohmann/json.hpp>

#include "app/demo/scene_flags.h"
#include "page_state.h"
#include "shadelab/context/window.h"
#include "shadelab/geometry/sphere.h"

using namespace shadelab;
using namespace shadelab::web;

extern "C" {

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

} // extern "C"
