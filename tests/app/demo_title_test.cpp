// What the demo says around the picture (src/app/demo/demo_state.h): the window's title (what the last key
// changed; the ray cast, not a level, under exact shading), the presentation label (its words; its size from
// the picture's alone, never clipped), the status line's note on the thinned normals, and the picture kept at
// the scene's aspect in the window's area.
#include "app/demo/demo_state.h"

#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "shadelab/scene/scene.h"

namespace shadelab::app {
namespace {

// With the panel hidden, what O, N, M, L (and the other keys) changed is in the title's end.
TEST(DemoTitle, SaysWhatTheLastKeyChanged) {
    DemoState state{Scene{}};
    EXPECT_EQ(windowTitle(state, 0).find("| H: keys |"), std::string::npos) << "nothing changed yet";
    const std::pair<Command, const char*> steps[] = {{Command::ToggleProjection, "orthographic projection"},
                                                     {Command::ToggleProjection, "perspective projection"},
                                                     {Command::ToggleNormals, "exact vertex normals"},
                                                     {Command::ToggleNormals, "averaged vertex normals"},
                                                     {Command::NextMaterial, "material: matte"},
                                                     {Command::NextLights, "lights: point"},
                                                     {Command::ToggleOverlay, "overlay: wireframe"},
                                                     {Command::Flat, "flat shading"},
                                                     {Command::Exact, "exact shading"},
                                                     {Command::ResetView, "view reset"}};
    for (const auto& [command, words] : steps) {
        state.apply(command);
        const std::string title = windowTitle(state, 0);
        EXPECT_TRUE(title.ends_with(std::string("| H: keys | ") + words)) << title;
    }
}

// Presentation mode: F2 toggles the large label; it names the mode, the lighting model, the
// drawn level and the exponent by its model's letter. F11 (full screen) is the window's to carry out.
TEST(DemoPresentation, LabelNamesModeLightingLevelAndExponent) {
    Scene scene;
    scene.objects[0].material.shininess = 32;
    DemoState state(scene);
    EXPECT_FALSE(state.presenting());
    EXPECT_TRUE(state.apply(Command::TogglePresentation));
    EXPECT_TRUE(state.presenting());
    EXPECT_EQ(presentationLabel(state), "PHONG SHADING\nBLINN-PHONG LIGHTING\nLEVEL 5 | BETA = 32");
    state.apply(Command::Gouraud);
    state.setMatchHighlight(false);
    state.apply(Command::ToggleLighting);
    state.apply(Command::LevelDown);
    EXPECT_EQ(presentationLabel(state), "GOURAUD SHADING\nPHONG LIGHTING\nLEVEL 4 | ALPHA = 32");
    EXPECT_FALSE(state.apply(Command::ToggleFullScreen)) << "the window's to carry out";
    state.apply(Command::TogglePresentation);
    EXPECT_FALSE(state.presenting());
}

} // namespace
} // namespace shadelab::app

// Exact shading draws no mesh, so the title, the status and the presentation label name the ray
// cast instead of a level and a triangle count; back on a mesh mode they show the level again.
TEST(DemoTitle, ExactShadingNamesTheRayCastNotALevel) {
    using namespace shadelab::app;
    DemoState state{shadelab::Scene{}};
    state.apply(Command::Exact);
    const std::string title = windowTitle(state, 0);
    EXPECT_NE(title.find("exact shading, blinn-phong lighting | ray-cast per pixel, no mesh | "),
              std::string::npos)
        << title;
    EXPECT_EQ(title.find("level"), std::string::npos) << title;
    EXPECT_EQ(title.find("triangles"), std::string::npos) << title;
    EXPECT_EQ(statusText(state).find("level"), std::string::npos) << statusText(state);
    EXPECT_NE(presentationLabel(state).find("RAY-CAST"), std::string::npos) << presentationLabel(state);
    state.apply(Command::Phong);
    EXPECT_NE(windowTitle(state, 0).find("| level 5 | "), std::string::npos) << windowTitle(state, 0);
}

// The presentation label is laid out from the picture's size alone (stable from frame to frame),
// large for a class (lines a twelfth of the height: 55 px at 1280x720), never wider than the picture less
// its margins (smaller text in a narrow picture instead of a clipped line), and its box holds all three
// lines.
TEST(DemoPresentation, LabelImageIsLargeStableAndNeverClipped) {
    using shadelab::app::presentationLabelImage;
    const std::string label = "PHONG SHADING\nBLINN-PHONG LIGHTING\nLEVEL 5 | BETA = 96";
    const auto wide = presentationLabelImage(label, 1280, 720);
    EXPECT_GE(wide.image.height, 3 * shadelab::textLineHeight(5)) << "three lines of 55 px at 720 high";
    EXPECT_LE(wide.image.width + 2 * wide.margin, 1280);
    const auto again = presentationLabelImage(label, 1280, 720);
    EXPECT_EQ(again.image.rgba, wide.image.rgba) << "the same size must give the same label";
    for (const auto& [w, h] : {std::pair{860, 720}, std::pair{480, 720}, std::pair{1920, 1080}}) {
        const auto fitted = presentationLabelImage(label, w, h);
        EXPECT_LE(fitted.image.width + 2 * fitted.margin, w) << w << "x" << h << ": a line would be clipped";
        EXPECT_LE(fitted.image.height + 2 * fitted.margin, h);
    }
    EXPECT_GT(presentationLabelImage(label, 1920, 1080).image.height, wide.image.height)
        << "scaled with the window";
}

// The normals overlay past level 3 is thinned (overlay.h); the status line (window and page) says how, and
// says nothing at level 3 or without the overlay.
TEST(DemoStatus, SaysWhichNormalsTheThinnedOverlayShows) {
    shadelab::Scene scene =
        shadelab::parseScene(R"({"overlay": "normals", "objects": [{"subdivisions": 6}]})");
    EXPECT_NE(shadelab::app::statusText(shadelab::app::DemoState(scene))
                  .find("normals shown: level 3's vertices and 1 face in 64 (of level 6)"),
              std::string::npos)
        << shadelab::app::statusText(shadelab::app::DemoState(scene));
    scene.objects[0].subdivisions = 3;
    EXPECT_EQ(shadelab::app::statusText(shadelab::app::DemoState(scene)).find("normals shown"),
              std::string::npos);
    scene.objects[0].subdivisions = 6;
    scene.overlay = shadelab::Overlay::Wireframe;
    EXPECT_EQ(shadelab::app::statusText(shadelab::app::DemoState(scene)).find("normals shown"),
              std::string::npos);
}

// The window keeps the scene's framing. grid.json (800x600) beside the panel in a 1280x800 window
// (an 860x800 area) is letterboxed, not cropped to its two middle columns.
TEST(FitPicture, KeepsTheScenesAspectCentredInTheArea) {
    using shadelab::app::fitPicture;
    const auto wide = fitPicture(800, 600, 860, 800);
    EXPECT_EQ(wide.width, 860);
    EXPECT_EQ(wide.height, 645); // 860 * 600 / 800
    EXPECT_EQ(wide.x, 0);
    EXPECT_EQ(wide.y, 77); // (800 - 645) / 2: bars above and below
    const auto tall = fitPicture(512, 1024, 1000, 600);
    EXPECT_EQ(tall.width, 300);
    EXPECT_EQ(tall.height, 600);
    EXPECT_EQ(tall.x, 350); // bars at the sides
    EXPECT_EQ(tall.y, 0);
    const auto same = fitPicture(640, 480, 1280, 960);
    EXPECT_EQ(same.x, 0);
    EXPECT_EQ(same.y, 0);
    EXPECT_EQ(same.width, 1280);
    EXPECT_EQ(same.height, 960);
    const auto sliver = fitPicture(1, 10000, 100, 100);
    EXPECT_EQ(sliver.width, 1) << "never narrower than a pixel";
    EXPECT_EQ(sliver.height, 100);
    const auto none = fitPicture(800, 600, 0, 800);
    EXPECT_EQ(none.width, 0);
    EXPECT_EQ(none.height, 0);
    EXPECT_TRUE(wide.contains(10, 77));
    EXPECT_FALSE(wide.contains(10, 76)) << "the bar above is not the picture";
    EXPECT_FALSE(wide.contains(10, 77 + 645)) << "the bar below is not the picture";
}
