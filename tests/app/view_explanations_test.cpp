// "What you are seeing" (src/app/demo/view_explanations.h), as the window's panel shows it: the line for
// the drawn scene follows the view, the shading mode and the lighting model, and names the lecture's
// formula. Expected words come from README's key table and DESIGN §3, not from view_explanations.cpp.
#include "app/demo/view_explanations.h"

#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/demo/demo_state.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app {
namespace {

// DESIGN §3: spec (Phong) = max(v·r, 0)^α, spec (Blinn-Phong) = max(n·h, 0)^β.
constexpr const char* kPhongSpec = "max(v·r, 0)^α";
constexpr const char* kBlinnSpec = "max(n·h, 0)^β";

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST(WhatYouAreSeeing, EachViewHasItsOwnLineNamedByIt) {
    const std::vector<std::pair<ViewKind, std::string>> views = {
        {ViewKind::Scene, "scene"},     {ViewKind::Error, "error"},     {ViewKind::Split, "split"},
        {ViewKind::Profile, "profile"}, {ViewKind::Outside, "outside"}, {ViewKind::Ndc, "ndc"}};
    std::set<std::string> lines;
    for (const auto& [kind, name] : views) {
        Scene scene;
        scene.view.kind = kind;
        const std::string line = whatYouAreSeeing(scene);
        EXPECT_EQ(line.rfind(name + ": ", 0), 0u) << line;
        EXPECT_EQ(line.find('\n'), std::string::npos) << "one line: " << line;
        EXPECT_TRUE(has(line, "; in ")) << "the space it is drawn in: " << line;
        lines.insert(line);
    }
    EXPECT_EQ(lines.size(), views.size()) << "two views share a line";
}

// The camera's picture (the scene view, a split's sides) adds the shading mode's line and the lighting
// model's specular formula; the observers' views are about the camera, not the shading.
TEST(WhatYouAreSeeing, TheCamerasPictureNamesItsShadingAndTheLightingFormula) {
    std::set<std::string> lines;
    for (const ShadingMode shading : kAllShadingModes)
        for (const LightingModel lighting : kLightingModels) {
            Scene scene;
            scene.shading = shading;
            scene.lighting = lighting;
            const std::string line = whatYouAreSeeing(scene);
            EXPECT_TRUE(has(line, " " + std::string(toString(shading)) + ": ")) << line;
            const bool phong = lighting == LightingModel::Phong;
            EXPECT_TRUE(has(line, phong ? kPhongSpec : kBlinnSpec)) << line;
            EXPECT_FALSE(has(line, phong ? kBlinnSpec : kPhongSpec)) << line;
            EXPECT_TRUE(has(line, "r = −l + 2(l·n)n") == phong) << line; // DESIGN §3's r
            EXPECT_TRUE(has(line, "h = normalize(v + l)") == !phong) << line;
            lines.insert(line);
        }
    EXPECT_EQ(lines.size(), kAllShadingModes.size() * kLightingModels.size());
    Scene outside;
    outside.view.kind = ViewKind::Outside;
    EXPECT_FALSE(has(whatYouAreSeeing(outside), kBlinnSpec)) << whatYouAreSeeing(outside);
    EXPECT_TRUE(has(whatYouAreSeeing(outside), "M_cam")) << whatYouAreSeeing(outside);
}

// The panel shows whatYouAreSeeing(state.drawn()): it follows the keys.
TEST(WhatYouAreSeeing, ThePanelsLineFollowsTheKeys) {
    DemoState state{Scene{}};
    const auto line = [&] { return whatYouAreSeeing(state.drawn()); };
    EXPECT_EQ(line().rfind("scene: ", 0), 0u) << line();
    state.apply(Command::ToggleErrorView);
    EXPECT_EQ(line().rfind("error: ", 0), 0u) << line();
    state.apply(Command::ToggleErrorView);
    state.apply(Command::ToggleNdcView);
    EXPECT_EQ(line().rfind("ndc: ", 0), 0u) << line();
    EXPECT_TRUE(has(line(), "[−1, 1]³")) << line();
    state.apply(Command::ToggleNdcView);
    state.apply(Command::Flat);
    EXPECT_TRUE(has(line(), " flat: ")) << line();
    const bool blinn = has(line(), kBlinnSpec);
    state.apply(Command::ToggleLighting);
    EXPECT_NE(has(line(), kBlinnSpec), blinn) << "B changed the lighting model, not the line: " << line();
}

// The help's table (the window's help, --help): a line per view and shading mode, each led by its name.
TEST(WhatYouAreSeeing, TheHelpTableHasALinePerEntry) {
    const std::string text = viewHelpText();
    std::size_t lines = 0;
    for (std::size_t at = 0; (at = text.find('\n', at)) != std::string::npos; ++at) ++lines;
    EXPECT_EQ(lines, viewExplanations().size()) << text;
    for (const ViewExplanation& row : viewExplanations()) {
        EXPECT_TRUE(has(text, std::string(row.name) + " ")) << row.name;
        EXPECT_TRUE(has(text, std::string(row.formula))) << row.name;
    }
}

} // namespace
} // namespace shadelab::app
