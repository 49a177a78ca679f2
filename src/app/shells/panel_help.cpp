// The help overlay (H): the key table, and under it the views' table — what each view and shading mode
// draws, in which space, by which formula of the lecture (app/demo/view_explanations.h).
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <imgui.h>

#include "app/demo/demo_state.h"
#include "app/demo/view_explanations.h"
#include "app/shells/panel.h"

namespace shadelab::app {
namespace {

// A two-column table whose second column wraps: a description that wraps stays in its column instead of
// running back under the first.
template <typename Rows, typename Row>
void table(const char* id, const char* first, const char* second, const Rows& rows, Row row) {
    if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_SizingFixedFit)) return;
    ImGui::TableSetupColumn(first, ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn(second, ImGuiTableColumnFlags_WidthStretch);
    for (const auto& entry : rows) {
        const auto [name, text] = row(entry);
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(name.c_str());
        ImGui::TableNextColumn();
        ImGui::TextWrapped("%s", text.c_str());
    }
    ImGui::EndTable();
}

} // namespace

// Centred and readable in any window: about 90 characters wide at most (the window less a margin), lines
// wrapped to its width, and a scroll bar when the window is too short for all of it.
void helpWindow() {
    static const std::vector<std::pair<std::string, std::string>> kKeys = keyHelpRows(); // made once
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float width = std::min(46 * ImGui::GetFontSize(), std::max(120.0f, display.x - 16));
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Always, {0.5f, 0.5f});
    ImGui::SetNextWindowSizeConstraints({width, 0}, {width, std::max(60.0f, display.y - 16)});
    ImGui::SetNextWindowSize({width, 0}, ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(1.0f); // opaque: the panel's text must not show through
    ImGui::Begin("keys", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize);
    table("key table", "key", "action", kKeys, [](const auto& row) { return row; });
    ImGui::Separator();
    ImGui::TextUnformatted("Views (what each shows):");
    table("view table", "name", "what is drawn; in which space; the formula", viewExplanations(),
          [](const ViewExplanation& view) {
              return std::pair{std::string(view.name), std::string(view.drawn) + "; in " +
                                                           std::string(view.space) + "; " +
                                                           std::string(view.formula)};
          });
    ImGui::End();
}

} // namespace shadelab::app
