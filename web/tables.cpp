// The tables the page builds its menus and key map from instead of repeating them (page_core.js `tables`).
#include <map>
#include <string>
#include <string_view>

#include <emscripten/emscripten.h>
#include <nlohmann/json.hpp>

#include "app/demo/demo_state.h"
#include "page_state.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/key_codes.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_flags.h"
#include "shadelab/scene/view.h"

using namespace shadelab;
using namespace shadelab::web;

namespace {

// The label of the key bound to `command` ("1 / F" gives "1"): the window's bindings (demo_keys.cpp).
std::string keyOf(app::Command command) {
    for (const app::KeyBinding& binding : app::keyBindings())
        if (binding.command == command) return std::string(binding.label.substr(0, binding.label.find(' ')));
    return "";
}

// One menu of the page: a vocabulary's values in its table's order, each with its label (the spelling, or
// the lecture's words for it below) and the key that chooses it; `key` is the key that steps through them.
template <class Enum, std::size_t N>
nlohmann::json menu(const std::array<Enum, N>& values, const std::map<Enum, std::string_view>& labels,
                    std::string_view key, const std::map<Enum, app::Command>& keys = {}) {
    nlohmann::json options = nlohmann::json::array();
    for (Enum value : values) {
        const auto label = labels.find(value);
        const auto command = keys.find(value);
        options.push_back({{"value", std::string(toString(value))},
                           {"label", std::string(label != labels.end() ? label->second : toString(value))},
                           {"key", command != keys.end() ? keyOf(command->second) : ""}});
    }
    return {{"key", std::string(key)}, {"options", options}};
}

// The page's menus, from the C++ tables: a value added to a vocabulary shows up in its menu. The labels
// say in the lecture's words what a bare spelling would not; a value without one shows its spelling.
nlohmann::json menus() {
    using app::Command;
    nlohmann::json views = nlohmann::json::array();
    for (const ViewName& view : kViewNames)
        views.push_back({{"value", std::string(view.name)},
                         {"label", std::string(view.name)},
                         {"key", std::string(view.key)},
                         {"help", std::string(view.help)}});
    // The projections O switches between (a frustum comes from a scene file only).
    const std::array projections = {ProjectionType::Perspective, ProjectionType::Orthographic};
    return {
        {"shading",
         menu(kAllShadingModes, {{ShadingMode::Gouraud, "Gouraud"}, {ShadingMode::Phong, "Phong"}}, "",
              {{ShadingMode::Flat, Command::Flat},
               {ShadingMode::Gouraud, Command::Gouraud},
               {ShadingMode::Phong, Command::Phong},
               {ShadingMode::Toon, Command::Toon},
               {ShadingMode::Exact, Command::Exact}})},
        {"lighting",
         menu(kLightingModels, {{LightingModel::Phong, "Phong"}, {LightingModel::BlinnPhong, "Blinn-Phong"}},
              keyOf(Command::ToggleLighting))},
        {"term", menu(kLightingTerms, {{LightingTerm::All, "all (the sum)"}}, keyOf(Command::NextTerm))},
        {"perspective-matrix", menu(kPerspectiveMatrices,
                                    {{PerspectiveMatrix::WebGl, "WebGL (times −1)"},
                                     {PerspectiveMatrix::Unnegated, "unnegated (w < 0: all clipped)"}},
                                    keyOf(Command::TogglePerspectiveMatrix))},
        {"normal-matrix", menu(kNormalMatrixRules,
                               {{NormalMatrixRule::InverseTranspose, "(M⁻¹)ᵀ"},
                                {NormalMatrixRule::Model, "M (wrong, on purpose)"}},
                               keyOf(Command::ToggleNormalMatrix))},
        {"projection", menu(projections, {}, keyOf(Command::ToggleProjection))},
        {"normals", menu(kVertexNormals, {}, keyOf(Command::ToggleNormals))},
        {"overlay", menu(kOverlays, {{Overlay::Normals, "edges + normals"}}, keyOf(Command::ToggleOverlay))},
        {"view-kind", {{"key", ""}, {"options", views}}},
        // The chosen object's shape (a model file's mesh comes from dropping the file: page_model.js).
        {"shape", menu(kShapes, {}, keyOf(Command::ToggleShape))},
    };
}

} // namespace

extern "C" {

// The tables the page reads rather than repeats: the flags' names (sceneFlags, the command line's
// table), the highest subdivision level, the longest scene text (web/driver.py reads no more of its
// input), and the browser's key names (KeyboardEvent.key, and .code for the
// keypad) as the GLFW codes of the window's bindings (demo_keys.cpp; a printable key is its upper-case
// ASCII, which the page forms itself; '+' is Shift + '=' as in the window); and the panel's menus, by the
// id of their <select> (page_menus.js fills them).
EMSCRIPTEN_KEEPALIVE const char* shadelab_tables() {
    nlohmann::json flags = nlohmann::json::array();
    for (const SceneFlag& flag : sceneFlags()) flags.push_back(std::string(flag.name));
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
        {"flags", flags},
        {"maxSubdivisions", kMaxSubdivisions},
        {"maxSceneBytes", kMaxSceneBytes},
        {"keys", keys},
        {"codes", codes},
        {"menus",
         menus()}}.dump());
}

} // extern "C"
