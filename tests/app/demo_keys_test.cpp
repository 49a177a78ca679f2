// The demo's keys (src/app/demo/demo_state.h) against docs/students.md "The demo window" and GLFW's key
// codes: every key the README lists gives its command, no key is bound twice, every command has one binding
// and the help text shows each; what apply() does with the shading keys, the window's own commands and the
// toggles (H, C, N, W). Expected values come from the README and GLFW, not from demo_state.cpp.
#include "app/demo/demo_state.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h> // only for the GLFW_KEY_* constants: the window reports GLFW key codes
#include <gtest/gtest.h>

#include "demo_test_support.h"
#include "shadelab/key_codes.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app {
namespace {

using namespace demo_test;

// ---- keys ----

// The key codes GLFW reports, and the command README's key table gives each.
const std::vector<std::pair<int, Command>>& issueKeys() {
    static const std::vector<std::pair<int, Command>> kKeys = {
        {GLFW_KEY_1, Command::Flat},
        {GLFW_KEY_F, Command::Flat},
        {GLFW_KEY_2, Command::Gouraud},
        {GLFW_KEY_G, Command::Gouraud},
        {GLFW_KEY_3, Command::Phong},
        {GLFW_KEY_P, Command::Phong},
        {GLFW_KEY_4, Command::Toon},
        {GLFW_KEY_T, Command::Toon},
        {GLFW_KEY_5, Command::Exact},
        {GLFW_KEY_X, Command::Exact},
        {GLFW_KEY_B, Command::ToggleLighting},
        {GLFW_KEY_EQUAL, Command::LevelUp}, // '+' is Shift + '=' (US layout); GLFW reports the key, '='
        {GLFW_KEY_KP_ADD, Command::LevelUp},
        {GLFW_KEY_MINUS, Command::LevelDown},
        {GLFW_KEY_KP_SUBTRACT, Command::LevelDown},
        {GLFW_KEY_O, Command::ToggleProjection},
        {GLFW_KEY_N, Command::ToggleNormals},
        {GLFW_KEY_M, Command::NextMaterial},
        {GLFW_KEY_L, Command::NextLights},
        {GLFW_KEY_R, Command::ResetView},
        {GLFW_KEY_S, Command::Screenshot},
        {GLFW_KEY_H, Command::ToggleHelp},
        {GLFW_KEY_F1, Command::ToggleHelp},
        {GLFW_KEY_ESCAPE, Command::Quit},
        {GLFW_KEY_C, Command::TogglePanel},
        {GLFW_KEY_F2, Command::TogglePresentation}, // Presentation mode
        {GLFW_KEY_W, Command::ToggleOverlay},       // wireframe and normals overlay
        {GLFW_KEY_D, Command::ToggleShape},         // the edited object: sphere or teapot (DESIGN §1)
        {GLFW_KEY_F11, Command::ToggleFullScreen},
        // A lesson's steps.
        {GLFW_KEY_PAGE_DOWN, Command::NextStep},
        {GLFW_KEY_SPACE, Command::NextStep},
        {GLFW_KEY_RIGHT, Command::NextStep},
        {GLFW_KEY_PAGE_UP, Command::PreviousStep},
        {GLFW_KEY_BACKSPACE, Command::PreviousStep},
        {GLFW_KEY_LEFT, Command::PreviousStep},
        {GLFW_KEY_HOME, Command::FirstStep},
        {GLFW_KEY_END, Command::LastStep},
    };
    return kKeys;
}

TEST(DemoKeys, WindowKeyConstantsAreGlfwKeyCodes) {
    EXPECT_EQ(kKeyEscape, GLFW_KEY_ESCAPE);
    EXPECT_EQ(kKeyF1, GLFW_KEY_F1);
    EXPECT_EQ(kKeyF2, GLFW_KEY_F2);
    EXPECT_EQ(kKeyF11, GLFW_KEY_F11);
    EXPECT_EQ(kKeyKeypadSubtract, GLFW_KEY_KP_SUBTRACT);
    EXPECT_EQ(kKeyKeypadAdd, GLFW_KEY_KP_ADD);
    EXPECT_EQ(kKeyPageDown, GLFW_KEY_PAGE_DOWN);
    EXPECT_EQ(kKeyEnd, GLFW_KEY_END);
}

TEST(DemoKeys, EveryKeyTheIssueListsMapsToItsCommand) {
    for (const auto& [key, command] : issueKeys()) {
        const auto got = commandForKey(key);
        ASSERT_TRUE(got.has_value()) << "key code " << key << " is not bound";
        EXPECT_EQ(*got, command) << "key code " << key;
    }
}

TEST(DemoKeys, EveryBindingsKeysMapToItsCommand) {
    ASSERT_FALSE(keyBindings().empty());
    for (const KeyBinding& binding : keyBindings()) {
        EXPECT_FALSE(binding.keys.empty()) << binding.label;
        for (int key : binding.keys) {
            const auto got = commandForKey(key);
            ASSERT_TRUE(got.has_value()) << binding.label << ": key " << key;
            EXPECT_EQ(*got, binding.command) << binding.label << ": key " << key;
        }
    }
}

TEST(DemoKeys, NoKeyIsBoundTwice) {
    std::map<int, std::string> seen;
    for (const KeyBinding& binding : keyBindings())
        for (int key : binding.keys) {
            const auto [it, inserted] = seen.emplace(key, std::string(binding.label));
            EXPECT_TRUE(inserted) << "key " << key << " is bound by both '" << it->second << "' and '"
                                  << binding.label << "'";
        }
}

TEST(DemoKeys, EveryCommandHasExactlyOneBinding) {
    for (Command command : kAllCommands) {
        const auto count = std::count_if(keyBindings().begin(), keyBindings().end(),
                                         [&](const KeyBinding& b) { return b.command == command; });
        EXPECT_EQ(count, 1) << "command " << int(command);
    }
}

TEST(DemoKeys, UnboundKeysGiveNoCommand) {
    for (int key : {GLFW_KEY_Z, GLFW_KEY_6, GLFW_KEY_F3, GLFW_KEY_ENTER, GLFW_KEY_UNKNOWN, 0})
        EXPECT_FALSE(commandForKey(key).has_value()) << "key " << key;
}

TEST(DemoKeys, HelpTextListsEveryBindingsLabelAndActionOnOneLine) {
    const std::string help = keyHelpText();
    std::vector<std::string> lines;
    std::istringstream in(help);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    for (const KeyBinding& binding : keyBindings()) {
        ASSERT_FALSE(binding.label.empty());
        ASSERT_FALSE(binding.action.empty());
        const bool found = std::any_of(lines.begin(), lines.end(), [&](const std::string& line) {
            return line.find(binding.label) != std::string::npos &&
                   line.find(binding.action) != std::string::npos;
        });
        EXPECT_TRUE(found) << "no help line has both '" << binding.label << "' and '" << binding.action
                           << "':\n"
                           << help;
    }
    // The mouse is part of "every key in the window" too.
    EXPECT_NE(help.find("drag"), std::string::npos) << help;
    EXPECT_NE(help.find("wheel"), std::string::npos) << help;
}

TEST(DemoKeys, HelpLabelsNameTheIssuesKeys) {
    // The labels are what the overlay, --help and the README show: each listed key appears in some label.
    std::string labels;
    for (const KeyBinding& binding : keyBindings()) labels += std::string(binding.label) + " | ";
    for (const char* key : {"1", "2", "3", "4", "F", "G", "P",  "T",   "B", "+",  "-",  "O",
                            "N", "M", "L", "R", "S", "H", "F1", "Esc", "C", "F2", "F11"})
        EXPECT_NE(labels.find(key), std::string::npos) << key << " not in labels: " << labels;
}

// ---- apply(): modes and toggles ----

TEST(DemoApply, DigitsSetTheShadingModes) {
    DemoState state(Scene{});
    const std::pair<Command, ShadingMode> cases[] = {
        {Command::Flat, ShadingMode::Flat},       {Command::Toon, ShadingMode::Toon},
        {Command::Gouraud, ShadingMode::Gouraud}, {Command::Phong, ShadingMode::Phong},
        {Command::Exact, ShadingMode::Exact},     {Command::Flat, ShadingMode::Flat}};
    for (const auto& [command, mode] : cases) {
        EXPECT_TRUE(state.apply(command));
        EXPECT_EQ(state.current().shading, mode);
        EXPECT_EQ(state.current().lighting, LightingModel::BlinnPhong)
            << "a shading key changed the lighting";
    }
    for (const auto& [key, command] : issueKeys()) {
        if (command != Command::Gouraud) continue;
        state.apply(*commandForKey(key));
        EXPECT_EQ(state.current().shading, ShadingMode::Gouraud);
    }
}

TEST(DemoApply, WindowCommandsReturnFalseAndChangeNothing) {
    DemoState state(threeObjectScene());
    const std::string before = sceneToJson(state.current());
    EXPECT_FALSE(state.apply(Command::Screenshot));
    EXPECT_FALSE(state.apply(Command::Quit));
    EXPECT_EQ(sceneToJson(state.current()), before);
}

TEST(DemoApply, HelpAndPanelToggle) {
    DemoState state(Scene{});
    const bool help = state.showHelp(), panel = state.showPanel();
    state.apply(Command::ToggleHelp);
    state.apply(Command::TogglePanel);
    EXPECT_NE(state.showHelp(), help);
    EXPECT_NE(state.showPanel(), panel);
    state.apply(Command::ToggleHelp);
    state.apply(Command::TogglePanel);
    EXPECT_EQ(state.showHelp(), help);
    EXPECT_EQ(state.showPanel(), panel);
}

TEST(DemoApply, NTogglesVertexNormals) {
    DemoState state(Scene{});
    EXPECT_EQ(state.current().vertexNormals, VertexNormals::Averaged); // DESIGN §1: averaged is the default
    EXPECT_TRUE(state.apply(Command::ToggleNormals));
    EXPECT_EQ(state.current().vertexNormals, VertexNormals::Exact);
    state.apply(Command::ToggleNormals);
    EXPECT_EQ(state.current().vertexNormals, VertexNormals::Averaged);
}

// Teaching instruments: W cycles the overlay through the scene (so S saves it and `render`
// draws it): none, wireframe, wireframe with face and vertex normals, the lights' markers, none.
TEST(DemoOverlay, WCyclesWireframeNormalsNoneAndTheSceneCarriesIt) {
    DemoState state{Scene{}};
    EXPECT_EQ(commandForKey('W'), Command::ToggleOverlay);
    const Overlay expected[] = {Overlay::Wireframe, Overlay::Normals, Overlay::Lights, Overlay::None};
    for (Overlay overlay : expected) {
        EXPECT_TRUE(state.apply(Command::ToggleOverlay));
        EXPECT_EQ(state.drawn().overlay, overlay);
        EXPECT_EQ(parseScene(sceneToJson(state.drawn())).overlay, overlay) << "the saved scene keeps it";
    }
}

} // namespace
} // namespace shadelab::app
