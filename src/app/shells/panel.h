// The demo's control panel and help overlay, drawn with Dear ImGui (Debian's libimgui-dev) over the scene.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "app/demo/demo_state.h"
#include "shadelab/gl/api.h"
#include "shadelab/last_key.h"

namespace shadelab {
class Window;
}

namespace shadelab::app {

class Panel {
public:
    // Installs ImGui's GLFW callbacks, chained to the window's own; `uiScale` scales every text.
    Panel(Window& window, double uiScale);
    ~Panel();
    Panel(const Panel&) = delete;
    Panel& operator=(const Panel&) = delete;

    // True while ImGui is using the keyboard or mouse (typing in a field, dragging a slider): the demo's
    // own keys and orbit are then left alone.
    bool wantsKeyboard() const;
    bool wantsMouse() const;

    // Builds and draws this frame's panel and help over the bound framebuffer. Every edited value goes
    // through its setter (scene_setters.h), which refuses what a scene file could not hold; the refusal
    // shows under the value's section.
    void draw(DemoState& state, const std::string& status, int columnWidth);

private:
    void controlsWindow(DemoState& state, const std::string& status, int columnWidth);
    void matricesSection(const DemoState& state);
    void probeSection(DemoState& state);

    Api api_;
    std::string refusal_, refused_; // the last refusal of a setter, and the value it refused
    // The matrices' and the probe's texts, made again only when the drawn scene (its version), the shown
    // object or the probe changes: a frame of an unchanged scene builds neither.
    LastKey<std::pair<std::uint64_t, std::optional<std::size_t>>> matricesFor_;
    std::string matricesText_;
    LastKey<std::pair<std::uint64_t, std::optional<ProbePoint>>> probeFor_;
    std::string probeText_;
};

// The help overlay (H), drawn inside Panel::draw's frame: the key table and the views' table
// (panel_help.cpp).
void helpWindow();

} // namespace shadelab::app
