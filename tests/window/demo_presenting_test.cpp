// The demo window around its picture (demo_window.h says what every window test checks): presentation mode's
// label and panel text, a lesson's steps, the help overlay, and the panel docked beside the picture.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "shadelab/image/image_file.h"
#include "window/demo_window.h"

namespace shadelab::window_test {
namespace {

// Presentation mode: --present draws the large label over the bottom of the picture and leaves
// the rest as `render` draws it; F2 takes the label away and the whole window is the render again.
TEST_F(DemoWindow, PresentationLabelCoversOnlyTheBottomAndF2RemovesIt) {
    const fs::path scene = writeScene("scene.json", sceneJson(kWidth * 2, kHeight * 2, 3, "phong", "phong"));
    const std::string size = std::to_string(kWidth * 2) + "x" + std::to_string(kHeight * 2);
    DemoProcess& demo =
        startDemo("demo", {scene.string(), "--size", size, "--hide-panel", "--present", "--gl-debug"});
    demo.window().waitForTitle("shadelab — phong shading, phong lighting | level 3 | ");
    const fs::path stem = demo.screenshot(); // offscreen: the picture without the label
    const Image rendered = readPng(stem.string() + ".png");
    const int top = rendered.height * 3 / 5;
    Image withLabel;
    ASSERT_TRUE(pollUntil([&] {
        withLabel = demo.window().capture();
        return compareImages(crop(withLabel, 0, 0, rendered.width, top),
                             crop(rendered, 0, 0, rendered.width, top), kWindowTolerance)
            .passed;
    })) << "the top of the window is not the picture";
    EXPECT_FALSE(compareImages(withLabel, rendered, kWindowTolerance).passed) << "no label was drawn";
    demo.window().key("F2");
    EXPECT_TRUE(matches(settledCapture(demo.window(), rendered), rendered, kWindowTolerance, "after_F2"));
    expectCleanQuit(demo);
}

// The panel's text, with --present's 1.75× text in a narrow column: Dear ImGui's dark style draws text
// white and nothing else in the panel near white, and clips what runs past the column at half the window
// padding beyond where lines wrap. Returns the rightmost text pixel's x over all rows, and where lines wrap
// (the column less the padding and, when its grab shows, the scroll bar): ImGui's default WindowPadding 8
// and ScrollbarSize 14 (imgui.cpp, ImGuiStyle()), scaled by the panel's ScaleAllSizes.
struct PanelTextExtent {
    int rightmostText = -1, wrapEdge = 0;
    bool scrollbar = false;
};
PanelTextExtent panelTextExtent(const Image& capture, int column, double uiScale) {
    const int padding = int(8 * uiScale), scrollbar = int(14 * uiScale);
    PanelTextExtent extent;
    int grabRows = 0;
    for (int y = 0; y < capture.height; ++y) {
        bool grab = false;
        for (int x = 0; x < column; ++x) {
            const std::uint8_t* p = capture.pixel(x, y);
            if (p[0] > 200 && p[1] > 200 && p[2] > 200)
                extent.rightmostText = std::max(extent.rightmostText, x);
            // The scroll bar's grab: ImGui's grey 0.31 (79/255).
            if (x >= column - scrollbar && std::abs(p[0] - 79) < 6 && p[0] == p[1] && p[1] == p[2])
                grab = true;
        }
        grabRows += grab;
    }
    extent.scrollbar = grabRows >= 10;
    extent.wrapEdge = column - padding - (extent.scrollbar ? scrollbar : 0);
    return extent;
}

// Presentation mode: --present starts with the panel hidden and the picture the whole window (S saves
// it at the window's size); C shows the panel, and its text — the switches' rows, the checkbox's label —
// wraps in the column instead of running past it into ImGui's clip (which cut "(beta" and "diff" off at
// this size). F2 out of presentation keeps the panel; F2 into it hides it again.
TEST_F(DemoWindow, PresentingStartsWithoutThePanelAndItsTextWrapsInTheColumn) {
    constexpr int kW = 1000, kH = 720;
    constexpr double kPresentScale = 1.75; // demo.cpp: --present's text scale without --ui-scale
    const int column = std::min(int(420 * kPresentScale), kW / 2); // demo_state.h's panelColumnWidth
    const fs::path scene = writeScene("scene.json", sceneJson(kW, kH, 3, "phong", "phong"));
    DemoProcess& demo = startDemo("demo", {scene.string(), "--size", "1000x720", "--present", "--gl-debug"});
    demo.window().waitForTitle("shadelab — phong shading, phong lighting | level 3 | ");
    const fs::path stem = demo.screenshot();
    const Image rendered = readPng(stem.string() + ".png");
    EXPECT_EQ(rendered.width, kW) << "the picture is not the whole window's width: a panel beside it?";
    EXPECT_EQ(rendered.height, kH);
    // The left column is the picture (the label covers only the bottom).
    const int top = kH * 3 / 5;
    Image capture;
    EXPECT_TRUE(pollUntil([&] {
        capture = demo.window().capture();
        return compareImages(crop(capture, 0, 0, column, top), crop(rendered, 0, 0, column, top),
                             kWindowTolerance)
            .passed;
    })) << "the left of the window is not the picture";

    demo.window().key("c");
    Image previous;
    const bool panelShown = pollUntil([&] {
        previous = std::exchange(capture, demo.window().capture());
        return capture.rgba == previous.rgba &&
               !compareImages(crop(capture, 0, 0, column, top), crop(rendered, 0, 0, column, top),
                              kWindowTolerance)
                    .passed;
    });
    ASSERT_TRUE(panelShown) << "C showed no panel within " << kWaitText;
    const PanelTextExtent text = panelTextExtent(crop(capture, 0, 0, column, kH), column, kPresentScale);
    std::printf("panel: text reaches x = %d, lines wrap at %d (column %d, scroll bar %s)\n",
                text.rightmostText, text.wrapEdge, column, text.scrollbar ? "shown" : "none");
    EXPECT_GT(text.rightmostText, column / 2) << "no panel text found";
    // One pixel of the glyphs' antialiasing past the wrap edge; a clipped line reaches half the padding.
    EXPECT_LE(text.rightmostText, text.wrapEdge + 1) << "text runs past where the column's lines wrap";
    if (HasFailure()) {
        fs::create_directories(fs::current_path() / "window-failures");
        writePng(capture, fs::current_path() / "window-failures" / (testName() + ".png"));
    }

    // F2 ends presenting and keeps the panel (S's picture is the area beside it); F2 again hides it.
    demo.window().key("F2");
    EXPECT_LT(readPng(demo.screenshot().string() + ".png").width, kW - column / 2)
        << "F2 out of presentation hid the panel";
    demo.window().key("F2");
    EXPECT_TRUE(pollUntil([&] {
        const Image now = demo.window().capture();
        return compareImages(crop(now, 0, 0, column, top), crop(rendered, 0, 0, column, top),
                             kWindowTolerance)
            .passed;
    })) << "F2 into presentation did not hide the panel";
    expectCleanQuit(demo);
}

// `shadelab LESSON.json` opens at step 1; Page Down / Space / Page Up / Home / End step through
// it, and the window's picture at each step is what `render` gives of that step's scene; a key changes the
// step and R returns to it as written. Steps 1 and 2 name scene files; step 3 changes step 2's shading,
// which s3.json writes out in full for render.
TEST_F(DemoWindow, LessonStepsThroughAndRReturnsToTheStep) {
    const std::vector<fs::path> scenes = {
        writeScene("s1.json", sceneJson(kWidth, kHeight, 3, "phong", "phong")),
        writeScene("s2.json", sceneJson(kWidth, kHeight, 2, "gouraud", "phong")),
        writeScene("s3.json", sceneJson(kWidth, kHeight, 2, "flat", "phong"))};
    const fs::path lesson = writeScene("lesson.json", R"({"title": "Three steps", "steps": [
      {"title": "One", "caption": "Phong at level 3.", "scene": "s1.json"},
      {"title": "Two", "scene": "s2.json"},
      {"title": "Three", "shading": "flat"}]})");
    std::vector<Image> rendered;
    for (std::size_t i = 0; i < scenes.size(); ++i)
        rendered.push_back(
            renderWithCli(scenes[i], scratch() / ("s" + std::to_string(i + 1) + ".png"), scratch()));
    DemoProcess& demo = startDemo("demo", {lesson.string(), "--size", kSize, "--hide-panel", "--gl-debug"});
    const auto expectStep = [&](std::size_t step, const std::string& what) {
        const std::string title =
            demo.window().waitForTitle("shadelab — step " + std::to_string(step + 1) + " of 3 | ");
        EXPECT_TRUE(
            matches(settledCapture(demo.window(), rendered[step]), rendered[step], kWindowTolerance, what))
            << title;
    };
    expectStep(0, "opened");
    demo.window().key("Next"); // Page Down
    expectStep(1, "page_down");
    demo.window().key("space");
    expectStep(2, "space");
    demo.window().key("Next"); // past the last step: stays
    demo.window().waitForTitle("shadelab — step 3 of 3 | flat shading");
    demo.window().key("Prior"); // Page Up
    expectStep(1, "page_up");
    // A key works inside the step (the step is a starting point); R returns to it as written.
    demo.window().key("3");
    demo.window().waitForTitle("shadelab — step 2 of 3 | phong shading");
    EXPECT_FALSE(compareImages(demo.window().capture(), rendered[1], kWindowTolerance).passed)
        << "the key changed nothing";
    demo.window().key("r");
    expectStep(1, "reset");
    demo.window().key("End");
    expectStep(2, "end");
    demo.window().key("Home");
    expectStep(0, "home");
    // F2 in a lesson: the step's band instead of the label, so the window shows the step's slide at its
    // size, as `shadelab slides` draws it.
    const std::vector<std::string> argv = {
        SHADELAB_EXE, "slides", lesson.string(), "--out-dir", (scratch() / "slides").string(),
        "--size",     kSize};
    const ToolRun slides = runTool(argv, childEnvironment(""), scratch(), kWaitLimit);
    ASSERT_TRUE(slides.ok()) << slides.describe(argv);
    const Image slide = readPng(scratch() / "slides" / "01-one.png");
    demo.window().key("F2");
    EXPECT_TRUE(matches(settledCapture(demo.window(), slide), slide, kWindowTolerance, "presenting"));
    expectCleanQuit(demo);
}

// H shows the help overlay over the picture and H again takes it away. The demo runs on its built-in
// scene (no scene file), whose modes the title must show.
TEST_F(DemoWindow, HTogglesTheHelpOverlay) {
    DemoProcess& demo = startDemo("demo", {"--size", kSize, "--hide-panel", "--gl-debug"});
    demo.window().waitForTitle("shadelab — phong shading, blinn-phong lighting | level 5 | ");
    const fs::path stem = demo.screenshot();
    const Image rendered = renderWithCli(stem.string() + ".json", scratch() / "render.png", scratch());
    const Image before = settledCapture(demo.window(), rendered);
    ASSERT_TRUE(matches(before, rendered, kWindowTolerance, "before_help"));

    demo.window().key("h");
    Image withHelp;
    Comparison change;
    const bool shown = pollUntil([&] {
        withHelp = demo.window().capture();
        change = compareImages(withHelp, before, kWindowTolerance);
        return !change.passed;
    });
    EXPECT_TRUE(shown) << "the window did not change within " << kWaitText << " of H";
    std::printf("help overlay: %d of %d pixels changed, mean delta %.1f\n", change.outliers, kWidth * kHeight,
                change.meanDelta);

    demo.window().key("h");
    const Image after = settledCapture(demo.window(), before);
    EXPECT_TRUE(matches(after, before, kWindowTolerance, "after_second_h"));
    expectCleanQuit(demo);
}

// The control panel, visible, over a level-5 sphere at 800×600: the panel is drawn on the left, the
// picture beside it is untouched. With SHADELAB_SAVE_SCREENSHOT=PATH the capture is written to PATH (the
// README's docs/demo-window.png); without it nothing is written anywhere.
// The panel is docked as a left column (at most 420 px, at most half the window: demo_state.h's
// panelColumnWidth), and the picture beside it is exactly what `render` gives for the rest of the window.
constexpr int panelColumn(int windowWidth) {
    return std::min(420, windowWidth / 2);
}

// The picture keeps the scene's aspect, centred in the area beside the panel with bars above and
// below or at the sides (never a cropped side). The size the scene's picture takes in an area, computed
// here on its own: the area's full width or full height, the other side rounded to the scene's aspect.
struct Fitted {
    int width, height;
};
Fitted fittedSize(int sceneWidth, int sceneHeight, int areaWidth, int areaHeight) {
    const double scene = double(sceneWidth) / sceneHeight, area = double(areaWidth) / areaHeight;
    if (area > scene) return {int(std::lround(areaHeight * scene)), areaHeight};
    return {areaWidth, int(std::lround(areaWidth / scene))};
}

// Waits for two equal captures of `size` whose area right of the panel holds `picture` centred, the rest of
// the area one bar colour; returns the capture.
Image settledBesidePanel(DemoProcess& demo, int width, int height, const Image& picture, const char* label) {
    const int column = panelColumn(width);
    const int x = column + (width - column - picture.width) / 2, y = (height - picture.height) / 2;
    Image capture, previous;
    const bool settled = pollUntil([&] {
        previous = std::exchange(capture, demo.window().capture());
        return capture.rgba == previous.rgba && capture.width == width && capture.height == height &&
               compareImages(crop(capture, x, y, picture.width, picture.height), picture, kWindowTolerance)
                   .passed;
    });
    EXPECT_TRUE(settled) << label << ": the window (" << capture.width << "x" << capture.height
                         << ") did not settle on the picture beside the panel within " << kWaitText << "; "
                         << (capture.width == width && capture.height == height
                                 ? matches(crop(capture, x, y, picture.width, picture.height), picture,
                                           kWindowTolerance, label)
                                       .message()
                                 : std::string("wrong window size"));
    if (settled) {
        // The bars: above and below the picture, or left and right of it.
        if (y > 0) {
            EXPECT_TRUE(uniform(crop(capture, column, 0, width - column, y))) << label << ": the bar above";
            EXPECT_TRUE(uniform(
                crop(capture, column, y + picture.height, width - column, height - y - picture.height)))
                << label << ": the bar below";
        }
        if (x > column) {
            EXPECT_TRUE(uniform(crop(capture, column, 0, x - column, height))) << label << ": the bar left";
            EXPECT_TRUE(uniform(crop(capture, x + picture.width, 0, width - x - picture.width, height)))
                << label << ": the bar right";
        }
    }
    return capture;
}

TEST_F(DemoWindow, PanelDrawsBesideThePicture) {
    constexpr int kW = 800, kH = 600;
    const int column = panelColumn(kW);
    const fs::path scene = writeScene("panel-scene.json", sceneJson(kW, kH, 5, "phong", "blinn-phong"));
    DemoProcess& demo = startDemo("panel-demo", {scene.string(), "--size", "800x600", "--gl-debug"});
    // The picture: the same scene rendered at the largest 4:3 size that fits beside the panel (400x300,
    // with bars above and below: the whole scene, as `render` frames it).
    const Fitted fitted = fittedSize(kW, kH, kW - column, kH);
    ASSERT_EQ(fitted.height, 300);
    const fs::path besideScene =
        writeScene("beside-scene.json", sceneJson(fitted.width, fitted.height, 5, "phong", "blinn-phong"));
    const Image picture = renderWithCli(besideScene, scratch() / "beside-render.png", scratch());
    const Image capture = settledBesidePanel(demo, kW, kH, picture, "panel_window");

    // The column itself holds the panel: it differs from the scene's flat background.
    const Image background = crop(picture, 0, 0, 1, 1);
    int panelPixels = 0;
    const Image left = crop(capture, 0, 0, column, kH);
    for (std::size_t i = 0; i + 3 < left.rgba.size(); i += 4)
        if (std::abs(int(left.rgba[i]) - int(background.rgba[0])) > 8 ||
            std::abs(int(left.rgba[i + 2]) - int(background.rgba[2])) > 8)
            ++panelPixels;
    EXPECT_GT(panelPixels, column * kH / 20) << "no panel in the left column?";
    std::printf("panel: %d of the column's pixels are the panel's\n", panelPixels);

    if (const char* path = std::getenv("SHADELAB_SAVE_SCREENSHOT"); path && *path) {
        writePng(capture, path);
        std::printf("saved the window with its panel to %s\n", path);
    }
    expectCleanQuit(demo);
}

// A newcomer's first window. The scene's image is 256x256, but the window opens at a size fit for
// the screen (1280x800, at most 90 % of the work area: Xvfb here is 1024x768), with the object framed as
// the scene defines it beside the panel, not covered by it.
TEST_F(DemoWindow, DefaultWindowFitsTheScreenAndThePanelCoversNothing) {
    constexpr int kW = std::min(1280, 1024 * 9 / 10), kH = std::min(800, 768 * 9 / 10);
    const int column = panelColumn(kW);
    const fs::path scene = writeScene("small-scene.json", sceneJson(256, 256, 4, "phong", "blinn-phong"));
    DemoProcess& demo = startDemo("default-demo", {scene.string(), "--gl-debug"});
    const Fitted fitted = fittedSize(256, 256, kW - column, kH); // square, as wide as the area
    const fs::path besideScene =
        writeScene("beside-default.json", sceneJson(fitted.width, fitted.height, 4, "phong", "blinn-phong"));
    const Image picture = renderWithCli(besideScene, scratch() / "beside-default.png", scratch());
    (void)settledBesidePanel(demo, kW, kH, picture, "default_window");
    expectCleanQuit(demo);
}

} // namespace
} // namespace shadelab::window_test
