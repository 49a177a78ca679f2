// The demo's key bindings, the one spelling of every key that the window, the help overlay, --help and
// the README table share.
#include "app/demo/demo_state.h"

#include <algorithm>

#include "shadelab/key_codes.h"

namespace shadelab::app {
namespace {

constexpr int kKeyMinus = '-', kKeyEqual = '='; // '+' is Shift + '=' on most layouts

// A view's key, its label and its help line, from the views' one table (view.h kViewNames).
KeyBinding viewKey(ViewKind kind, Command command) {
    const ViewName& view = viewNamed(kind);
    return {{int(view.key.front())}, view.key, view.help, command};
}

const std::vector<KeyBinding>& bindings() {
    static const std::vector<KeyBinding> kBindings = {
        {{'1', 'F'}, "1 / F", "flat shading", Command::Flat},
        {{'2', 'G'}, "2 / G", "Gouraud shading", Command::Gouraud},
        {{'3', 'P'}, "3 / P", "Phong shading", Command::Phong},
        {{'4', 'T'}, "4 / T", "toon shading", Command::Toon},
        {{'5', 'X'}, "5 / X", "exact: the sphere ray-cast per pixel", Command::Exact},
        viewKey(ViewKind::Error, Command::ToggleErrorView),
        viewKey(ViewKind::Split, Command::ToggleSplitView),
        viewKey(ViewKind::Profile, Command::ToggleProfileView),
        viewKey(ViewKind::Outside, Command::ToggleOutsideView),
        viewKey(ViewKind::Ndc, Command::ToggleNdcView),
        {{'B'}, "B", "Phong <-> Blinn-Phong lighting", Command::ToggleLighting},
        {{'K'}, "K", "term: all, then ambient, diffuse, specular alone", Command::NextTerm},
        {{'U'},
         "U",
         "perspective matrix: WebGL's (times -1) <-> unnegated, where everything is clipped",
         Command::TogglePerspectiveMatrix},
        {{'J'},
         "J",
         "normals by (M^-1)^T <-> by M (the wrong matrix, on purpose)",
         Command::ToggleNormalMatrix},
        {{kKeyEqual, kKeyKeypadAdd}, "+", "subdivision level up", Command::LevelUp},
        {{kKeyMinus, kKeyKeypadSubtract}, "-", "subdivision level down", Command::LevelDown},
        {{'A'}, "A", "automatic level: silhouette error < tolerance_px", Command::AutoLevel},
        {{'O'}, "O", "perspective <-> orthographic", Command::ToggleProjection},
        {{'N'}, "N", "averaged <-> exact vertex normals", Command::ToggleNormals},
        {{'W'},
         "W",
         "overlay: wireframe, then face and vertex normals, then the lights' markers, then none",
         Command::ToggleOverlay},
        {{'D'}, "D", "shape of the edited object: sphere <-> Newell's teapot", Command::ToggleShape},
        {{'M'}, "M", "next material preset", Command::NextMaterial},
        {{'L'}, "L", "next light set-up", Command::NextLights},
        {{'R'}, "R", "reset the view (in a lesson: the step as written)", Command::ResetView},
        {{'S'}, "S", "save a screenshot (PNG + scene JSON)", Command::Screenshot},
        {{'C'}, "C", "show / hide the control panel", Command::TogglePanel},
        {{'H', kKeyF1}, "H / F1", "show / hide this help", Command::ToggleHelp},
        {{kKeyF2}, "F2", "presentation label: mode, lighting, level, exponent", Command::TogglePresentation},
        {{kKeyF11}, "F11", "full screen", Command::ToggleFullScreen},
        {{kKeyPageDown, kKeySpace, kKeyRight},
         "PgDn / Space / Right",
         "lesson: next step",
         Command::NextStep},
        {{kKeyPageUp, kKeyBackspace, kKeyLeft},
         "PgUp / Backspace / Left",
         "lesson: previous step",
         Command::PreviousStep},
        {{kKeyHome}, "Home", "lesson: first step", Command::FirstStep},
        {{kKeyEnd}, "End", "lesson: last step", Command::LastStep},
        {{kKeyEscape}, "Esc", "quit", Command::Quit},
    };
    return kBindings;
}

} // namespace

std::span<const KeyBinding> keyBindings() {
    return bindings();
}

std::optional<Command> commandForKey(int key) {
    for (const KeyBinding& binding : bindings())
        if (std::find(binding.keys.begin(), binding.keys.end(), key) != binding.keys.end())
            return binding.command;
    return std::nullopt;
}

std::vector<std::pair<std::string, std::string>> keyHelpRows() {
    std::vector<std::pair<std::string, std::string>> rows;
    for (const KeyBinding& b : bindings()) rows.emplace_back(b.label, b.action);
    rows.emplace_back("drag", "orbit around the target");
    rows.emplace_back("wheel", "zoom");
    rows.emplace_back("right-drag", "move the light around the target");
    rows.emplace_back("click", "probe a surface point: l, n, v, r/h and the terms, mode vs exact");
    return rows;
}

std::string keyHelpText() {
    std::string text;
    for (auto [keys, action] : keyHelpRows()) {
        keys.resize(std::max<std::size_t>(keys.size(), 8), ' ');
        text.append(keys).append(" ").append(action).append("\n");
    }
    return text;
}

} // namespace shadelab::app
