// The demo window's keys and views (demo_window.h says what every window test checks): each mode key, the
// teaching instruments (wireframe, light drag, probe), the exact/error/split/profile/outside/NDC views, the
// same on OpenGL ES, and the drawn level after a resize.
#include <csignal>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "shadelab/image/image_file.h"
#include "shadelab/scene/auto_level.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_file.h"
#include "window/demo_window.h"

namespace shadelab::window_test {
namespace {

// What the demo should show: the part of the state the keys under test change.
struct Expected {
    ShadingMode shading = ShadingMode::Toon;
    LightingModel lighting = LightingModel::Phong;
    int level = 3;
    double shininess = 16;
    ProjectionType projection = ProjectionType::Perspective;
    LightingTerm term = LightingTerm::All;
    NormalMatrixRule normalMatrix = NormalMatrixRule::InverseTranspose;
    PerspectiveMatrix perspectiveMatrix = PerspectiveMatrix::WebGl;

    // "shadelab — <shading> shading, <lighting> lighting[, <term> term only][, normals by M] | level N |
    // <triangles> | <frame time> | H: keys"
    std::string titlePrefix() const {
        return "shadelab — " + std::string(toString(shading)) + " shading, " +
               std::string(toString(lighting)) + " lighting" +
               (term == LightingTerm::All ? "" : ", " + std::string(toString(term)) + " term only") +
               (normalMatrix == NormalMatrixRule::Model ? ", normals by M" : "") +
               (perspectiveMatrix == PerspectiveMatrix::Unnegated
                    ? ", unnegated perspective matrix: w < 0 in front, all clipped"
                    : "") +
               " | level " + std::to_string(level) + " | ";
    }
};

struct KeyStep {
    const char* key; // as xdotool names it
    std::function<void(Expected&)> change;
};

// The keys of the demo issue in order, each changing the state from the one before. The scene starts in
// toon shading under Phong lighting, so every key changes something.
const std::vector<KeyStep>& keySteps() {
    static const std::vector<KeyStep> kSteps = {
        {"1", [](Expected& e) { e.shading = ShadingMode::Flat; }},
        {"2", [](Expected& e) { e.shading = ShadingMode::Gouraud; }},
        {"3", [](Expected& e) { e.shading = ShadingMode::Phong; }},
        {"4", [](Expected& e) { e.shading = ShadingMode::Toon; }},
        // β = 4α keeps the highlight size going to Blinn-Phong; the demo has it on by default.
        {"b",
         [](Expected& e) {
             e.lighting = LightingModel::BlinnPhong;
             e.shininess *= 4;
         }},
        {"plus", [](Expected& e) { ++e.level; }}, // '+' is Shift + '=': the demo binds the '=' key
        {"minus", [](Expected& e) { --e.level; }},
        // K: one term of the lighting sum at a time, then all of it again.
        {"k", [](Expected& e) { e.term = LightingTerm::Ambient; }},
        {"k", [](Expected& e) { e.term = LightingTerm::Diffuse; }},
        {"k", [](Expected& e) { e.term = LightingTerm::Specular; }},
        {"k", [](Expected& e) { e.term = LightingTerm::All; }},
        // J: normals by M, the wrong matrix (the scene's object is an ellipsoid, where it shows), and back.
        {"j", [](Expected& e) { e.normalMatrix = NormalMatrixRule::Model; }},
        {"j", [](Expected& e) { e.normalMatrix = NormalMatrixRule::InverseTranspose; }},
        // U: the perspective matrix before its -1, where everything is clipped (an empty picture), and back.
        {"u", [](Expected& e) { e.perspectiveMatrix = PerspectiveMatrix::Unnegated; }},
        {"u", [](Expected& e) { e.perspectiveMatrix = PerspectiveMatrix::WebGl; }},
        {"o", [](Expected& e) { e.projection = ProjectionType::Orthographic; }}, // not in the title
    };
    return kSteps;
}

// S saves the state and the picture; the state must be `expected`, and the window and the saved PNG must
// both be what `render` gives for that state. Returns that picture.
Image checkState(DemoProcess& demo, const Expected& expected, const std::string& label,
                 const fs::path& scratch, const std::string& api = "gl") {
    const auto start = Clock::now();
    const fs::path stem = demo.screenshot();
    const double screenshotMs = msSince(start);
    const Scene saved = loadScene(stem.string() + ".json");
    EXPECT_EQ(toString(saved.shading), toString(expected.shading));
    EXPECT_EQ(toString(saved.lighting), toString(expected.lighting));
    EXPECT_EQ(toString(saved.term), toString(expected.term));
    EXPECT_EQ(toString(saved.normalMatrix), toString(expected.normalMatrix));
    EXPECT_EQ(toString(saved.perspectiveMatrix), toString(expected.perspectiveMatrix));
    EXPECT_EQ(toString(saved.projection.type), toString(expected.projection));
    EXPECT_EQ(saved.width, kWidth);
    EXPECT_EQ(saved.height, kHeight);
    EXPECT_EQ(saved.lights.size(), 2u);
    EXPECT_EQ(saved.objects.size(), 1u);
    if (!saved.objects.empty()) {
        EXPECT_EQ(saved.objects[0].subdivisions, expected.level);
        EXPECT_DOUBLE_EQ(saved.objects[0].material.shininess, expected.shininess);
    }

    const auto renderStart = Clock::now();
    const Image rendered =
        renderWithCli(stem.string() + ".json", scratch / (label + ".render.png"), scratch, api);
    const double renderMs = msSince(renderStart);
    const Image capture = settledCapture(demo.window(), rendered);
    const Image screenshot = readPng(stem.string() + ".png");
    EXPECT_TRUE(matches(capture, rendered, kWindowTolerance, label + ".window"));
    // S's picture is the one `render` gives for the saved scene, pixel for pixel.
    EXPECT_TRUE(matches(screenshot, rendered, kExact, label + ".screenshot"));
    std::printf("  %-8s S %4.0f ms, render %4.0f ms | window vs render: %s | S vs render: %s\n",
                label.c_str(), screenshotMs, renderMs,
                compareImages(capture, rendered, kWindowTolerance).summary().c_str(),
                compareImages(screenshot, rendered, kExact).summary().c_str());
    return rendered;
}

// `S` then `render` of the saved JSON gives the same pixels — 0 differing — with a spot light, in
// every shading mode (exact and toon included) under both lighting models. The window draws with the
// lights' values as uniforms (a slider recompiles nothing), so it is held to kWindowTolerance; S draws the
// picture as `render` does.
TEST_F(DemoWindow, ScreenshotIsWhatRenderGivesPixelForPixel) {
    std::string json = sceneJson(kWidth, kHeight, 4, "phong", "phong");
    const std::string spot = R"({ "type": "spot", "position": [-2, 2, 4], "direction": [0.45, -0.45, -0.8],
      "cutoff_deg": 25, "exponent": 8, "diffuse": [0.9, 0.8, 0.3], "specular": [1, 1, 0.5],
      "attenuation": [1, 0.05, 0.01] },
    )";
    json.insert(json.find("{ \"type\": \"directional\""), spot);
    const fs::path scene = writeScene("spot.json", json);
    DemoProcess& demo =
        startDemo("spot-demo", {scene.string(), "--size", kSize, "--hide-panel", "--gl-debug"});
    demo.window().waitForTitle("shadelab — phong shading, phong lighting");
    int states = 0;
    for (const char* lightingKey : {"", "b"}) {
        if (*lightingKey) demo.window().key(lightingKey);
        for (const auto& [key, mode] :
             {std::pair{"1", "flat"}, std::pair{"2", "gouraud"}, std::pair{"3", "phong"},
              std::pair{"4", "toon"}, std::pair{"5", "exact"}}) {
            demo.window().key(key);
            const std::string lighting = *lightingKey ? "blinn-phong" : "phong";
            demo.window().waitForTitle(std::string("shadelab — ") + mode + " shading, " + lighting +
                                       " lighting");
            const fs::path stem = demo.screenshot();
            const Scene saved = loadScene(stem.string() + ".json");
            ASSERT_EQ(saved.lights.size(), 3u);
            EXPECT_EQ(toString(saved.lights[1].type), "spot");
            const std::string label = std::string("spot_") + mode + "_" + lighting;
            const Image rendered =
                renderWithCli(stem.string() + ".json", scratch() / (label + ".png"), scratch());
            EXPECT_TRUE(matches(readPng(stem.string() + ".png"), rendered, kExact, label));
            ++states;
        }
    }
    EXPECT_EQ(states, 10);
    expectCleanQuit(demo);
}

// Every key of keySteps() through the window of `api` (gl or gles), each state checked against `render
// --api` of the same API.
void everyModeKeyShowsWhatRenderGives(DemoWindow& test, const std::string& api) {
    // An ellipsoid, so that J (normals by M) changes the picture.
    std::string json = sceneJson(kWidth, kHeight, 3, "toon", "phong");
    json.replace(json.find(R"("radius": 1.1,)"), 14, R"("radius": 1.1, "scale": [1.4, 0.7, 1],)");
    const fs::path scene = test.writeScene("scene.json", json);
    DemoProcess& demo =
        test.startDemo("demo", {scene.string(), "--size", kSize, "--hide-panel", "--gl-debug", "--api", api});
    Expected expected;
    demo.window().waitForTitle(expected.titlePrefix());
    Image previous = checkState(demo, expected, "start", test.scratch(), api);
    int number = 0;
    for (const KeyStep& step : keySteps()) {
        SCOPED_TRACE(std::string("after key ") + step.key);
        const std::string label = std::to_string(++number) + "-" + step.key; // K comes four times
        const auto start = Clock::now();
        demo.window().key(step.key);
        step.change(expected);
        demo.window().waitForTitle(expected.titlePrefix());
        std::printf("key %-6s title in %3.0f ms\n", step.key, msSince(start));
        const Image picture = checkState(demo, expected, label, test.scratch(), api);
        // Each key changes the picture beyond the tolerance, so a window stuck on the state before fails.
        EXPECT_FALSE(compareImages(picture, previous, kWindowTolerance).passed)
            << "the picture after key " << step.key << " is the one before it";
        previous = picture;
    }
    // The letter aliases of 1-4, by the title alone.
    for (const auto& [key, shading] :
         {std::pair{"f", ShadingMode::Flat}, std::pair{"g", ShadingMode::Gouraud},
          std::pair{"p", ShadingMode::Phong}, std::pair{"t", ShadingMode::Toon}}) {
        demo.window().key(key);
        expected.shading = shading;
        demo.window().waitForTitle(expected.titlePrefix());
    }
    test.expectCleanQuit(demo);
}

// The teaching instruments: W draws the wireframe (part of the scene: S saves it and `render` draws the
// same picture); right-drag moves the light (saved too); a click probes the point under the pointer, says
// so in the title and draws the probe's vectors over the picture, which S leaves out (they are not part of
// the scene). Each step changes the window's picture.
TEST_F(DemoWindow, OverlayLightDragAndProbeShowWhatRenderGives) {
    const fs::path scene = writeScene("scene.json", sceneJson(kWidth, kHeight, 3, "phong", "phong"));
    DemoProcess& demo = startDemo("demo", {scene.string(), "--size", kSize, "--hide-panel", "--gl-debug"});
    demo.window().waitForTitle("shadelab — phong shading");
    auto savedAndRendered = [&](const std::string& label) {
        const fs::path stem = demo.screenshot();
        const Image rendered =
            renderWithCli(stem.string() + ".json", scratch() / (label + ".png"), scratch());
        EXPECT_TRUE(
            matches(settledCapture(demo.window(), rendered), rendered, kWindowTolerance, label + ".window"));
        EXPECT_TRUE(
            matches(readPng(stem.string() + ".png"), rendered, kWindowTolerance, label + ".screenshot"));
        return std::pair{loadScene(stem.string() + ".json"), rendered};
    };
    const auto [plainScene, plain] = savedAndRendered("plain");
    EXPECT_EQ(plainScene.overlay, Overlay::None);

    demo.window().key("w");
    EXPECT_TRUE(pollUntil([&] { return demo.window().title().ends_with("| overlay: wireframe"); }))
        << "W: the title did not say the overlay within " << kWaitText << "; it is " << demo.window().title();
    const auto [wireScene, wire] = savedAndRendered("wireframe");
    EXPECT_EQ(wireScene.overlay, Overlay::Wireframe);
    EXPECT_FALSE(compareImages(wire, plain, kWindowTolerance).passed) << "W drew no edges";

    demo.window().rightDrag(kWidth / 2, kHeight / 2, -80, 0);
    EXPECT_TRUE(pollUntil([&] {
        return demo.window().title().find("| light 1 (point) at (") != std::string::npos;
    })) << "the light drag: the title did not name the light within "
        << kWaitText << "; it is " << demo.window().title();
    const auto [litScene, lit] = savedAndRendered("light");
    EXPECT_LT(litScene.lights[0].position.x, wireScene.lights[0].position.x) << "dragged left";
    EXPECT_NEAR(glm::length(litScene.lights[0].position), glm::length(wireScene.lights[0].position), 1e-6);
    EXPECT_FALSE(compareImages(lit, wire, kWindowTolerance).passed) << "the light did not move";

    demo.window().click(kWidth / 2, kHeight / 2);
    EXPECT_TRUE(pollUntil([&] {
        return demo.window().title().find("| probe: phong differs from exact by ") != std::string::npos;
    })) << demo.window().title();
    // The vectors are drawn over the picture, so the window now differs from the render near the centre.
    bool vectorsShown = pollUntil(
        [&, &lit = lit] { return !compareImages(demo.window().capture(), lit, kWindowTolerance).passed; });
    EXPECT_TRUE(vectorsShown) << "the probe's vectors are not drawn";
    const fs::path stem = demo.screenshot();
    EXPECT_TRUE(matches(readPng(stem.string() + ".png"), lit, kWindowTolerance, "probe.screenshot"))
        << "S saves the scene's picture, without the probe's vectors";
    expectCleanQuit(demo);
}

// 5 (exact), E (error), V (split, and a drag of its divider), I (profile, and a pointer move choosing its
// row), Y (outside, and a drag orbiting its observer) and Q (NDC) each change the picture, say so in the
// title, and the window shows what `render` draws for the JSON that S saves, the view included.
TEST_F(DemoWindow, ExactErrorSplitProfileOutsideAndNdcShowWhatRenderGives) {
    const fs::path scene = writeScene("scene.json", sceneJson(kWidth, kHeight, 3, "gouraud", "phong"));
    DemoProcess& demo = startDemo("demo", {scene.string(), "--size", kSize, "--hide-panel", "--gl-debug"});
    demo.window().waitForTitle("shadelab — gouraud shading");
    Image previous;
    auto step = [&](const std::string& label, const std::function<bool(const std::string&)>& titleSays) {
        EXPECT_TRUE(pollUntil([&] { return titleSays(demo.window().title()); }))
            << label << ": " << demo.window().title();
        const fs::path stem = demo.screenshot();
        const Image rendered =
            renderWithCli(stem.string() + ".json", scratch() / (label + ".png"), scratch());
        EXPECT_TRUE(
            matches(settledCapture(demo.window(), rendered), rendered, kWindowTolerance, label + ".window"));
        if (!previous.rgba.empty()) {
            EXPECT_FALSE(compareImages(rendered, previous, kWindowTolerance).passed)
                << label << " changed nothing";
        }
        previous = rendered;
        return loadScene(stem.string() + ".json");
    };
    auto has = [](const char* words) {
        return [words](const std::string& title) { return title.find(words) != std::string::npos; };
    };
    step("gouraud", has("gouraud shading"));
    demo.window().key("5");
    EXPECT_EQ(step("exact", has("| exact shading")).shading, ShadingMode::Exact);
    demo.window().key("2");
    demo.window().key("e");
    const Scene error = step("error", has("| error vs exact: interior mean "));
    EXPECT_EQ(error.view.kind, ViewKind::Error);
    EXPECT_EQ(error.shading, ShadingMode::Gouraud);
    demo.window().key("v");
    const Scene split = step("split", has("| split: gouraud | exact"));
    EXPECT_EQ(toString(split.view), "split:gouraud,exact");
    // Grabs the divider (the camera stays), with the demo stopped meanwhile: it handles the whole drag
    // after the pointer has arrived at its end, as a loaded machine does, and must still place the press
    // where it happened (this failed once in CI, the press taken where the pointer was by then).
    struct Resume {
        pid_t pid;
        ~Resume() { ::kill(pid, SIGCONT); } // also if the drag throws: the demo must still quit
    };
    ASSERT_EQ(::kill(demo.pid(), SIGSTOP), 0);
    {
        const Resume resume{demo.pid()};
        demo.window().drag(1, kWidth / 2, kHeight / 2, -64, 0);
    }
    const Scene moved =
        step("split-moved", [](const std::string& t) { return t.find("split:") != std::string::npos; });
    ASSERT_TRUE(moved.view.at.has_value());
    EXPECT_NEAR(*moved.view.at, (kWidth / 2 - 64.0) / kWidth, 2.0 / kWidth);
    EXPECT_EQ(moved.eye, split.eye) << "the divider drag orbited the camera";
    demo.window().key("i");
    demo.window().move(kWidth / 2, kHeight / 4);
    const Scene profile = step("profile", has("| profile: row 60,"));
    EXPECT_EQ(profile.view.kind, ViewKind::Profile);
    EXPECT_NEAR(profile.view.at.value_or(-1), 0.25, 1.0 / kHeight);
    demo.window().key("i");
    EXPECT_EQ(step("scene", has("| view: scene")).view.kind, ViewKind::Scene);
    // Y: the outside view, and a drag orbits its observer, not the camera.
    demo.window().key("y");
    const Scene outside = step("outside", has("| outside: observer at azimuth 55 deg"));
    EXPECT_EQ(outside.view.kind, ViewKind::Outside);
    demo.window().drag(1, kWidth / 2, kHeight / 2, 40, 0);
    const Scene orbited = step("outside-orbited", has("| outside: observer at azimuth 35 deg"));
    EXPECT_EQ(orbited.eye, outside.eye) << "the drag orbited the camera";
    EXPECT_EQ(orbited.view.observer.azimuthDeg, 35);
    // Q: the NDC view, from the same observer.
    demo.window().key("q");
    const Scene ndc = step("ndc", has("| ndc: observer at azimuth 35 deg"));
    EXPECT_EQ(ndc.view.kind, ViewKind::Ndc);
    // How to move the observer is said in the title, where the pointer is; the picture is render's, without
    // it.
    EXPECT_NE(demo.window().title().find("(drag: orbit, wheel: zoom)"), std::string::npos)
        << demo.window().title();
    expectCleanQuit(demo);
}

TEST_F(DemoWindow, EveryModeKeyShowsWhatRenderGives) {
    everyModeKeyShowsWhatRenderGives(*this, "gl");
}

// The same window on an OpenGL ES 3.0 context (GLFW_OPENGL_ES_API), held to `render --api gles`.
TEST_F(DemoWindow, OpenGlEsWindowShowsWhatRenderGives) {
    everyModeKeyShowsWhatRenderGives(*this, "gles");
}

// After the window is resized, the title shows the level that is drawn. The scene is 256×256;
// the window grows to 960×720 (inside Xvfb's 1024×768 screen) and A picks the level for that size: the
// title's level is the one the saved JSON (at the window's size) gives, and the picture is what `render`
// draws for that JSON.
TEST_F(DemoWindow, AfterAResizeTheTitleShowsTheDrawnLevel) {
    const fs::path scene = writeScene("scene.json", sceneJson(256, 256, 3, "phong", "phong"));
    DemoProcess& demo =
        startDemo("demo", {scene.string(), "--size", "256x256", "--hide-panel", "--gl-debug"});
    demo.window().waitForTitle("shadelab — phong shading, phong lighting | level 3 | ");
    demo.window().resize(960, 720);
    demo.window().key("a");
    std::string title;
    ASSERT_TRUE(pollUntil([&] {
        return (title = demo.window().title()).find("(auto)") != std::string::npos;
    })) << "A did not turn auto on: "
        << title;
    const std::size_t at = title.find("| level ") + 8;
    const int titleLevel = std::stoi(title.substr(at));
    const fs::path stem = demo.screenshot();
    const Scene saved = loadScene(stem.string() + ".json");
    EXPECT_EQ(saved.width, 720)
        << "the square scene's picture in a 960x720 window: 720x720, bars at the sides";
    EXPECT_EQ(saved.height, 720);
    EXPECT_EQ(titleLevel, subdivisionLevel(saved, saved.objects.at(0))) << title;
    EXPECT_GT(titleLevel, subdivisionLevel(loadScene(scene), loadScene(scene).objects.at(0)))
        << "at 960×720 auto should choose a finer level than at 256×256";
    const Image rendered =
        renderWithCli(stem.string() + ".json", scratch() / "resized.render.png", scratch());
    EXPECT_TRUE(matches(crop(settledCapture(demo.window(), rendered, 120, 0), 120, 0, 720, 720), rendered,
                        kWindowTolerance, "resized"));
    expectCleanQuit(demo);
}

} // namespace
} // namespace shadelab::window_test
