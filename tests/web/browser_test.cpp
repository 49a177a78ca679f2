// The WebGL 2 build in a real browser (DESIGN §7): Debian's headless Chromium (SwiftShader) driven by
// chromium-driver through web/driver.py, the page served from 127.0.0.1. Held to the same analytic reference
// as the native APIs, to the CPU's flat lighting, and to the native OpenGL ES render of the same scenes; the
// page's keys, messages, canvas size and console are checked as a user meets them.
//
// A session is a batch of requests run by one browser (driver.py session); each test builds one, runs it,
// and reads the answers. Without the browser build or Chromium the tests skip with the reason, except in
// CI (CI set), where they fail.
#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/demo/demo_state.h"
#include "app/demo/scene_flags.h"
#include "app/demo/view_explanations.h"
#include "cli/run_process.h"
#include "gl/gl_test_support.h"
#include "gl/projected_mesh.h"
#include "shadelab/context/window.h"
#include "shadelab/image/image_file.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/lesson.h"
#include "shadelab/scene/scene_file.h"
#include "shadelab/shading/probe.h"
#include "tolerances.h"

namespace shadelab::test {
namespace {

namespace fs = std::filesystem;
using cli_test::describe;
using cli_test::Outcome;
using cli_test::RunOptions;
using cli_test::runShadelab;
using cli_test::runWith;
using nlohmann::json;

// ---- the browser session -------------------------------------------------------------------------

std::vector<std::uint8_t> base64Decode(const std::string& text) {
    static const std::string kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<std::uint8_t> out;
    out.reserve(text.size() / 4 * 3);
    unsigned bits = 0;
    int count = 0;
    for (char c : text) {
        const std::size_t value = kAlphabet.find(c);
        if (value == std::string::npos) continue; // '=' padding
        bits = (bits << 6) | unsigned(value);
        count += 6;
        if (count >= 8) {
            count -= 8;
            out.push_back(std::uint8_t((bits >> count) & 0xff));
        }
    }
    return out;
}

class Session {
public:
    // Each returns the index of its answer.
    std::size_t open(const std::string& query = "", const std::vector<std::string>& args = {},
                     const fs::path& downloads = {}) {
        json request = {{"op", "open"}, {"query", query}, {"args", args}};
        if (!downloads.empty()) request["downloads"] = downloads.string();
        return add(request);
    }
    // The page with `files` served beside it at /files/ and the streamed scenes at /stream/ (driver.py
    // TestFilesHandler).
    std::size_t openWithFiles(const std::string& query, const fs::path& files) {
        return add({{"op", "open"}, {"query", query}, {"files", files.string()}});
    }
    // The page with more of driver.py's "open" fields: "lessons" (a folder served as scripts/web.sh serve
    // --lessons serves it).
    std::size_t openWith(const std::string& query, json fields) {
        fields["op"] = "open";
        fields["query"] = query;
        return add(fields);
    }
    std::size_t loadUrl(const std::string& url) { return add({{"op", "load-url"}, {"url", url}}); }
    std::size_t served() { return add({{"op", "served"}}); }
    std::size_t waitFiles(const std::vector<fs::path>& paths) {
        json list = json::array();
        for (const fs::path& p : paths) list.push_back(p.string());
        return add({{"op", "wait-files"}, {"paths", list}});
    }
    std::size_t load(const Scene& scene, const std::string& name = "scene.json") {
        return add({{"op", "load"}, {"text", sceneToJson(scene)}, {"name", name}});
    }
    std::size_t loadText(const std::string& text, const std::string& name) {
        return add({{"op", "load"}, {"text", text}, {"name", name}});
    }
    std::size_t loadFile(const fs::path& path, const std::string& name) {
        return add({{"op", "load-file"}, {"path", path.string()}, {"name", name}});
    }
    std::size_t key(int code) { return add({{"op", "key"}, {"code", code}}); }
    std::size_t ui() { return add({{"op", "ui"}}); }
    // Real mouse input at (x, y) CSS pixels from the canvas's centre.
    std::size_t click(int x = 0, int y = 0) {
        return add({{"op", "pointer"}, {"action", "click"}, {"x", x}, {"y", y}});
    }
    std::size_t move(int x, int y) {
        return add({{"op", "pointer"}, {"action", "move"}, {"x", x}, {"y", y}});
    }
    std::size_t drag(int dx, int dy, bool shift) {
        return add({{"op", "pointer"}, {"action", "drag"}, {"dx", dx}, {"dy", dy}, {"shift", shift}});
    }
    // A touch gesture at (x, y) CSS pixels from the canvas's centre (driver.py Page.touch).
    std::size_t tap(int x = 0, int y = 0) {
        return add({{"op", "touch"}, {"gesture", "tap"}, {"x", x}, {"y", y}});
    }
    std::size_t touchDrag(int dx, int dy) {
        return add({{"op", "touch"}, {"gesture", "drag"}, {"dx", dx}, {"dy", dy}});
    }
    std::size_t pinch(int fromPx, int toPx) {
        return add({{"op", "touch"}, {"gesture", "pinch"}, {"from", fromPx}, {"to", toPx}});
    }
    // A real click on a control (it takes the focus from the canvas).
    std::size_t clickElement(const std::string& selector) {
        return add({{"op", "click-element"}, {"selector", selector}});
    }
    // The viewport, the document's width and each element's box (getBoundingClientRect, scrollWidth,
    // clientWidth), null for an element that is not there.
    std::size_t layout(const std::vector<std::string>& selectors) {
        return add({{"op", "layout"}, {"selectors", selectors}});
    }
    // A mutation for a test to see fail: every shader compiled from now on has `from` replaced by `to`.
    std::size_t mutateShader(const std::string& from, const std::string& to) {
        return add({{"op", "mutate-shader"}, {"from", from}, {"to", to}});
    }
    std::size_t shaderMutations() { return add({{"op", "shader-mutations"}}); }
    std::size_t element(const std::string& selector) {
        return add({{"op", "element"}, {"selector", selector}});
    }
    std::size_t panel(const std::string& selector, const std::string& value,
                      const std::string& event = "change") {
        return add({{"op", "panel"}, {"selector", selector}, {"value", value}, {"event", event}});
    }
    std::size_t message() { return add({{"op", "message"}}); }
    std::size_t capture(const std::string& kind = "rgba8") {
        return add({{"op", "capture"}, {"kind", kind}});
    }
    // At width × height rather than the scene's image size (the picture at that size, as drawn()).
    std::size_t capture(int width, int height) {
        return add({{"op", "capture"}, {"kind", "rgba8"}, {"width", width}, {"height", height}});
    }
    std::size_t resize(int width, int height) {
        return add({{"op", "resize"}, {"width", width}, {"height", height}});
    }
    // Chromium's mobile emulation from now on: a screen of width × height CSS pixels at `scale` device
    // pixels each, touch events on; answers the canvas's size once it has refitted, as resize.
    std::size_t phone(int width, int height, double scale) {
        return add({{"op", "phone"}, {"width", width}, {"height", height}, {"scale", scale}});
    }
    std::size_t screenshot(const fs::path& path) {
        return add({{"op", "screenshot"}, {"path", path.string()}});
    }
    std::size_t console() { return add({{"op", "console"}}); }
    // Waits (at most 20 s) until the page's state holds `value` at `path`; answers what it holds there.
    std::size_t waitUi(const std::vector<std::string>& path, const json& value) {
        return add({{"op", "wait-ui"}, {"path", path}, {"value", value}});
    }
    std::size_t sleep(double seconds) { return add({{"op", "sleep"}, {"seconds", seconds}}); }

    // Runs the batch; false (with the test failed or skipped) when there is no browser to run it in.
    bool run(const fs::path& folder) {
        std::string input;
        for (const json& request : requests_) input += request.dump() + "\n";
        input += R"({"op": "quit"})"
                 "\n";
        RunOptions options;
        options.program = "/usr/bin/python3";
        options.stdinText = input;
        options.stdoutPath = folder / "answers.jsonl";
        options.timeout = std::chrono::seconds(240);
        std::ofstream(*options.stdoutPath).close();
        const Outcome driver = runWith({SHADELAB_WEB_DRIVER, "session"}, folder, options);
        EXPECT_EQ(driver.exitCode, 0) << driver.err;
        std::ifstream answers(*options.stdoutPath);
        for (std::string line; std::getline(answers, line);) answers_.push_back(json::parse(line));
        if (answers_.size() != requests_.size()) {
            ADD_FAILURE() << "the driver answered " << answers_.size() << " of " << requests_.size()
                          << " requests\n"
                          << driver.err;
            return false;
        }
        for (std::size_t i = 0; i < answers_.size(); ++i)
            if (!answers_[i].value("ok", false)) {
                ADD_FAILURE() << "request " << requests_[i].dump().substr(0, 200)
                              << " failed: " << answers_[i];
                return false;
            }
        return true;
    }

    const json& answer(std::size_t i) const { return answers_.at(i); }
    Image image(std::size_t i) const {
        const json& a = answers_.at(i);
        Image image(a.at("width"), a.at("height"));
        const std::vector<std::uint8_t> bytes = base64Decode(a.at("data"));
        EXPECT_EQ(bytes.size(), image.rgba.size());
        std::copy_n(bytes.begin(), std::min(bytes.size(), image.rgba.size()), image.rgba.begin());
        return image;
    }
    ImageF imageF(std::size_t i) const {
        const json& a = answers_.at(i);
        ImageF image(a.at("width"), a.at("height"));
        const std::vector<std::uint8_t> bytes = base64Decode(a.at("data"));
        EXPECT_EQ(bytes.size(), image.rgba.size() * sizeof(float));
        std::memcpy(image.rgba.data(), bytes.data(),
                    std::min(bytes.size(), image.rgba.size() * sizeof(float)));
        return image;
    }

private:
    std::size_t add(json request) {
        requests_.push_back(std::move(request));
        return requests_.size() - 1;
    }
    std::vector<json> requests_, answers_;
};

// Why no browser test can run here, or "".
std::string browserUnavailable() {
    if (!fs::exists(fs::path(SHADELAB_WEB_BUILD) / "shadelab.wasm"))
        return std::string(SHADELAB_WEB_BUILD) + " holds no browser build (scripts/web.sh build)";
    if (!fs::exists("/usr/bin/chromium") || !fs::exists("/usr/bin/chromedriver"))
        return "no Debian chromium / chromium-driver (scripts/web.sh build installs them)";
    // Selenium reaches chromedriver at "localhost": a root made by debootstrap has no /etc/hosts, and every
    // page test then failed after 30 s with "Can not connect to the Service".
    addrinfo* found = nullptr;
    if (::getaddrinfo("localhost", nullptr, nullptr, &found) != 0)
        return "the name localhost does not resolve (no /etc/hosts?): chromedriver is reached through it; "
               "add "
               "'127.0.0.1 localhost' to /etc/hosts";
    ::freeaddrinfo(found);
    return "";
}

class Browser : public testing::Test {
protected:
    void SetUp() override {
        if (const std::string why = browserUnavailable(); !why.empty()) {
            if (std::getenv("CI")) FAIL() << why;
            GTEST_SKIP() << why;
        }
        const std::string name = testing::UnitTest::GetInstance()->current_test_info()->name();
        dir_ = fs::temp_directory_path() / ("shadelab-web-" + std::to_string(::getpid()) + "-" + name);
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        if (dir_.empty()) return;
        if (!HasFailure())
            fs::remove_all(dir_);
        else
            std::printf("kept %s\n", dir_.string().c_str());
    }
    fs::path dir_;
};

// No WebGL error, warning or uncaught exception in the console during the session.
void expectCleanConsole(const json& entries) {
    for (const json& entry : entries) {
        const std::string message = entry.value("message", "");
        EXPECT_NE(entry.value("level", ""), "SEVERE") << message;
        EXPECT_EQ(message.find("WebGL"), std::string::npos) << message;
        EXPECT_EQ(message.find("GL_INVALID"), std::string::npos) << message;
    }
}

// Browser against native: the interior within 2/255; SwiftShader and llvmpipe rasterize the silhouette
// differently (measured: about 1 % of a sphere's pixels), so up to 1.5 % of the pixels may differ more.
Tolerance swiftShaderTolerance(const Image& image) {
    return Tolerance{2, 0.6, int(0.015 * image.width * image.height)};
}

ImageF asFloat(const Image& image) {
    ImageF out(image.width, image.height);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) out.rgba[i] = float(image.rgba[i]) / 255.0f;
    return out;
}

// Native OpenGL ES renders, the browser's counterpart (tests link the headless renderer).
HeadlessRenderer& nativeGles() {
    static HeadlessRenderer renderer(ContextRequest{Backend::Egl, Api::Gles, std::nullopt});
    return renderer;
}

// Every analytic scene under each lighting model, in `mode` at `level`, loaded and captured through a float
// target (for session.imageF once the session has run).
struct AnalyticCapture {
    std::string label;
    Scene scene;
    std::size_t capture;
};
std::vector<AnalyticCapture> captureAnalyticCases(Session& session, ShadingMode mode, int level) {
    std::vector<AnalyticCapture> items;
    for (const AnalyticCase& c : analyticCases()) {
        for (LightingModel model : kLightingModels) {
            Scene scene = c.scene();
            scene.shading = mode;
            scene.lighting = model;
            for (SceneObject& o : scene.objects) o.subdivisions = level;
            session.load(scene);
            items.push_back(
                {std::string(c.name) + "/" + std::string(toString(model)), scene, session.capture("float")});
        }
    }
    return items;
}

// ---- the tests -----------------------------------------------------------------------------------

// The issue's bar for every API: Phong at level 8 against the exact ray-cast, interior mean < 0.5/255 and
// max <= 4/255, on the analytic test scenes, read back unrounded through a float target.
TEST_F(Browser, PhongLevel8MatchesTheAnalyticReference) {
    Session session;
    session.open();
    const std::vector<AnalyticCapture> items = captureAnalyticCases(session, ShadingMode::Phong, 8);
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    for (const AnalyticCapture& item : items) {
        const ImageF rendered = session.imageF(item.capture);
        const ReferenceImage reference = renderReference(item.scene);
        const InteriorError e = interiorError(rendered, reference);
        // A spot light's cone edge is a step in the lighting itself: a pixel centre within float rounding
        // of the cutoff is lit in double and unlit in float, or the other way round. SwiftShader lands a few
        // such pixels on the other side (llvmpipe, by chance, none); they are counted, and only for spots.
        const std::size_t over = interiorPixelsOver(rendered, reference, 4);
        const bool hardEdge = std::any_of(item.scene.lights.begin(), item.scene.lights.end(),
                                          [](const Light& l) { return l.type == LightType::Spot; });
        std::printf("webgl2 %s: interior mean %.3f/255, max %.3f/255 over %zu pixels; %zu over 4/255\n",
                    item.label.c_str(), e.mean, e.max, e.pixels, over);
        SCOPED_TRACE(item.label);
        ASSERT_GT(e.pixels, 1000u);
        EXPECT_LT(e.mean, 0.5);
        if (hardEdge) {
            EXPECT_LE(double(over), 0.001 * double(e.pixels)) << "more than the spot cone's edge pixels";
        } else {
            EXPECT_LE(e.max, 4.0);
        }
    }
    expectCleanConsole(session.answer(console).at("console"));
}

// Exact shading on WebGL 2: the sphere ray-cast in the fragment shader against the same ray cast
// in double, on the analytic scenes, read back through a float target: interior mean <= 0.05/255 and max
// <= 2/255 (except, under a spot, pixel centres within float rounding of the cone's edge, counted as in the
// Phong test), and the covered pixels those of the reference within 0.05 per silhouette pixel.
TEST_F(Browser, ExactShadingMatchesTheAnalyticReference) {
    Session session;
    session.open();
    const std::vector<AnalyticCapture> items = captureAnalyticCases(session, ShadingMode::Exact, 8);
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    for (const AnalyticCapture& item : items) {
        const ImageF rendered = session.imageF(item.capture);
        const ReferenceImage reference = renderReference(item.scene);
        const InteriorError e = interiorError(rendered, reference);
        const std::size_t over = interiorPixelsOver(rendered, reference, 2);
        const bool hardEdge = std::any_of(item.scene.lights.begin(), item.scene.lights.end(),
                                          [](const Light& l) { return l.type == LightType::Spot; });
        const double shift = silhouetteShiftPx(rendered, reference);
        std::printf("webgl2 exact %s: interior mean %.4f/255, max %.3f/255 over %zu pixels; %zu over 2/255; "
                    "silhouette %.4f px\n",
                    item.label.c_str(), e.mean, e.max, e.pixels, over, shift);
        SCOPED_TRACE(item.label);
        ASSERT_GT(e.pixels, 1000u);
        EXPECT_LE(e.mean, 0.05);
        EXPECT_LE(shift, 0.05);
        if (hardEdge) {
            EXPECT_LE(double(over), 0.001 * double(e.pixels)) << "more than the spot cone's edge pixels";
        } else {
            EXPECT_LE(e.max, 2.0);
        }
    }
    expectCleanConsole(session.answer(console).at("console"));
}

// DESIGN §3 on WebGL 2: one colour per triangle, the CPU's lighting at its centroid within ±1.
TEST_F(Browser, FlatIsLitOnceAtEachCentroidAsTheCpuComputes) {
    Session session;
    session.open();
    // The check asks for each lighting model of its level-1 scene: render both up front.
    std::vector<std::pair<Scene, std::size_t>> shots;
    for (LightingModel model : kLightingModels) {
        Scene scene = litSphereScene(256, LightType::Point);
        scene.shading = ShadingMode::Flat;
        scene.objects[0].subdivisions = 1;
        scene.lighting = model;
        session.load(scene);
        shots.emplace_back(scene, session.capture());
    }
    if (!session.run(dir_)) return;
    checkFlatLitAtCentroids([&](const Scene& scene) {
        for (const auto& [shot, index] : shots)
            if (shot.lighting == scene.lighting) return session.image(index);
        ADD_FAILURE() << "no browser render for " << toString(scene.lighting);
        return Image(scene.width, scene.height);
    });
}

// SwiftShader is not llvmpipe: the same program gives slightly different pixels. Every mode × lighting
// model against the native OpenGL ES render. Where the picture is smooth they agree within 2/255 (mean on the
// interior below 0.1/255); where it steps — the silhouette, flat triangles' shared edges, toon bands, the
// spot cone's edge — a pixel centre may fall on the other side, so those pixels are counted, not bounded: at
// most 1.5 % of the image may differ by more than 2/255.
TEST_F(Browser, MatchesTheNativeOpenGlEsRender) {
    Session session;
    session.open();
    std::vector<std::pair<Scene, std::size_t>> shots;
    for (const Scene& scene : modeScenes(192, 5)) {
        session.load(scene);
        shots.emplace_back(scene, session.capture());
    }
    if (!session.run(dir_)) return;
    for (const auto& [scene, index] : shots) {
        const Image browser = session.image(index);
        const Image native = nativeGles().render(scene);
        const ReferenceImage reference = renderReference(scene);
        const std::vector<bool> interior = interiorMask(reference.objectId, 192, 192, 2);
        int interiorMax = 0;
        std::size_t differing = 0, interiorDiffering = 0, overTwo = 0;
        double interiorSum = 0;
        std::size_t interiorPixels = 0;
        for (std::size_t i = 0; i < interior.size(); ++i) {
            int delta = 0;
            for (int c = 0; c < 3; ++c)
                delta = std::max(delta, std::abs(int(browser.rgba[i * 4 + c]) - int(native.rgba[i * 4 + c])));
            differing += delta > 0;
            overTwo += delta > 2;
            if (!interior[i]) continue;
            ++interiorPixels;
            interiorSum += delta;
            interiorMax = std::max(interiorMax, delta);
            interiorDiffering += delta > 0;
        }
        const std::string label =
            std::string(toString(scene.shading)) + "/" + std::string(toString(scene.lighting));
        std::printf(
            "webgl2 vs native gles %s: interior max %d/255, mean %.4f/255, %zu of %zu interior px differ; "
            "%zu px differ in all, %zu by more than 2/255\n",
            label.c_str(), interiorMax, interiorSum / double(interiorPixels), interiorDiffering,
            interiorPixels, differing, overTwo);
        // Each against the exact answer, both read back in 8 bits: the error the shading mode makes.
        const InteriorError browserError = interiorError(asFloat(browser), reference);
        const InteriorError nativeError = interiorError(asFloat(native), reference);
        std::printf("  %s against the analytic reference (8-bit, interior mean / max): webgl2 %.3f / %.1f, "
                    "native gles %.3f / %.1f\n",
                    label.c_str(), browserError.mean, browserError.max, nativeError.mean, nativeError.max);
        SCOPED_TRACE(label);
        EXPECT_NEAR(browserError.mean, nativeError.mean, 0.1) << "the browser's error is not the shading's";
        EXPECT_LT(interiorSum / double(interiorPixels), 0.1);
        EXPECT_LE(double(overTwo), 0.015 * 192 * 192);
    }
}

// The teaching instruments in the page, with real mouse input: W draws the wireframe (its edges where
// native render draws them for the state the page reports, within a pixel); Shift + drag moves the light
// around the target; a click probes the point under the pointer, and the page's table holds the values the
// native probe computes there; a click that only takes the focus back from the panel places no probe.
// The pixels where an overlay's lines changed a picture (more than 30/255 in a channel from `under`).
struct LineMask {
    int width = 0, height = 0;
    std::vector<bool> set;
    std::size_t count() const { return std::size_t(std::count(set.begin(), set.end(), true)); }
    // How many of this mask's pixels lie within a pixel of one of `other`'s.
    std::size_t within1(const LineMask& other) const {
        std::size_t near = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                if (!set[std::size_t(y * width + x)]) continue;
                bool found = false;
                for (int dy = -1; dy <= 1 && !found; ++dy)
                    for (int dx = -1; dx <= 1 && !found; ++dx)
                        found = x + dx >= 0 && y + dy >= 0 && x + dx < width && y + dy < height &&
                                other.set[std::size_t((y + dy) * width + x + dx)];
                near += found;
            }
        return near;
    }
};
LineMask linePixels(const Image& over, const Image& under) {
    LineMask mask{over.width, over.height,
                  std::vector<bool>(std::size_t(over.width) * std::size_t(over.height))};
    for (std::size_t i = 0; i < mask.set.size(); ++i)
        for (std::size_t k = 0; k < 3; ++k)
            mask.set[i] =
                mask.set[i] || std::abs(int(over.rgba[i * 4 + k]) - int(under.rgba[i * 4 + k])) > 30;
    return mask;
}

TEST_F(Browser, OverlayLightDragAndProbeAsInTheWindow) {
    Scene scene = litSphereScene(160, LightType::Point);
    scene.objects[0].subdivisions = 3;
    Session session;
    session.open();
    session.load(scene);
    const std::size_t plain = session.capture();
    const std::size_t press = session.key('W');
    const std::size_t wired = session.ui();
    const std::size_t wire = session.capture();
    session.drag(-60, 0, true);
    const std::size_t moved = session.ui();
    session.click();
    const std::size_t probed = session.ui();
    // A click that takes the keys back from the panel only focuses the canvas; the next one probes.
    session.clickElement("#help-button"); // H: the help shows
    session.clickElement("#help-button"); // and goes; the button keeps the focus
    session.click(120, 80);
    const std::size_t focused = session.ui();
    session.click(120, 80);
    const std::size_t probedAgain = session.ui();
    session.key('K'); // the ambient term alone: the probe's pixel row follows what is drawn
    const std::size_t ambient = session.ui();
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;

    EXPECT_EQ(session.answer(focused).at("ui").at("probe"), session.answer(probed).at("ui").at("probe"))
        << "the click that focused the canvas placed a probe";
    EXPECT_NE(session.answer(probedAgain).at("ui").at("probe"), session.answer(probed).at("ui").at("probe"))
        << "the click on the focused canvas placed no probe";
    EXPECT_EQ(session.answer(press).at("result"), 1);
    const Scene wireState = parseScene(session.answer(wired).at("ui").at("atImageSize").dump(), "page state");
    EXPECT_EQ(wireState.overlay, Overlay::Wireframe);
    // Lines are one pixel wide and SwiftShader rasterizes them by its own rule: the page's edge pixels
    // (those the overlay changed) must lie within a pixel of native's, and be about as many.
    const Image browser = session.image(wire), browserPlain = session.image(plain);
    Scene plainState = wireState;
    plainState.overlay = Overlay::None;
    const Image native = nativeGles().render(wireState), nativePlain = nativeGles().render(plainState);
    const LineMask pageLines = linePixels(browser, browserPlain),
                   nativeLines = linePixels(native, nativePlain);
    const std::size_t pageCount = pageLines.count(), nativeCount = nativeLines.count(),
                      nearNative = pageLines.within1(nativeLines);
    std::printf(
        "wireframe: %zu edge pixels in the page, %zu native, %zu of the page's within 1 px of native's\n",
        pageCount, nativeCount, nearNative);
    EXPECT_GT(nativeCount, 300u);
    EXPECT_NEAR(double(pageCount), double(nativeCount), 0.15 * double(nativeCount));
    EXPECT_GE(double(nearNative), 0.97 * double(pageCount));
    // Away from the lines the picture is native's.
    const Comparison c = compareImages(browserPlain, nativePlain, swiftShaderTolerance(browserPlain));
    EXPECT_TRUE(c.passed) << c.summary();

    const json afterDrag = session.answer(moved).at("ui");
    const Scene dragged = parseScene(afterDrag.at("current").dump(), "page state");
    EXPECT_LT(dragged.lights[0].position.x, scene.lights[0].position.x) << "dragged left";
    EXPECT_NEAR(glm::length(dragged.lights[0].position), glm::length(scene.lights[0].position), 1e-6);
    EXPECT_NE(afterDrag.at("title").get<std::string>().find("light 1 (point) at ("), std::string::npos);

    const json afterClick = session.answer(probed).at("ui");
    const std::string title = afterClick.at("title"), table = afterClick.at("probe");
    EXPECT_NE(title.find("probe: phong differs from exact by "), std::string::npos) << title;
    ASSERT_EQ(table.rfind("probe: object 1, level 3", 0), 0u) << table;
    // The table's exact pixel against the native probe at the canvas's centre (where the click landed,
    // give or take the rounding of CSS pixels: 0.02 covers a pixel's change there).
    const Scene shown = parseScene(afterClick.at("current").dump(), "page state");
    const auto point = pickSurfacePoint(shown, shown.width / 2.0, shown.height / 2.0);
    ASSERT_TRUE(point.has_value());
    const ProbeReport expected = probeSurface(shown, *point, buildSphere(3));
    const std::size_t row = table.find("pixel");
    ASSERT_NE(row, std::string::npos) << table;
    double values[6] = {};
    ASSERT_EQ(std::sscanf(table.c_str() + row, "pixel %lf %lf %lf | %lf %lf %lf", &values[0], &values[1],
                          &values[2], &values[3], &values[4], &values[5]),
              6)
        << table;
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(values[k], expected.mode.color[k], 0.02) << "phong, channel " << k << "\n" << table;
        EXPECT_NEAR(values[3 + k], expected.exact.color[k], 0.02) << "exact, channel " << k << "\n" << table;
    }
    // With K's ambient term drawn, the table's pixel row is its ambient row (both sides), and the point
    // tracer follows the probed point through the lecture's stages.
    const std::string ambientTable = session.answer(ambient).at("ui").at("probe");
    const auto rowOf = [&](const char* name) {
        std::array<double, 6> v{};
        const std::size_t at = ambientTable.find(std::string(name) + " ");
        EXPECT_NE(at, std::string::npos) << name << " in\n" << ambientTable;
        if (at == std::string::npos) return v;
        const std::string format = std::string(name) + " %lf %lf %lf | %lf %lf %lf";
        EXPECT_EQ(
            std::sscanf(ambientTable.c_str() + at, format.c_str(), &v[0], &v[1], &v[2], &v[3], &v[4], &v[5]),
            6)
            << ambientTable;
        return v;
    };
    const std::array<double, 6> pixel = rowOf("pixel"), ambientRow = rowOf("ambient");
    for (std::size_t k = 0; k < 6; ++k)
        EXPECT_NEAR(pixel[k], std::min(1.0, ambientRow[k]), 1e-3) << "column " << k << "\n" << ambientTable;
    for (const char* stage : {"world  α = M·p", "camera β = M_cam·α", "clip   M_proj·β", "NDC    clip/w"})
        EXPECT_NE(ambientTable.find(stage), std::string::npos) << stage << " in\n" << ambientTable;
    expectCleanConsole(session.answer(console).at("console"));
}

// The normals overlay draws the normals the shading uses (issue 46, item 1): on an ellipsoid, J (normals by
// M) moves the drawn normals, and under each rule the page's lines lie where native's do.
TEST_F(Browser, NormalsOverlayFollowsTheNormalMatrix) {
    Scene scene = litSphereScene(160, LightType::Point);
    scene.objects[0].subdivisions = 1;
    scene.objects[0].scale = {1.6, 0.6, 1};
    scene.overlay = Overlay::Normals;
    scene.term = LightingTerm::Ambient; // an even surface under the lines
    Session session;
    session.open();
    session.load(scene);
    const std::size_t rightUi = session.ui(), right = session.capture();
    const std::size_t press = session.key('J');
    const std::size_t modelUi = session.ui(), model = session.capture();
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    EXPECT_EQ(session.answer(press).at("result"), 1);
    LineMask page[2], native[2];
    int k = 0;
    for (const auto& [ui, capture] : {std::pair{rightUi, right}, std::pair{modelUi, model}}) {
        const Scene state = parseScene(session.answer(ui).at("ui").at("atImageSize").dump(), "page state");
        EXPECT_EQ(state.normalMatrix, k == 0 ? NormalMatrixRule::InverseTranspose : NormalMatrixRule::Model);
        Scene plain = state;
        plain.overlay = Overlay::None;
        const Image under = nativeGles().render(plain);
        page[k] = linePixels(session.image(capture), under);
        native[k] = linePixels(nativeGles().render(state), under);
        SCOPED_TRACE(std::string(toString(state.normalMatrix)));
        std::printf("normals by %s: %zu line pixels in the page, %zu native, %zu within 1 px of native's\n",
                    std::string(toString(state.normalMatrix)).c_str(), page[k].count(), native[k].count(),
                    page[k].within1(native[k]));
        EXPECT_GT(native[k].count(), 200u);
        EXPECT_GE(double(page[k].within1(native[k])), 0.95 * double(page[k].count()));
        ++k;
    }
    // The two rules draw different normals: many of one's line pixels are nowhere near the other's.
    const std::size_t moved = page[0].count() - page[0].within1(page[1]);
    EXPECT_GT(moved, 50u) << "J did not move the drawn normals";
    EXPECT_GT(native[0].count() - native[0].within1(native[1]), 50u);
    expectCleanConsole(session.answer(console).at("console"));
}

// Keys 1–4, B, K (each term of the lighting sum, then all), J (normals by M and back), U (the unnegated
// perspective matrix, an empty picture, and back), +, −, O change the page's picture as they change the
// window's: after each, the picture differs from the one before, and it is what native `render` draws for
// the state the page reports.
TEST_F(Browser, KeysChangeThePictureAsInTheWindow) {
    Scene scene = litSphereScene(160, LightType::Point);
    scene.shading = ShadingMode::Toon;
    scene.objects[0].subdivisions = 3;
    scene.objects[0].scale = {1.4, 0.7, 1}; // an ellipsoid: normals by M (J) change its picture
    Session session;
    session.open();
    session.load(scene);
    struct Step {
        const char* key;
        int code;
        std::size_t ui = 0, capture = 0, press = 0;
    };
    // B in Phong shading, where the highlight shows the model (toon's threshold can hide it).
    std::vector<Step> steps = {{"start", 0}, {"1", '1'}, {"2", '2'}, {"4", '4'}, {"5", '5'}, {"3", '3'},
                               {"B", 'B'},   {"K", 'K'}, {"K", 'K'}, {"K", 'K'}, {"K", 'K'}, {"J", 'J'},
                               {"J", 'J'},   {"U", 'U'}, {"U", 'U'}, {"+", '='}, {"-", '-'}, {"O", 'O'}};
    for (Step& step : steps) {
        if (step.code) step.press = session.key(step.code);
        step.ui = session.ui();
        step.capture = session.capture();
    }
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    Image previous;
    for (const Step& step : steps) {
        SCOPED_TRACE(std::string("after key ") + step.key);
        if (step.code) {
            EXPECT_EQ(session.answer(step.press).at("result"), 1) << "the key was not applied";
        }
        const Scene state =
            parseScene(session.answer(step.ui).at("ui").at("atImageSize").dump(), "page state");
        const Image browser = session.image(step.capture);
        const Image native = nativeGles().render(state);
        const Comparison c = compareImages(browser, native, swiftShaderTolerance(browser));
        EXPECT_TRUE(c.passed) << "the page's picture is not native render's of its state: " << c.summary();
        std::printf("key %s: page vs native render of its state: %s\n", step.key, c.summary().c_str());
        if (!previous.rgba.empty()) {
            EXPECT_FALSE(compareImages(browser, previous, kBeyondRounding).passed)
                << "the key did not change the picture";
        }
        previous = browser;
    }
    const json ui = session.answer(steps.back().ui).at("ui");
    EXPECT_TRUE(ui.at("orthographic").get<bool>());
    EXPECT_EQ(ui.at("current").at("lighting"), "phong") << "B from Blinn-Phong";
    EXPECT_EQ(ui.at("current").at("term"), "all") << "K four times: ambient, diffuse, specular, all";
    EXPECT_EQ(ui.at("current").at("normal_matrix"), "inverse-transpose") << "J twice: model, then back";
    EXPECT_EQ(ui.at("current").at("perspective_matrix"), "webgl") << "U twice: unnegated, then back";
    expectCleanConsole(session.answer(console).at("console"));
}

// The NDC view of one flat red unit sphere (ambient light only: SwiftShader and llvmpipe then differ at
// the silhouette alone) from the eye at 8, the sphere spanning distances 7 to 9: cut by the near plane at
// 7.5 or by the far plane at 8.4, each seen from the side of the face that cuts it, under perspective and
// orthographic projection (the scenes of views_test.cpp's
// NdcView.ASphereTheNearOrFarPlaneCutsEndsAtTheCubesFace).
std::vector<Scene> ndcCutScenes() {
    std::vector<Scene> scenes;
    for (const auto& [near, far, azimuthDeg] : {std::tuple{7.5, 10.0, 40.0}, std::tuple{6.0, 8.4, 110.0}})
        for (ProjectionType type : {ProjectionType::Perspective, ProjectionType::Orthographic}) {
            Scene scene;
            scene.width = scene.height = 200;
            scene.eye = {0, 0, 8};
            scene.projection = {type, 40, -2.4, 2.4, -2.4, 2.4, near, far};
            scene.view.kind = ViewKind::Ndc;
            scene.view.observer = {azimuthDeg, 20, 1};
            scene.objects[0].subdivisions = 5;
            scene.objects[0].material = {{0.9, 0, 0}, {0, 0, 0}, {0, 0, 0}, 1};
            Light ambient;
            ambient.type = LightType::Ambient;
            ambient.ambient = {1, 1, 1};
            ambient.diffuse = ambient.specular = glm::dvec3(0);
            scene.lights = {ambient};
            scene.shading = ShadingMode::Flat;
            scenes.push_back(scene);
        }
    return scenes;
}

// The NDC view's clip, per fragment, in shaders/surface.frag.glsl (NDC_VIEW), and the same in x and y only:
// the mutation that must fail the NDC tests.
constexpr const char* kNdcClipInCube = "any(greaterThan(abs(vCameraClip.xyz), vec3(vCameraClip.w)))";
constexpr const char* kNdcClipXyOnly = "any(greaterThan(abs(vCameraClip.xy), vec2(vCameraClip.w)))";

// The teaching views in the page: 5 (exact), E (error), V (split) and a real mouse drag of its divider, I
// (profile) and a pointer move choosing its row. Each picture is native OpenGL ES's render of the page's
// state (its view included) within the SwiftShader tolerance, and the state says what the key did. The
// panel's "what you are seeing" line follows the view and the shading mode (the one table,
// view_explanations.h), and H's help shows the table under the keys. The NDC view's clip in z: spheres
// the near or far plane cuts are drawn cut, as natively; with the page's shader clipping in x and y only
// (a mutation made here, through WebGL's shaderSource) the same pictures fail the comparison.
TEST_F(Browser, ViewsAsInTheWindow) {
    Scene scene = litSphereScene(200, LightType::Point);
    scene.shading = ShadingMode::Gouraud;
    scene.objects[0].subdivisions = 3;
    Session session;
    session.open();
    session.load(scene);
    struct Step {
        const char* what;
        std::function<std::size_t()> act;
        std::size_t done = 0, ui = 0, capture = 0;
    };
    std::vector<Step> steps = {
        {"start", nullptr},
        {"5", [&] { return session.key('5'); }},
        {"E",
         [&] {
             session.key('2');
             return session.key('E');
         }},
        {"V", [&] { return session.key('V'); }},
        {"divider drag", [&] { return session.drag(-40, 0, false); }},
        {"I", [&] { return session.key('I'); }},
        {"pointer move", [&] { return session.move(0, -50); }},
        {"Y", [&] { return session.key('Y'); }},
        {"observer drag", [&] { return session.drag(30, 10, false); }},
        {"Q", [&] { return session.key('Q'); }},
    };
    std::vector<std::size_t> seeing;
    for (Step& step : steps) {
        if (step.act) step.done = step.act();
        step.ui = session.ui();
        step.capture = session.capture();
        seeing.push_back(session.element("#seeing"));
    }
    // The title after Q's picture was captured: its view report is set when the picture is drawn.
    const std::size_t afterQ = session.ui();
    session.key('H');
    const std::size_t help = session.element("#help");
    const std::size_t viewHelp = session.element("#view-help");
    session.key('H');
    // The outside view's corners on the page, as on GL, GLES and OSMesa (views_test.cpp): a volume alone.
    Scene volume;
    volume.width = volume.height = 256;
    volume.eye = {0, 0, 5};
    volume.projection = {ProjectionType::Perspective, 50, -1, 1, -1, 1, 2.5, 7};
    volume.objects.clear();
    volume.lights.clear();
    volume.view.kind = ViewKind::Outside;
    session.load(volume);
    const std::size_t volumeCapture = session.capture();
    const std::vector<Scene> cuts = ndcCutScenes();
    std::vector<std::size_t> cutCaptures, unclippedCaptures;
    for (const Scene& cut : cuts) {
        session.load(cut);
        cutCaptures.push_back(session.capture());
    }
    // Gouraud draws ambient-only flat red as flat does, through another program: compiled after the mutation.
    session.mutateShader(kNdcClipInCube, kNdcClipXyOnly);
    for (Scene cut : cuts) {
        cut.shading = ShadingMode::Gouraud;
        session.load(cut);
        unclippedCaptures.push_back(session.capture());
    }
    const std::size_t mutations = session.shaderMutations();
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    std::vector<json> states;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const Step& step = steps[i];
        SCOPED_TRACE(step.what);
        const json ui = session.answer(step.ui).at("ui");
        states.push_back(ui.at("current"));
        const Scene state = parseScene(ui.at("atImageSize").dump(), "page state");
        const json line = session.answer(seeing[i]).at("element");
        ASSERT_TRUE(line.is_object()) << "no 'what you are seeing' line in the panel";
        EXPECT_EQ(line.at("text"), app::whatYouAreSeeing(state));
        const Image browser = session.image(step.capture);
        const Comparison c =
            compareImages(browser, nativeGles().render(state), swiftShaderTolerance(browser));
        std::printf("%s: view %s; page vs native render of its state: %s\n", step.what,
                    ui.at("view").get<std::string>().c_str(), c.summary().c_str());
        EXPECT_TRUE(c.passed) << c.summary();
    }
    EXPECT_EQ(states[1].at("shading"), "exact");
    EXPECT_EQ(states[2].at("view"), "error");
    EXPECT_EQ(states[3].at("view"), "split:gouraud,exact");
    ASSERT_TRUE(states[4].contains("view_at"));
    EXPECT_LT(states[4].at("view_at").get<double>(), 0.49) << "the drag did not move the divider left";
    EXPECT_EQ(states[4].at("camera"), states[3].at("camera")) << "the divider drag orbited the camera";
    EXPECT_EQ(states[5].at("view"), "profile");
    ASSERT_TRUE(states[6].contains("view_at"));
    EXPECT_LT(states[6].at("view_at").get<double>(), 0.49) << "the pointer above the centre: a row above it";
    EXPECT_NE(session.answer(steps[6].ui).at("ui").at("title").get<std::string>().find("| profile: row "),
              std::string::npos);
    EXPECT_EQ(states[7].at("view"), "outside");
    EXPECT_EQ(states[8].at("camera"), states[7].at("camera"))
        << "the drag orbited the camera, not the observer";
    EXPECT_NE(states[8].at("view_observer"), states[7].at("view_observer")) << "the drag left the observer";
    EXPECT_EQ(states[9].at("view"), "ndc");
    EXPECT_EQ(states[9].at("view_observer"), states[8].at("view_observer")) << "Q keeps the observer";
    EXPECT_TRUE(session.answer(seeing[0]).at("element").at("text").get<std::string>().starts_with("scene: "));
    EXPECT_NE(session.answer(seeing[0]).at("element").at("text").get<std::string>().find("gouraud: "),
              std::string::npos);
    EXPECT_NE(session.answer(seeing[1]).at("element").at("text").get<std::string>().find("exact: "),
              std::string::npos);
    EXPECT_TRUE(session.answer(seeing[9]).at("element").at("text").get<std::string>().starts_with("ndc: "));
    EXPECT_FALSE(session.answer(help).at("element").at("hidden").get<bool>()) << "H shows the help";
    EXPECT_EQ(session.answer(viewHelp).at("element").at("text"), app::viewHelpText());
    const std::string titleAfterQ = session.answer(afterQ).at("ui").at("title");
    EXPECT_NE(titleAfterQ.find("| ndc: observer at azimuth "), std::string::npos) << titleAfterQ;
    const Image& volumeImage = session.image(volumeCapture);
    ASSERT_EQ(volumeImage.width, 256);
    std::string misses;
    for (const std::string& miss : outsideCornerMisses(volumeImage, volume)) misses += miss + "\n";
    EXPECT_EQ(misses, "") << "the view volume's corners on the page";

    EXPECT_GT(session.answer(mutations).at("count").get<int>(), 0)
        << "the NDC view's shader no longer holds the clip test this test mutates: " << kNdcClipInCube;
    for (std::size_t i = 0; i < cuts.size(); ++i) {
        const std::string label = std::string(cuts[i].projection.near > 7 ? "near" : "far") +
                                  " plane cuts, " + std::string(toString(cuts[i].projection.type));
        SCOPED_TRACE(label);
        const Image native = nativeGles().render(cuts[i]);
        const Image& page = session.image(cutCaptures[i]);
        const Image& unclipped = session.image(unclippedCaptures[i]);
        const Comparison cut = compareImages(page, native, swiftShaderTolerance(page));
        const Comparison whole = compareImages(unclipped, native, swiftShaderTolerance(unclipped));
        std::printf("ndc, %s: page vs native %s; the page clipping in x and y only: %s\n", label.c_str(),
                    cut.summary().c_str(), whole.summary().c_str());
        EXPECT_TRUE(cut.passed) << cut.summary();
        EXPECT_FALSE(whole.passed) << "the comparison cannot tell a sphere left whole in z: "
                                   << whole.summary();
        if (!cut.passed || whole.passed) { // to look at
            writePng(page, dir_ / ("ndc-cut-" + std::to_string(i) + ".png"));
            writePng(unclipped, dir_ / ("ndc-whole-" + std::to_string(i) + ".png"));
        }
    }
    expectCleanConsole(session.answer(console).at("console"));
}

// The control panel edits the scene through the same parser as a file: a spot's cutoff from its slider
// reaches the scene and the picture; an attenuation of 0, 0, 0 is refused with the scene's own message.
TEST_F(Browser, PanelEditsGoThroughTheSceneParser) {
    Scene scene = litSphereScene(128, LightType::Spot);
    Session session;
    session.open();
    session.load(scene);
    const std::size_t before = session.capture();
    const std::size_t cutoff = session.panel("#lights input[type=range]", "30");
    const std::size_t widened = session.ui();
    const std::size_t after = session.capture();
    const std::string attenuation =
        "#lights label:nth-of-type(6) input:nth-of-type"; // a, b, c: (1), (2), (3)
    session.panel(attenuation + "(2)", "0");
    session.panel(attenuation + "(3)", "0");
    const std::size_t zero = session.panel(attenuation + "(1)", "0");
    const std::size_t message = session.message();
    // The view volume: a narrower field of view, then the near plane moved through the sphere (3.6 of
    // the eye's 4 to its centre: the front cap is clipped), then a far plane short of near, refused.
    const std::size_t narrowed = session.panel("#fovy", "30", "input");
    const std::size_t clipping = session.panel("#near", std::to_string(std::log10(3.6)), "input");
    const std::size_t clipped = session.capture();
    const std::size_t clippedUi = session.ui();
    const std::size_t matrices = session.element("#matrices");
    session.panel("#far", "-2", "input"); // 0.01, nearer than near
    const std::size_t refused = session.message();
    const std::size_t afterRefusal = session.ui();
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    EXPECT_TRUE(session.answer(cutoff).at("found").get<bool>());
    EXPECT_EQ(session.answer(widened).at("ui").at("scene").at("lights")[0].at("cutoff_deg"), 30);
    EXPECT_FALSE(compareImages(session.image(after), session.image(before), kBeyondRounding).passed)
        << "a wider cone lights more of the sphere";
    Scene wide = scene;
    wide.lights[0].cutoffDeg = 30;
    const Comparison c = compareImages(session.image(after), nativeGles().render(wide),
                                       swiftShaderTolerance(session.image(after)));
    EXPECT_TRUE(c.passed) << c.summary();
    EXPECT_TRUE(session.answer(zero).at("found").get<bool>());
    const std::string shown = session.answer(message).at("message");
    EXPECT_NE(shown.find("attenuation"), std::string::npos) << shown;

    EXPECT_TRUE(session.answer(narrowed).at("found").get<bool>()) << "no field-of-view slider";
    EXPECT_TRUE(session.answer(clipping).at("found").get<bool>()) << "no near-plane slider";
    const Scene clippedScene =
        parseScene(session.answer(clippedUi).at("ui").at("scene").dump(), "page state");
    EXPECT_EQ(clippedScene.projection.fovyDeg, 30);
    EXPECT_EQ(clippedScene.projection.near, 3.6);
    // The page draws what `render` draws of the scene it holds, the clipped cap included.
    Scene expectedClip = wide;
    expectedClip.lights[0].attenuation = clippedScene.lights[0].attenuation; // b and c edited to 0
    expectedClip.projection.fovyDeg = 30;
    expectedClip.projection.near = 3.6;
    const Image& clippedImage = session.image(clipped);
    const Comparison clip =
        compareImages(clippedImage, nativeGles().render(expectedClip), swiftShaderTolerance(clippedImage));
    EXPECT_TRUE(clip.passed) << clip.summary();
    Scene unclipped = expectedClip;
    unclipped.projection.near = 0.5;
    EXPECT_FALSE(compareImages(clippedImage, nativeGles().render(unclipped), Tolerance{2, 0, 0}).passed)
        << "a near plane through the sphere must change the picture";
    const std::string matrixText = session.answer(matrices).at("element").at("text");
    EXPECT_NE(matrixText.find("M_cam = [u v w e]^-1"), std::string::npos) << matrixText;
    EXPECT_NE(matrixText.find("n = -3.6, f = -20"), std::string::npos) << matrixText;
    const std::string refusal = session.answer(refused).at("message");
    EXPECT_NE(refusal.find("projection.far"), std::string::npos) << refusal;
    EXPECT_EQ(session.answer(afterRefusal).at("ui").at("scene").at("projection").at("far"), 20)
        << "a refused edit leaves the view volume as it was";
    expectCleanConsole(session.answer(console).at("console"));
}

// A bad scene shows the command line's own message on the page, and the previous picture stays.
TEST_F(Browser, BadSceneShowsTheCommandLineMessage) {
    const std::string bad =
        R"({ "lights": [ { "type": "point", "position": [3, 3, 5], "attenuation": [1, 0, -1] } ] })";
    std::ofstream(dir_ / "bad.json") << bad;
    const Outcome cli = runShadelab({"render", "bad.json", "--out", "x.png"}, dir_);
    ASSERT_EQ(cli.exitCode, 2) << cli.err;
    ASSERT_TRUE(cli.err.starts_with("shadelab: ")) << cli.err;
    const std::string expected = cli.err.substr(10, cli.err.find('\n') - 10);

    Session session;
    session.open();
    session.load(litSphereScene(96, LightType::Point), "good.json");
    const std::size_t load = session.loadText(bad, "bad.json");
    const std::size_t shown = session.message();
    const std::size_t picture = session.capture();
    const std::size_t notJson = session.loadText("{ \"shading\": ", "cut.json");
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    EXPECT_EQ(session.answer(load).at("message"), expected);
    EXPECT_EQ(session.answer(shown).at("message"), expected) << "the page must show it";
    const Image image = session.image(picture);
    std::size_t covered = 0;
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) covered += image.rgba[i] != 0;
    EXPECT_GT(covered, 1000u) << "the canvas went blank";
    EXPECT_TRUE(session.answer(notJson).at("message").get<std::string>().starts_with("cut.json: "))
        << session.answer(notJson);
    expectCleanConsole(session.answer(console).at("console"));
}

// Resizing the browser resizes the canvas's drawing buffer; the picture in it keeps the scene's aspect,
// the largest that fits (fitPicture, as the window places it), and is what the page draws.
// Then the page on a phone: Chromium's mobile emulation of a 390×844 screen at 2 device pixels per CSS
// pixel, with touch events. The picture comes first and as wide as the screen, the panel below it, nothing
// wider than the screen; a one-finger drag orbits, a two-finger pinch zooms by the ratio of the fingers'
// spread (60 to 90 px: the eye 1.5 times nearer), a tap probes, and the probe's table lies inside the
// screen with none of it cut off. (The page gave the panel half the width and squeezed the picture into
// the other half, 195 px wide, the probe's table scrolled out of sight.) Its screenshot:
// build/web-phone.png.
TEST_F(Browser, CanvasFollowsTheWindowAndAPhoneGetsThePictureFirstAndTouch) {
    Session session;
    session.open();
    const std::size_t wide = session.resize(1200, 600);
    const std::size_t wideUi = session.ui();
    const std::size_t tall = session.resize(700, 900);
    const std::size_t tallUi = session.ui();
    const std::size_t phone = session.phone(390, 844, 2);
    const std::vector<std::string> parts = {"#canvas", "#panel", "#probe"};
    const std::size_t before = session.layout(parts);
    const std::size_t start = session.ui();
    session.touchDrag(80, 0);
    const std::size_t dragged = session.ui();
    session.pinch(60, 90);
    const std::size_t pinched = session.ui();
    session.tap();
    const std::size_t tapped = session.ui();
    const std::size_t after = session.layout(parts);
    session.screenshot(fs::path(SHADELAB_BUILD_DIR) / "web-phone.png");
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    for (auto [resize, ui] : {std::pair{wide, wideUi}, std::pair{tall, tallUi}}) {
        const json canvas = session.answer(resize).at("canvas"); // [width, height, clientWidth, clientHeight]
        const json shown = session.answer(ui).at("ui");
        const json image = shown.at("current").at("image"), own = shown.at("scene").at("image");
        EXPECT_EQ(canvas[0], canvas[2]) << canvas;
        EXPECT_EQ(canvas[1], canvas[3]) << canvas;
        const app::PictureRect picture =
            app::fitPicture(own.at("width"), own.at("height"), canvas[0], canvas[1]);
        EXPECT_EQ(image.at("width"), picture.width) << canvas;
        EXPECT_EQ(image.at("height"), picture.height) << canvas;
    }
    const json w = session.answer(wide).at("canvas"), t = session.answer(tall).at("canvas");
    EXPECT_GT(w[0].get<int>(), w[1].get<int>()) << "a wide window gives a wide canvas";
    EXPECT_LT(t[0].get<int>(), t[1].get<int>()) << "a tall window gives a tall canvas";

    const json p = session.answer(phone).at("canvas");
    EXPECT_EQ(p[0].get<int>(), 2 * p[2].get<int>()) << "the drawing buffer at 2 pixels per CSS pixel: " << p;
    for (const std::size_t measured : {before, after}) {
        const json layout = session.answer(measured).at("layout");
        const double width = layout.at("innerWidth");
        const json canvas = layout.at("elements").at("#canvas"), panel = layout.at("elements").at("#panel");
        SCOPED_TRACE(layout.dump());
        EXPECT_EQ(width, 390);
        EXPECT_LE(layout.at("scrollWidth").get<double>(), width) << "the page is wider than the screen";
        EXPECT_NEAR(canvas.at("left").get<double>(), 0, 1);
        EXPECT_NEAR(canvas.at("width").get<double>(), width, 1) << "the picture is not the screen's width";
        EXPECT_LE(canvas.at("bottom").get<double>(), panel.at("top").get<double>())
            << "the panel is not below it";
    }
    const auto eye = [&](std::size_t ui) {
        const json camera = session.answer(ui).at("ui").at("current").at("camera");
        return glm::dvec3(camera.at("eye")[0], camera.at("eye")[1], camera.at("eye")[2]) -
               glm::dvec3(camera.at("target")[0], camera.at("target")[1], camera.at("target")[2]);
    };
    EXPECT_GT(glm::length(eye(dragged) - eye(start)), 0.5) << "the drag did not orbit the camera";
    EXPECT_NEAR(glm::length(eye(dragged)), glm::length(eye(start)), 1e-9) << "the drag zoomed";
    EXPECT_NEAR(glm::length(eye(dragged)) / glm::length(eye(pinched)), 1.5, 0.02) << "the pinch's zoom";
    const std::string table = session.answer(tapped).at("ui").at("probe");
    EXPECT_EQ(table.rfind("probe: object 1,", 0), 0u) << "the tap placed no probe: " << table;
    const json layout = session.answer(after).at("layout");
    const json probe = layout.at("elements").at("#probe");
    EXPECT_GE(probe.at("left").get<double>(), 0) << probe;
    EXPECT_LE(probe.at("right").get<double>(), layout.at("innerWidth").get<double>()) << probe;
    EXPECT_LE(probe.at("scrollWidth").get<double>(), probe.at("clientWidth").get<double>())
        << "the probe's table is cut off at its box's edge: " << probe;
    expectCleanConsole(session.answer(console).at("console"));
}

// S saves what the window's S saves: the picture as an opaque PNG and the scene JSON that draws it, here as
// two downloads. The PNG is the canvas's picture (native render of the saved JSON agrees), the JSON the
// state. Also the picture of the page for the README (build/web-page.png, copied to docs/ by hand).
TEST_F(Browser, SDownloadsThePictureAndItsScene) {
    Session session;
    session.open("", {}, dir_);
    const std::size_t canvas = session.resize(1280, 800);
    const std::size_t shot = session.screenshot(fs::path(SHADELAB_BUILD_DIR) / "web-page.png");
    session.key('M'); // a material preset, so the JSON is not the file the page started with
    const std::size_t press = session.key('S');
    const std::size_t files = session.waitFiles({dir_ / "shadelab-001.png", dir_ / "shadelab-001.json"});
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    (void)shot;
    EXPECT_EQ(session.answer(press).at("result"), 2);
    ASSERT_EQ(session.answer(files).at("present"), json::array({true, true}));
    const Image png = readPng(dir_ / "shadelab-001.png");
    const Scene saved = loadScene(dir_ / "shadelab-001.json");
    EXPECT_EQ(png.width, saved.width);
    EXPECT_EQ(png.height, saved.height);
    // The picture without the bars: the showcase's square at its size in the canvas.
    const json size = session.answer(canvas).at("canvas");
    const Scene showcase = loadScene(fs::path(SHADELAB_WEB_BUILD) / "scenes" / "showcase.json");
    const app::PictureRect picture = app::fitPicture(showcase.width, showcase.height, size[0], size[1]);
    EXPECT_EQ(png.width, picture.width) << size;
    EXPECT_EQ(png.height, picture.height) << size;
    EXPECT_NE(saved.objects.at(0).material.shininess, 24.0) << "the material preset is not in the JSON";
    const Comparison c = compareImages(png, nativeGles().render(saved), swiftShaderTolerance(png));
    EXPECT_TRUE(c.passed) << c.summary();
    expectCleanConsole(session.answer(console).at("console"));
}

// Presentation mode in the page: ?present shows the large label (the window's words), F2 hides it.
TEST_F(Browser, PresentationLabelShowsAndF2HidesIt) {
    Session session;
    session.open("?present");
    const std::size_t ui = session.ui();
    const std::size_t canvas = session.resize(1280, 720);
    session.screenshot(dir_ / "with-label.png");
    session.key(kKeyF2);
    session.screenshot(dir_ / "without.png");
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    const std::string label = session.answer(ui).at("ui").at("presentation");
    EXPECT_TRUE(label.starts_with("PHONG SHADING\nBLINN-PHONG LIGHTING\nLEVEL 3")) << label;
    // The label is drawn into the picture by the same code as the window's (FramedPicture with
    // presentationLabelImage), so the page shows it where and as large as that layout says: the pixels
    // that F2 changes are those of the label's box at the bottom left of the picture (the scene's framing
    // in the canvas, between bars), and most of the box.
    const Image a = readPng(dir_ / "with-label.png"), b = readPng(dir_ / "without.png");
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    const json size = session.answer(canvas).at("canvas"); // drawing buffer, then CSS size
    const json own = session.answer(ui).at("ui").at("scene").at("image");
    const app::PictureRect picture = app::fitPicture(own.at("width"), own.at("height"), size[0], size[1]);
    const auto layout = shadelab::app::presentationLabelImage(label, picture.width, picture.height);
    int minX = a.width, minY = a.height, maxX = -1, maxY = -1, changed = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            if (!std::equal(a.pixel(x, y), a.pixel(x, y) + 3, b.pixel(x, y))) {
                ++changed;
                minX = std::min(minX, x), maxX = std::max(maxX, x), minY = std::min(minY, y),
                maxY = std::max(maxY, y);
            }
    ASSERT_GT(changed, 0) << "F2 changed nothing: no label was drawn";
    // The canvas is the page's right part, as tall as the page (the screenshot's CSS pixels at ratio 1).
    const int canvasLeft = a.width - size[0].get<int>();
    EXPECT_EQ(minX, canvasLeft + picture.x + layout.margin) << "the box's left edge";
    EXPECT_EQ(maxY, picture.y + picture.height - layout.margin - 1) << "the box's bottom edge";
    EXPECT_EQ(maxX - minX + 1, layout.image.width) << "the box is as wide as the layout says";
    EXPECT_EQ(maxY - minY + 1, layout.image.height) << "the box is as tall as the layout says";
    expectCleanConsole(session.answer(console).at("console"));
}

// A lecturer's lesson folder (scripts/web.sh serve --lessons DIR) with one lesson, whose name is markup,
// naming a scene in a subfolder; beside it what must not be listed or served: a scene, a file that is no
// JSON, a hidden lesson, and a link to a lesson outside the folder.
constexpr const char* kOwnLessonName = "<img src=x onerror=alert(1)>.json";
fs::path makeLessonFolder(const fs::path& dir) {
    const fs::path folder = dir / "own", outside = dir / "outside";
    fs::create_directories(folder / "scenes");
    fs::create_directories(outside);
    const std::string lesson = R"({"title": "Own <i>lesson</i>", "steps": [
      {"title": "Ring", "caption": "A scene of my own.", "scene": "scenes/ring.json"},
      {"title": "Gouraud", "caption": "The same, Gouraud.", "shading": "gouraud"}]})";
    std::ofstream(folder / kOwnLessonName) << lesson;
    std::ofstream(folder / "scenes" / "ring.json")
        << R"({"image": {"width": 160, "height": 120}, "shading": "flat", "objects": [{"subdivisions": 2}]})";
    std::ofstream(folder / "plain.json") << R"({"shading": "flat"})";
    std::ofstream(folder / "broken.json") << "{\"steps\": ";
    std::ofstream(folder / ".hidden.json") << lesson;
    std::ofstream(outside / "secret.json") << R"({"title": "Not yours", "steps": []})";
    fs::create_symlink(outside / "secret.json", folder / "linked.json");
    return folder;
}

// Lessons in the page: the bundled lesson by ?lesson=URL, its scene files fetched beside it (../scenes/),
// every one of its steps drawn by the page as natively at 320×180, the picker naming it; then a lesson
// loaded as a file steps with Page Down, Space, Page Up and the panel's ▶ button, each step's picture native
// OpenGL ES's render of that step's scene, and R returns to a changed step; the panel shows the step. A
// lecturer's own lesson (scripts/web.sh serve --lessons DIR) is in the picker, as text, and loads from it.
TEST_F(Browser, LessonStepsWithKeysAndButtonsAndTheBundledLessonDrawsEveryStep) {
    const std::string text = R"({"title": "Three steps", "steps": [
      {"title": "One", "caption": "Flat at level 2.", "scene": {"image": {"width": 160, "height": 120},
       "shading": "flat", "objects": [{"subdivisions": 2}]}},
      {"title": "Two", "caption": "Gouraud.", "shading": "gouraud"},
      {"title": "Three", "caption": "Phong, Blinn-Phong.", "shading": "phong", "lighting": "blinn-phong"}]})";
    const Lesson lesson = parseLesson(text, "three.json", [](const std::string&) -> std::string {
        throw std::logic_error("no scene files");
    });
    const fs::path bundledPath = fs::path(SHADELAB_WEB_BUILD) / "lessons" / "lighting.json";
    const Lesson bundled = loadLesson(bundledPath);
    // One page for both parts (a Chromium start is about 6 CPU-seconds), its canvas small: each step key
    // redraws it, and SwiftShader's time goes with its size.
    const fs::path own = makeLessonFolder(dir_);
    const Lesson ownLesson = loadLesson(own / kOwnLessonName);
    Session session;
    session.openWith("?lesson=lessons/lighting.json", {{"lessons", own.string()}});
    session.resize(640, 400);
    const std::size_t bundledUi = session.ui();
    const std::size_t bundledMessage = session.message();
    const std::size_t picker = session.element("#bundled");
    std::vector<std::size_t> bundledCaptures;
    for (std::size_t i = 0; i < bundled.steps.size(); ++i) {
        bundledCaptures.push_back(session.capture(320, 180));
        session.key(kKeyPageDown);
    }
    const std::size_t load = session.loadText(text, "three.json");
    struct Shown {
        const char* after;
        std::size_t step;
        std::size_t ui = 0, capture = 0;
    };
    std::vector<Shown> shown = {{"load", 0}, {"Page Down", 1}, {"Space", 2}, {"Page Up", 1}, {"R", 1}};
    const std::vector<int> keys = {0, kKeyPageDown, kKeySpace, kKeyPageUp, 'R'};
    std::size_t changed = 0;
    for (std::size_t i = 0; i < shown.size(); ++i) {
        if (keys[i] == 'R') {
            session.key('1'); // a key inside the step: flat shading
            changed = session.capture();
        }
        if (keys[i] != 0) session.key(keys[i]);
        shown[i].ui = session.ui();
        shown[i].capture = session.capture();
    }
    session.panel("#step-next", "", "click");
    const std::size_t afterButton = session.ui();
    const std::size_t caption = session.element("#step-caption");
    const std::size_t position = session.element("#step-out");
    // The lecturer's folder (--lessons): its one lesson in the picker, its name as text; picked, it loads
    // with the scene it names from the folder.
    const std::size_t ownOption = session.element("#bundled option[value^=\"own:\"]");
    const std::size_t secondOwn =
        session.element("#bundled option[value^=\"own:\"] ~ option[value^=\"own:\"]");
    session.panel("#bundled", std::string("own:") + kOwnLessonName);
    session.waitUi({"lesson", "title"}, "Own <i>lesson</i>"); // the picker's load fetches lesson and scene
    const std::size_t ownUi = session.ui();
    const std::size_t ownPicture = session.capture();
    const std::size_t ownTitle = session.element("#lesson-title");
    const std::size_t markup = session.element("img");
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;

    const json option = session.answer(ownOption).at("element");
    ASSERT_TRUE(option.is_object()) << "the lecturer's lesson is not in the picker";
    EXPECT_EQ(option.at("text"), std::string("own lesson: ") + kOwnLessonName);
    EXPECT_TRUE(session.answer(secondOwn).at("element").is_null())
        << "listed beside the lesson: " << session.answer(secondOwn);
    const json ownShown = session.answer(ownUi).at("ui");
    ASSERT_TRUE(ownShown.at("lesson").is_object()) << ownShown.at("error");
    EXPECT_EQ(ownShown.at("lesson").at("title"), "Own <i>lesson</i>");
    EXPECT_EQ(session.answer(ownTitle).at("element").at("text"), "Own <i>lesson</i>");
    EXPECT_TRUE(session.answer(markup).at("element").is_null()) << "a name or title became markup";
    const Image ownImage = session.image(ownPicture);
    const Comparison ownCompared = compareImages(ownImage, nativeGles().render(ownLesson.steps[0].scene),
                                                 swiftShaderTolerance(ownImage));
    EXPECT_TRUE(ownCompared.passed) << "the lecturer's step 1: " << ownCompared.summary();

    EXPECT_EQ(session.answer(load).at("message"), "") << "the lesson loads";
    for (const Shown& s : shown) {
        SCOPED_TRACE(std::string("after ") + s.after);
        const json lessonUi = session.answer(s.ui).at("ui").at("lesson");
        ASSERT_TRUE(lessonUi.is_object()) << "no lesson in the panel";
        EXPECT_EQ(lessonUi.at("step"), s.step + 1);
        EXPECT_EQ(lessonUi.at("steps"), 3);
        const Image page = session.image(s.capture);
        const Image native = nativeGles().render(lesson.steps[s.step].scene);
        const Comparison c = compareImages(page, native, swiftShaderTolerance(page));
        EXPECT_TRUE(c.passed) << "the page's picture is not native render's of step " << s.step + 1 << ": "
                              << c.summary();
    }
    EXPECT_FALSE(
        compareImages(session.image(changed), session.image(shown.back().capture), kBeyondRounding).passed)
        << "the key inside the step changed nothing (R then had nothing to restore)";
    EXPECT_EQ(session.answer(afterButton).at("ui").at("lesson").at("step"), 3) << "the ▶ button";
    EXPECT_EQ(session.answer(caption).at("element").at("text"), "Phong, Blinn-Phong.");
    EXPECT_EQ(session.answer(position).at("element").at("text"), "step 3 of 3");

    EXPECT_EQ(session.answer(bundledMessage).at("message"), "") << "the bundled lesson loads by its URL";
    EXPECT_EQ(session.answer(bundledUi).at("ui").at("lesson").at("steps"), bundled.steps.size());
    EXPECT_EQ(session.answer(picker).at("element").at("value"), "lesson:lighting.json")
        << "the picker names the bundled lesson";
    for (std::size_t i = 0; i < bundled.steps.size(); ++i) {
        SCOPED_TRACE("bundled lesson, step " + std::to_string(i + 1) + ": " + bundled.steps[i].title);
        Scene scene = bundled.steps[i].scene;
        scene.width = 320;
        scene.height = 180;
        const Image page = session.image(bundledCaptures[i]);
        const Comparison c = compareImages(page, nativeGles().render(scene), swiftShaderTolerance(page));
        EXPECT_TRUE(c.passed) << c.summary();
    }
    expectCleanConsole(session.answer(console).at("console"));
}

// The page's gaps: the picker names a bundled scene opened by ?scene=; the view menu says what
// the split draws; every warning the command line prints for a scene shows on the page; the probe's table
// keeps its columns (no wrapping); every menu stays inside its box; a spot's cutoff and exponent sliders
// show their numbers; Esc's note goes away by itself.
TEST_F(Browser, PickerViewMenuWarningsProbeSlidersAndEscAsTheCommandLineHasThem) {
    const std::string colourScene = R"({"image": {"width": 64, "height": 64},
      "lights": [{"type": "spot", "position": [0, 2, 4], "direction": [0, -0.4, -1], "cutoff_deg": 27.5,
                  "exponent": 12, "diffuse": [200, 30, 30]}]})";
    std::ofstream(dir_ / "colour.json") << colourScene;
    const Outcome cli =
        runWith({"render", (dir_ / "colour.json").string(), "--out", (dir_ / "c.png").string()}, dir_);
    ASSERT_EQ(cli.exitCode, 0) << describe(cli);
    std::vector<std::string> cliWarnings; // "shadelab: warning: FILE: WARNING", FILE the path given
    for (std::size_t at = 0; (at = cli.err.find("shadelab: warning: ", at)) != std::string::npos;) {
        const std::size_t start = cli.err.find(": ", cli.err.find("colour.json", at)) + 2;
        const std::size_t end = cli.err.find('\n', start);
        cliWarnings.push_back(cli.err.substr(start, end - start));
        at = end;
    }
    ASSERT_FALSE(cliWarnings.empty()) << "the command line warned of nothing: " << cli.err;

    Session session;
    session.open("?scene=scenes/grid.json&view=split:flat,gouraud");
    const std::size_t picker = session.element("#bundled");
    const std::size_t split = session.element("#view-kind option[value=\"split\"]");
    const std::size_t probeStyle = session.element("#probe");
    const std::vector<std::string> selects = {
        "#bundled",       "#shading",    "#lighting", "#term",    "#perspective-matrix",
        "#normal-matrix", "#projection", "#normals",  "#overlay", "#view-kind"};
    const std::size_t menus = session.layout(selects);
    session.loadText(colourScene, "colour.json");
    const std::size_t warnings = session.element("#warnings");
    const std::size_t slider = session.element("#lights output");
    session.key(256); // Esc
    const std::size_t escNote = session.element("#message");
    session.sleep(4.5);
    const std::size_t later = session.element("#message");
    if (!session.run(dir_)) return;
    EXPECT_EQ(session.answer(picker).at("element").at("value"), "grid.json");
    EXPECT_EQ(session.answer(split).at("element").at("text"), "split: flat | gouraud (V)");
    EXPECT_EQ(session.answer(probeStyle).at("element").at("whiteSpace"), "pre");
    // Every menu inside its fieldset's box (the view menu's longest option pushed it 8 px past it).
    for (const std::string& select : selects) {
        const json box = session.answer(menus).at("layout").at("elements").at(select);
        ASSERT_TRUE(box.is_object()) << select;
        EXPECT_LE(box.at("right").get<double>(), box.at("fieldset").at("right").get<double>()) << select;
        EXPECT_GE(box.at("left").get<double>(), box.at("fieldset").at("left").get<double>()) << select;
    }
    const json shown = session.answer(warnings).at("element");
    EXPECT_FALSE(shown.at("hidden").get<bool>());
    for (const std::string& warning : cliWarnings)
        EXPECT_NE(shown.at("text").get<std::string>().find("warning: colour.json: " + warning),
                  std::string::npos)
            << "the command line's warning '" << warning << "' is not on the page: " << shown;
    EXPECT_EQ(session.answer(slider).at("element").at("text"), "27.5") << "the cutoff slider's number";
    EXPECT_FALSE(session.answer(escNote).at("element").at("hidden").get<bool>());
    EXPECT_TRUE(session.answer(later).at("element").at("hidden").get<bool>()) << "Esc's note stayed";
}

// The page frames a scene as `render` does, with the window's code (fitPicture, FramedPicture).
// grid.json (800x600, four columns of spheres) in a canvas narrower than 4:3 (bars above and below) and in
// a wider one (bars at the sides): what differs from the bars' colour is the largest rectangle of the
// scene's aspect, centred, where the page says the picture is; its pixels are native render's of grid.json
// at that size (the SwiftShader tolerance); and every canvas pixel around it is one colour. The page drew
// the scene at the canvas's aspect, cutting half of the fourth column off in the narrow canvas.
TEST_F(Browser, WideScenesKeepTheirFramingBetweenBars) {
    const Scene grid = loadScene(fs::path(SHADELAB_WEB_BUILD) / "scenes" / "grid.json");
    Session session;
    session.open("?scene=scenes/grid.json");
    struct Case {
        std::string name;
        int windowWidth;
        std::size_t canvas = 0, ui = 0;
    };
    std::vector<Case> cases = {{"narrow", 900}, {"wide", 1280}}; // canvases of about 560x657 and 940x657
    for (Case& c : cases) {
        c.canvas = session.resize(c.windowWidth, 800);
        c.ui = session.ui();
        session.screenshot(dir_ / (c.name + ".png"));
    }
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const json size = session.answer(c.canvas).at("canvas");
        const int width = size[0], height = size[1];
        const Image shot = readPng(dir_ / (c.name + ".png"));
        // The canvas is the page's right part, as tall as the page (the screenshot's CSS pixels at ratio 1).
        ASSERT_GE(shot.width, width);
        ASSERT_GE(shot.height, height);
        const int left = shot.width - width;
        const std::uint8_t* bar = shot.pixel(left, 0); // a corner of the canvas: a bar in both cases
        auto isBar = [&](int x, int y) { return std::equal(bar, bar + 3, shot.pixel(left + x, y)); };
        int minX = width, minY = height, maxX = -1, maxY = -1;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                if (!isBar(x, y)) {
                    minX = std::min(minX, x), maxX = std::max(maxX, x);
                    minY = std::min(minY, y), maxY = std::max(maxY, y);
                }
        ASSERT_GE(maxX, 0) << "the canvas is one colour";
        const app::PictureRect seen{minX, minY, maxX - minX + 1, maxY - minY + 1};
        std::printf("%s: canvas %dx%d, picture %dx%d at (%d, %d)\n", c.name.c_str(), width, height,
                    seen.width, seen.height, seen.x, seen.y);
        // The scene's aspect within one pixel's rounding, centred, touching two sides of the canvas.
        const app::PictureRect fitted = app::fitPicture(grid.width, grid.height, width, height);
        EXPECT_EQ(seen.x, fitted.x);
        EXPECT_EQ(seen.y, fitted.y);
        EXPECT_EQ(seen.width, fitted.width);
        EXPECT_EQ(seen.height, fitted.height);
        EXPECT_LE(std::abs(seen.width * grid.height - seen.height * grid.width),
                  std::max(grid.width, grid.height))
            << "not the scene's aspect";
        EXPECT_TRUE(seen.width == width || seen.height == height) << "not the largest that fits";
        const json picture = session.answer(c.ui).at("ui").value("picture", json::object());
        EXPECT_EQ(picture,
                  json({{"x", seen.x}, {"y", seen.y}, {"width", seen.width}, {"height", seen.height}}))
            << "where the page says the picture is";

        // The bars: every canvas pixel outside the picture is the corner's colour (they exist: the aspects
        // differ); inside it, the picture is native render's of the scene at the picture's size.
        std::size_t barPixels = 0, otherColour = 0;
        Image inside(fitted.width, fitted.height);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                if (fitted.contains(x, y)) {
                    std::copy_n(shot.pixel(left + x, y), 4, inside.pixel(x - fitted.x, y - fitted.y));
                } else {
                    ++barPixels;
                    otherColour += !isBar(x, y);
                }
            }
        EXPECT_GT(barPixels, std::size_t(width)) << "no bars";
        EXPECT_EQ(otherColour, 0u) << "bar pixels not of the bars' one colour";
        Scene sized = grid;
        sized.width = fitted.width;
        sized.height = fitted.height;
        const Comparison compared =
            compareImages(inside, nativeGles().render(sized), swiftShaderTolerance(inside));
        std::printf("%s: the picture vs native render of grid.json at its size: %s\n", c.name.c_str(),
                    compared.summary().c_str());
        EXPECT_TRUE(compared.passed) << compared.summary();
    }
    expectCleanConsole(session.answer(console).at("console"));
}

// The page's material controls edit the object chosen (0: all objects), as the window's panel
// does (DemoState::chooseEditedObject and editMaterial), and a probe click chooses the object it hits.
// grid.json's twelve spheres each have their own shininess: choosing object 7 and moving the shininess
// slider changes object 7's alone, and the panel says "panel edits: object 7 of 12"; a click on the second
// sphere makes it the edited object, and the sliders then show its values; with all objects chosen the
// slider sets that property of every object. The page showed objects[0]'s values and copied an edit to
// every object.
TEST_F(Browser, MaterialControlsEditTheChosenObjectAndAProbeClickChoosesIt) {
    const Scene grid = loadScene(fs::path(SHADELAB_WEB_BUILD) / "scenes" / "grid.json");
    ASSERT_EQ(grid.objects.size(), 12u);
    // The second sphere's middle, in CSS pixels from the canvas's centre (the picture's centre), for the
    // picture a 1280x800 window gives (876x657); checked below against the picture the page reports.
    Scene nominal = grid;
    nominal.width = 876;
    nominal.height = 657;
    double sumX = 0, sumY = 0, hits = 0;
    for (int y = 0; y < nominal.height; y += 2)
        for (int x = 0; x < nominal.width; x += 2)
            if (const auto point = pickSurfacePoint(nominal, x + 0.5, y + 0.5); point && point->object == 1) {
                sumX += x + 0.5, sumY += y + 0.5, ++hits;
            }
    ASSERT_GT(hits, 100);
    const int clickX = int(std::lround(sumX / hits - nominal.width / 2.0));
    const int clickY = int(std::lround(sumY / hits - nominal.height / 2.0));

    Session session;
    session.open("?scene=scenes/grid.json");
    const std::size_t canvas = session.resize(1280, 800);
    const std::size_t chose = session.panel("#object", "7");
    const std::size_t slid = session.panel("#shininess", "1.5", "input"); // log10: 31.6
    const std::size_t edited = session.ui();
    const std::size_t editedValue = session.element("#shininess-out");
    session.click(clickX, clickY);
    const std::size_t clicked = session.ui();
    const std::size_t chooser = session.element("#object");
    const std::size_t clickedValue = session.element("#shininess-out");
    session.panel("#object", "0");             // all objects
    session.panel("#shininess", "2", "input"); // log10: 100
    const std::size_t all = session.ui();
    // The scale sliders (the normal-matrix lesson's ellipsoid): object 3's x, then every object's y.
    session.panel("#object", "3");
    const std::size_t scaled = session.panel("#scale-x", "2.5", "input");
    const std::size_t scaledValue = session.element("#scale-out");
    session.panel("#object", "0");
    session.panel("#scale-y", "0.5", "input");
    const std::size_t allScaled = session.ui();
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;

    EXPECT_TRUE(session.answer(chose).at("found").get<bool>()) << "no object chooser on the page";
    ASSERT_TRUE(session.answer(slid).at("found").get<bool>()) << "no shininess slider";
    const json afterEdit = session.answer(edited).at("ui");
    const std::string status = afterEdit.at("status");
    EXPECT_NE(status.find("panel edits: object 7 of 12"), std::string::npos) << status;
    EXPECT_NE(status.find("material: scene's own, edited in the panel"), std::string::npos) << status;
    EXPECT_EQ(afterEdit.at("editedObject"), 7);
    const Scene afterEditScene = parseScene(afterEdit.at("scene").dump(), "page state");
    ASSERT_EQ(afterEditScene.objects.size(), 12u);
    for (std::size_t i = 0; i < 12; ++i) {
        SCOPED_TRACE("object " + std::to_string(i + 1));
        Material expected = grid.objects[i].material;
        if (i == 6) expected.shininess = 31.6;
        EXPECT_EQ(afterEditScene.objects[i].material, expected)
            << "shininess " << afterEditScene.objects[i].material.shininess;
    }
    EXPECT_EQ(session.answer(editedValue).at("element").at("text"), "31.6");

    // The click landed on the second sphere of the picture the page drew (else the window gave another size).
    const json afterClick = session.answer(clicked).at("ui");
    const json size = session.answer(canvas).at("canvas"), picture = afterClick.at("picture");
    const Scene shown = parseScene(afterClick.at("current").dump(), "page state");
    const double pictureX = size[0].get<int>() / 2.0 + clickX - picture.at("x").get<int>();
    const double pictureY = size[1].get<int>() / 2.0 + clickY - picture.at("y").get<int>();
    const auto hit = pickSurfacePoint(shown, pictureX, pictureY);
    ASSERT_TRUE(hit && hit->object == 1) << "the click at (" << pictureX << ", " << pictureY
                                         << ") of the picture missed the second sphere: " << picture;
    const std::string clickedStatus = afterClick.at("status"), table = afterClick.at("probe");
    EXPECT_EQ(table.rfind("probe: object 2,", 0), 0u) << table;
    EXPECT_EQ(afterClick.at("editedObject"), 2);
    EXPECT_NE(clickedStatus.find("panel edits: object 2 of 12"), std::string::npos) << clickedStatus;
    EXPECT_EQ(session.answer(chooser).at("element").at("value"), "2");
    char own[16];
    std::snprintf(own, sizeof own, "%.1f", grid.objects[1].material.shininess);
    EXPECT_EQ(session.answer(clickedValue).at("element").at("text"), own) << "the slider shows object 2's";
    const Scene afterClickScene = parseScene(afterClick.at("scene").dump(), "page state");
    EXPECT_EQ(afterClickScene.objects.at(6).material.shininess, 31.6) << "a click edits nothing";

    // All objects, chosen explicitly: the slider sets every object's shininess, and each keeps the rest of
    // its own material (the grid's rows differ in specular).
    const json afterAll = session.answer(all).at("ui");
    const std::string allStatus = afterAll.at("status");
    EXPECT_NE(allStatus.find("panel edits: all 12 objects"), std::string::npos) << allStatus;
    const Scene allScene = parseScene(afterAll.at("scene").dump(), "page state");
    ASSERT_EQ(allScene.objects.size(), 12u);
    for (std::size_t i = 0; i < 12; ++i) {
        SCOPED_TRACE("object " + std::to_string(i + 1));
        Material expected = grid.objects[i].material;
        expected.shininess = 100;
        EXPECT_EQ(allScene.objects[i].material, expected)
            << "shininess " << allScene.objects[i].material.shininess;
    }

    // Object 3 got x = 2.5; then every object y = 0.5, each keeping its x (as the material sliders).
    ASSERT_TRUE(session.answer(scaled).at("found").get<bool>()) << "no scale slider";
    EXPECT_EQ(session.answer(scaledValue).at("element").at("text"), "2.50 1.00 1.00");
    const Scene scaledScene = parseScene(session.answer(allScaled).at("ui").at("scene").dump(), "page state");
    ASSERT_EQ(scaledScene.objects.size(), 12u);
    for (std::size_t i = 0; i < 12; ++i) {
        SCOPED_TRACE("object " + std::to_string(i + 1));
        EXPECT_EQ(scaledScene.objects[i].scale, glm::dvec3(i == 2 ? 2.5 : 1, 0.5, 1))
            << "scale " << scaledScene.objects[i].scale.x << " " << scaledScene.objects[i].scale.y;
    }
    expectCleanConsole(session.answer(console).at("console"));
}

// Where WebGL 2 is missing the page says so, never a blank canvas.
TEST_F(Browser, WithoutWebGl2ThePageSaysSo) {
    Session session;
    const std::size_t open = session.open("", {"--disable-webgl2"});
    if (!session.run(dir_)) return;
    EXPECT_NE(session.answer(open).at("failed").get<std::string>().find("no WebGL 2"), std::string::npos)
        << session.answer(open);
}

// Scenes pass through the heap: one over about 1.3 MB (or a panel edit of 10,000 objects, 1.6 MB of JSON)
// threw "memory access out of bounds" and left the page dead. Up to the CLI's 16 MiB loads; beyond it the
// CLI's own message; the page draws on after each, and its panel edits apply to all 10,000 objects. (The
// panel's twice-a-second refresh read the 10,000 objects' JSON three times over, so every call to the
// page waited 10 s, and each material slider step took 2 s: it now reads the scene's values and the shown
// object's material only.)
TEST_F(Browser, LargeScenesLoadAndTooLargeOnesGetTheCommandLineMessage) {
    std::string objects;
    for (int i = 0; i < 10000; ++i)
        objects += std::string(i ? ", " : "") + R"({"center": [)" + std::to_string(i % 100 * 0.05 - 2.5) +
                   ", " + std::to_string(i / 100 * 0.05 - 2.5) +
                   R"(, -3], "radius": 0.02, "subdivisions": 0})";
    std::ofstream(dir_ / "many.json")
        << R"({"image": {"width": 96, "height": 96}, "objects": [)" << objects << "]}";
    std::ofstream(dir_ / "padded.json")
        << R"({"image": {"width": 96, "height": 96})" << std::string(3 << 20, ' ') << "}";
    std::ofstream(dir_ / "huge.json")
        << R"({"image": {"width": 96, "height": 96})" << std::string(17 << 20, ' ') << "}";
    const Outcome cli = runShadelab({"render", "huge.json", "--out", "x.png"}, dir_);
    ASSERT_EQ(cli.exitCode, 2) << cli.err;
    const std::string expected = cli.err.substr(10, cli.err.find('\n') - 10); // less "shadelab: "

    Session session;
    session.open();
    const std::size_t padded = session.loadFile(dir_ / "padded.json", "padded.json");
    const std::size_t huge = session.loadFile(dir_ / "huge.json", "huge.json");
    const std::size_t many = session.loadFile(dir_ / "many.json", "many.json");
    // The toon bands' edit (as a light's) hands back the scene's values; its objects stay.
    const std::size_t edit = session.panel("#bands", "7", "input");
    const std::size_t after = session.message();
    // A material slider with every object chosen: that property of all 10,000.
    session.panel("#object", "0", "input");
    const std::size_t slid = session.panel("#shininess", "1.5", "input"); // log10: 31.6
    const std::size_t afterSlide = session.message();
    const std::size_t ui = session.ui();
    if (!session.run(dir_)) return;
    EXPECT_EQ(session.answer(padded).at("message"), "") << "a 3 MB scene";
    EXPECT_EQ(session.answer(huge).at("message"), expected);
    EXPECT_EQ(session.answer(many).at("message"), "") << "10,000 objects";
    EXPECT_TRUE(session.answer(edit).at("found").get<bool>()) << "no bands slider";
    EXPECT_EQ(session.answer(after).at("message"), "") << "the panel edit of 10,000 objects";
    const json& sceneShown = session.answer(ui).at("ui").at("scene");
    ASSERT_EQ(sceneShown.at("objects").size(), 10000u);
    EXPECT_EQ(sceneShown.at("toon_bands"), 7);
    EXPECT_TRUE(session.answer(slid).at("found").get<bool>()) << "no shininess slider";
    EXPECT_EQ(session.answer(afterSlide).at("message"), "") << "the material edit of 10,000 objects";
    EXPECT_EQ(sceneShown.at("objects").at(0).at("material").at("shininess"), 31.6);
    EXPECT_EQ(sceneShown.at("objects").at(9999).at("material").at("shininess"), 31.6);
}

// A % in ?scene= that is no escape: the page starts and says it cannot fetch that scene (a URIError stopped
// it with nothing shown).
TEST_F(Browser, APercentThatIsNoEscapeInTheSceneUrlIsAMessage) {
    Session session;
    const std::size_t open = session.open("?scene=scenes/50%off.json");
    const std::size_t message = session.message();
    if (!session.run(dir_)) return;
    EXPECT_EQ(session.answer(open).at("failed"), "") << session.answer(open);
    const std::string shown = session.answer(message).at("message").get<std::string>();
    EXPECT_NE(shown.find("50%off.json: cannot fetch the scene (HTTP 404)"), std::string::npos) << shown;
}

// A lesson's step paths and files on the page, as the command line bounds them. Every step's path is checked
// before anything is fetched: the command line's refusals ("-", a NUL, an absolute path) with its messages,
// and what the page alone would take for another place (a scheme, another origin; "http://[" threw outside
// any handler and the page never became ready) in the same form. A step file over 16 MiB is refused with
// the command line's message without reading it whole (a Content-Length over it: not read at all; a stream
// without one: cancelled past 16 MiB), each distinct file is fetched once, and fetching stops where the
// lesson's steps pass what the parser takes (the native message names the step).
TEST_F(Browser, LessonStepPathsAreCheckedFirstAndTheirFilesBounded) {
    const fs::path files = dir_ / "files";
    fs::create_directories(files);
    const std::string small = R"({"image": {"width": 32, "height": 24}})";
    std::ofstream(files / "s.json") << small;
    const auto lessonWith = [](const std::vector<std::string>& scenes) {
        json lesson = {{"title", "t"}, {"steps", json::array()}};
        for (const std::string& scene : scenes)
            lesson["steps"].push_back(
                {{"title", "step " + std::to_string(lesson["steps"].size())}, {"scene", scene}});
        return lesson.dump();
    };
    // The text the page's C++ is handed for a path (web/main.cpp shadelab_load_lesson's reader), so the
    // native parser gives the message the page must give.
    const auto pageReader = [&files](const std::string& path) -> std::string {
        if (path.starts_with("../stream/")) checkSceneTextSize(kMaxSceneBytes + 1, path);
        std::ifstream in(files / path, std::ios::binary);
        if (!in) throw InputError("no such test file");
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        checkSceneTextSize(text.size(), path);
        return text;
    };
    const auto nativeMessage = [&](const std::string& text, const std::string& name) {
        try {
            (void)parseLesson(text, name, pageReader);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("(the native parser took it)");
    };
    const std::string elsewhere = ": steps[1].scene: must be a path relative to the lesson's folder, got ";

    // Refused before any request: the command line's rules, then the page's.
    struct Refusal {
        std::string path, expected;
    };
    std::vector<Refusal> refusals;
    for (const std::string& path :
         {std::string("/files/abs.json"), std::string("-"), std::string("a\0b.json", 8), std::string()})
        refusals.push_back({path, ""}); // expected: the native parser's message
    for (const std::string path :
         {"http://127.0.0.2:9/x.json", "//127.0.0.2:9/x.json", "data:application/json,{}",
          "javascript:alert(1)", "\\\\127.0.0.2:9\\x.json", " http://127.0.0.2:9/x.json", "http://["})
        refusals.push_back({path, elsewhere + quotedValue(path)});
    for (std::size_t i = 0; i < refusals.size(); ++i) {
        const std::string name = "refused-" + std::to_string(i) + ".json";
        const std::string text = lessonWith({"s.json", refusals[i].path});
        std::ofstream(files / name) << text;
        refusals[i].expected =
            refusals[i].expected.empty() ? nativeMessage(text, name) : name + refusals[i].expected;
    }
    std::ofstream(files / "bad-url.json") << lessonWith({"http://["});
    const std::string badUrlExpected =
        "bad-url.json: steps[0].scene: must be a path relative to the lesson's "
        "folder, got \"http://[\"";
    // A data: lesson has no folder for its steps.
    const std::string dataLesson = "data:application/json," + lessonWith({"s.json"});

    // Too large: one file of 17 MiB (sent with its Content-Length), 200 MiB streamed without one and with
    // one; and steps that parse more than 64 MiB in all (15 MiB named five times: the sixth step's file is
    // never fetched).
    const auto padded = [&](const fs::path& path, std::size_t bytes) {
        const std::string head = R"({"image": {"width": 8, "height": 8})";
        std::ofstream(path, std::ios::binary) << head << std::string(bytes - head.size() - 1, ' ') << "}";
    };
    padded(files / "big17.json", 17 << 20);
    padded(files / "t1.json", 15 << 20);
    padded(files / "t2.json", 1 << 20);
    const std::vector<std::pair<std::string, std::string>> large = {
        {"big-file.json", lessonWith({"s.json", "big17.json"})},
        {"streamed.json", lessonWith({"s.json", "../stream/200.json"})},
        {"declared.json", lessonWith({"s.json", "../stream/200-declared.json"})},
        {"steps-total.json", lessonWith({"t1.json", "t1.json", "t1.json", "t1.json", "t1.json", "t2.json"})},
    };
    for (const auto& [name, text] : large) std::ofstream(files / name) << text;

    Session session;
    const std::size_t open = session.openWithFiles("?lesson=files/bad-url.json", files);
    const std::size_t openMessage = session.message();
    std::vector<std::size_t> refused;
    for (std::size_t i = 0; i < refusals.size(); ++i)
        refused.push_back(session.loadUrl("files/refused-" + std::to_string(i) + ".json"));
    const std::size_t beforeAnyFile = session.served();
    const std::size_t data = session.loadUrl(dataLesson);
    std::vector<std::size_t> largeLoads;
    for (const auto& [name, text] : large) largeLoads.push_back(session.loadUrl("files/" + name));
    session.sleep(1); // the stream's server thread notes what it sent once the page has hung up
    const std::size_t served = session.served();
    const std::size_t shown = session.message();
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;

    EXPECT_EQ(session.answer(open).at("failed"), "");
    EXPECT_EQ(session.answer(openMessage).at("message"), badUrlExpected)
        << "?lesson= with a step \"http://[\"";
    for (std::size_t i = 0; i < refusals.size(); ++i)
        EXPECT_EQ(session.answer(refused[i]).at("message"), refusals[i].expected) << json(refusals[i].path);
    const json requestedFirst = session.answer(beforeAnyFile).at("requested");
    for (const char* never : {"/files/s.json", "/files/abs.json"})
        EXPECT_EQ(std::count(requestedFirst.begin(), requestedFirst.end(), never), 0)
            << never << " was requested for a refused lesson: " << requestedFirst;
    const std::string dataMessage = session.answer(data).at("message");
    EXPECT_NE(
        dataMessage.find(R"(steps[0].scene: the page cannot fetch it beside the lesson, whose URL "data:)"),
        std::string::npos)
        << dataMessage;
    EXPECT_NE(dataMessage.find("has no folder"), std::string::npos) << dataMessage;
    for (std::size_t i = 0; i < large.size(); ++i)
        EXPECT_EQ(session.answer(largeLoads[i]).at("message"), nativeMessage(large[i].second, large[i].first))
            << large[i].first;
    const json& requested = session.answer(served).at("requested");
    const json& streamed = session.answer(served).at("streamed");
    const auto times = [&](const std::string& path) {
        return std::count(requested.begin(), requested.end(), path);
    };
    EXPECT_EQ(times("/files/t1.json"), 1) << "t1.json, named by two steps, fetched once";
    EXPECT_EQ(times("/files/t2.json"), 0) << "fetched after the steps passed 64 MiB of scene text";
    // What the server could send before the page hung up: the limit, plus what the sockets' buffers and the
    // browser's network process hold.
    ASSERT_TRUE(streamed.contains("/stream/200.json")) << streamed;
    ASSERT_TRUE(streamed.contains("/stream/200-declared.json")) << streamed;
    const double mib = 1 << 20;
    EXPECT_LT(streamed.at("/stream/200.json").get<double>() / mib, 48) << "MiB sent without a Content-Length";
    EXPECT_LT(streamed.at("/stream/200-declared.json").get<double>() / mib, 32)
        << "MiB sent after the header";
    std::printf("streamed before the page hung up: %.1f MiB without a Content-Length, %.1f MiB with one\n",
                streamed.at("/stream/200.json").get<double>() / mib,
                streamed.at("/stream/200-declared.json").get<double>() / mib);
    EXPECT_FALSE(session.answer(shown).at("message").get<std::string>().empty()) << "the last refusal shows";
    for (const json& entry : session.answer(console).at("console"))
        EXPECT_EQ(entry.value("message", "").find("Uncaught"), std::string::npos) << entry;
}

// scripts/web.sh render follows the command line's rules with its messages: a FIFO scene (it waited
// forever) and /dev/zero (read until memory ran out) are refused as `shadelab render` refuses them; names
// are escaped; a new file gets the mode umask gives (0600 before), a FIFO output is written through (it
// was replaced), /dev/stdout is the open descriptor; a picture larger than one script call can carry is
// read back in bands (8192x8192 ended in a WebDriver "script timeout").
TEST_F(Browser, RenderScriptFollowsTheCommandLinesRules) {
    RunOptions options;
    options.program = SHADELAB_WEB_SH;
    options.timeout = std::chrono::seconds(60);
    ASSERT_EQ(::mkfifo((dir_ / "fifo.json").c_str(), 0644), 0);
    for (const std::string& scene :
         {std::string("fifo.json"), std::string("/dev/zero"), std::string("e\x1b[31m.json")}) {
        const Outcome web = runWith({"render", scene, "--out", "o.png"}, dir_, options);
        const Outcome cli = runShadelab({"render", scene, "--out", "o.png"}, dir_);
        EXPECT_EQ(web.exitCode, 2) << scene << ": " << web.err;
        EXPECT_EQ(web.err, cli.err) << scene;
        EXPECT_EQ(web.err.find('\x1b'), std::string::npos) << web.err;
    }
    EXPECT_FALSE(fs::exists(dir_ / "o.png"));
    // The flags are the program's one table (app::sceneFlags), read from the page: an unknown one is named,
    // and the message lists every flag the command line has.
    const Outcome unknown = runWith({"render", "--shade", "flat", "--out", "o.png"}, dir_, options);
    EXPECT_EQ(unknown.exitCode, 2) << unknown.err;
    EXPECT_NE(unknown.err.find("unknown option \"--shade\""), std::string::npos) << unknown.err;
    for (const app::SceneFlag& flag : app::sceneFlags())
        EXPECT_NE(unknown.err.find("--" + std::string(flag.name)), std::string::npos) << flag.name;
    EXPECT_FALSE(fs::exists(dir_ / "o.png"));

    const mode_t mask = ::umask(0);
    ::umask(mask);
    ASSERT_EQ(runWith({"render", "--size", "32x24", "--out", "new.png"}, dir_, options).exitCode, 0);
    EXPECT_EQ(fs::status(dir_ / "new.png").permissions(), fs::perms(0666 & ~mask));

    ASSERT_EQ(::mkfifo((dir_ / "out.fifo").c_str(), 0644), 0);
    const int fd = ::open((dir_ / "out.fifo").c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    ASSERT_GE(fd, 0);
    std::string received;
    bool closed = false;
    std::thread reader([&] { closed = cli_test::readToEndWithin(fd, std::chrono::seconds(60), received); });
    const Outcome fifo = runWith({"render", "--size", "32x24", "--out", "out.fifo"}, dir_, options);
    if (!fifo.started) ::close(::open((dir_ / "out.fifo").c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC));
    reader.join();
    ::close(fd);
    EXPECT_EQ(fifo.exitCode, 0) << fifo.err;
    EXPECT_TRUE(closed && received.starts_with("\x89PNG")) << received.size() << " bytes through the FIFO";
    EXPECT_TRUE(fs::is_fifo(dir_ / "out.fifo")) << "the FIFO was replaced";

    const Outcome stdoutRun = runWith({"render", "--size", "32x24", "--out", "/dev/stdout"}, dir_, options);
    EXPECT_EQ(stdoutRun.exitCode, 0) << stdoutRun.err;
    EXPECT_TRUE(stdoutRun.out.starts_with("\x89PNG")) << stdoutRun.out.size() << " bytes on standard output";

    // 3000x2900 is five bands of at most 8 MB: the same picture as the native OpenGL ES render.
    ASSERT_EQ(runWith({"render", "--size", "3000x2900", "--out", "big.png"}, dir_, options).exitCode, 0);
    const Image big = readPng(dir_ / "big.png");
    Scene scene;
    scene.width = 3000;
    scene.height = 2900;
    const Comparison c = compareImages(big, nativeGles().render(scene), swiftShaderTolerance(big));
    EXPECT_TRUE(c.passed) << c.summary();
}

// scripts/web.sh render refuses what `shadelab render` refuses before any work, with its message and exit
// code: standard output appended to the scene (`--out /dev/stdout >> scene.json`, and its other names)
// wrote the PNG into its own input; a descriptor's name with a trailing slash (/dev/fd/1/ was taken for
// descriptor 1) and a path under a regular file ("does not exist" where the command line says "a part of
// ... is a file") were judged otherwise. The scene is the same after each run.
TEST_F(Browser, RenderScriptRefusesOutputsAsTheCommandLineDoes) {
    const std::string scene = R"({"image": {"width": 16, "height": 12}})"
                              "\n";
    std::ofstream(dir_ / "scene.json") << scene;
    std::ofstream(dir_ / "afile") << "a regular file\n";
    struct Case {
        std::vector<std::string> args;
        bool stdoutToScene; // standard output appended to scene.json, as `>> scene.json`
    };
    const std::vector<Case> cases = {
        {{"render", "scene.json", "--out", "-"}, true},
        {{"render", "scene.json", "--out", "/dev/stdout"}, true},
        {{"render", "scene.json", "--out", "/dev/fd/1"}, true},
        {{"render", "scene.json", "--out", "/proc/self/fd/1"}, true},
        {{"render", "scene.json", "--out", "/dev/fd/1/"}, false},
        {{"render", "scene.json", "--out", "/dev/stdout/"}, false},
        {{"render", "scene.json", "--out", "/proc/self/fd/1/."}, false},
        {{"render", "scene.json", "--out", "afile/sub/x.png"}, false},
        {{"render", "scene.json", "--out", "afile/x.png"}, false},
    };
    for (const Case& c : cases) {
        const std::string shown = c.args.back() + (c.stdoutToScene ? " >> scene.json" : "");
        RunOptions options;
        options.timeout = std::chrono::seconds(60);
        if (c.stdoutToScene) {
            options.stdoutPath = dir_ / "scene.json";
            options.stdoutAppends = true;
        }
        options.program = SHADELAB_EXE;
        const Outcome cli = runWith(c.args, dir_, options);
        options.program = SHADELAB_WEB_SH;
        const Outcome web = runWith(c.args, dir_, options);
        EXPECT_EQ(cli.exitCode, 2) << shown << ": " << cli.err;
        EXPECT_EQ(web.exitCode, cli.exitCode) << shown << ": " << web.err;
        EXPECT_EQ(web.err, cli.err) << shown;
        std::ifstream in(dir_ / "scene.json", std::ios::binary);
        const std::string after((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_EQ(after, scene) << shown << ": the scene was written to";
        std::ofstream(dir_ / "scene.json", std::ios::trunc) << scene; // whole again for the next case
    }
    EXPECT_FALSE(fs::exists(dir_ / "afile" / "sub"));
}

// A free TCP port on 127.0.0.1 (bound and released; the server takes it right after).
int freePort() {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t size = sizeof address;
    if (::bind(fd, reinterpret_cast<sockaddr*>(&address), size) != 0 ||
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &size) != 0) {
        ::close(fd);
        return -1;
    }
    ::close(fd);
    return ntohs(address.sin_port);
}

// What GET `target` from 127.0.0.1:`port` (HTTP/1.0: the server closes when it is sent) answers, headers
// and body, up to `limit` bytes; "" when nothing answers. A server that accepts and never answers fails
// here after 5 s, not at ctest's timeout.
std::string httpReply(int port, const std::string& target, std::size_t limit) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    const timeval timeout{5, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = htons(std::uint16_t(port));
    std::string reply;
    if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
        const std::string request = "GET " + target + " HTTP/1.0\r\nHost: 127.0.0.1\r\n\r\n";
        if (::write(fd, request.data(), request.size()) == ssize_t(request.size())) {
            char buffer[4096];
            for (ssize_t n; reply.size() < limit && (n = ::read(fd, buffer, sizeof buffer)) > 0;)
                reply.append(buffer, std::size_t(n));
        }
    }
    ::close(fd);
    return reply;
}

// The status code of GET `target`, or -1 when nothing answers.
int httpStatus(int port, const std::string& target) {
    const std::string reply = httpReply(port, target, 256);
    return reply.starts_with("HTTP/1.") && reply.size() > 12 ? std::stoi(reply.substr(9, 3)) : -1;
}

// The body of GET `target`, "" when nothing answers.
std::string httpBody(int port, const std::string& target) {
    const std::string reply = httpReply(port, target, std::string::npos);
    const std::size_t body = reply.find("\r\n\r\n");
    return body == std::string::npos ? "" : reply.substr(body + 4);
}

// The status of GET / from a server just started on `port`, asked every 100 ms until it answers; -1 when
// it has not within 20 s.
int statusOnceServing(int port) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    int index = -1;
    while ((index = httpStatus(port, "/")) < 0 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    return index;
}

// scripts/web.sh serve serves the page and nothing else: no build files, no listings, no links out of the
// page's folder; a port outside 1..65535 is refused (70000 bound 4464 and printed the wrong URL). With
// --lessons DIR, DIR's files under /own-lessons/ by the same rules, and its lessons (only they, by name)
// in /own-lessons/index.json; a DIR that is not a folder is refused.
TEST_F(Browser, ServeGivesThePageAndNothingElse) {
    RunOptions options;
    options.program = SHADELAB_WEB_SH;
    options.timeout = std::chrono::seconds(30);
    for (const char* port : {"70000", "0", "http"}) {
        const Outcome bad = runWith({"serve", port}, dir_, options);
        EXPECT_EQ(bad.exitCode, 2) << port << ": " << describe(bad);
        EXPECT_NE(bad.err.find("1..65535"), std::string::npos) << bad.err;
    }
    const fs::path own = makeLessonFolder(dir_);
    for (const std::string& folder : {(dir_ / "missing").string(), (own / "plain.json").string()}) {
        const Outcome bad =
            runWith({"serve", std::to_string(freePort()), "--lessons", folder}, dir_, options);
        EXPECT_EQ(bad.exitCode, 2) << folder << ": " << describe(bad);
        EXPECT_NE(bad.err.find("--lessons must name a folder"), std::string::npos) << bad.err;
        EXPECT_NE(bad.err.find(folder), std::string::npos) << bad.err;
    }

    const int port = freePort();
    ASSERT_GT(port, 0);
    const pid_t server = ::fork();
    if (server == 0) {
        ::execl(SHADELAB_WEB_SH, SHADELAB_WEB_SH, "serve", std::to_string(port).c_str(), "--lessons",
                own.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ASSERT_GT(server, 0);
    const int index = statusOnceServing(port);
    EXPECT_EQ(index, 200) << "the page's index.html (the server did not answer within 20 s if -1)";
    EXPECT_EQ(httpStatus(port, "/shadelab.wasm"), 200);
    EXPECT_EQ(httpStatus(port, "/scenes/index.json"), 200);
    for (const char* outside : {"/CMakeCache.txt", "/../CMakeCache.txt", "/generated/",
                                "/header-only/glm/glm.hpp", "/scenes/", "/%2e%2e/CMakeCache.txt"})
        EXPECT_EQ(httpStatus(port, outside), 404) << outside;
    const std::string list = httpBody(port, "/own-lessons/index.json");
    EXPECT_EQ(json::parse(list, nullptr, false), json::array({kOwnLessonName})) << list;
    EXPECT_EQ(httpStatus(port, "/own-lessons/%3Cimg%20src%3Dx%20onerror%3Dalert(1)%3E.json"), 200);
    EXPECT_EQ(httpStatus(port, "/own-lessons/scenes/ring.json"), 200);
    EXPECT_EQ(httpStatus(port, "/own-lessons/plain.json"), 200) << "a file in DIR, though not listed";
    for (const char* outside :
         {"/own-lessons/", "/own-lessons/scenes/", "/own-lessons/linked.json",
          "/own-lessons/../outside/secret.json", "/own-lessons/%2e%2e/outside/secret.json",
          "/own-lessons/..%2foutside/secret.json"})
        EXPECT_EQ(httpStatus(port, outside), 404) << outside;
    ::kill(server, SIGTERM);
    int status = 0;
    ::waitpid(server, &status, 0);
}

// A client that asks for `target` and resets the connection (SO_LINGER 0) after reading a little, as a tab
// closed mid-download does. Its small receive buffer keeps the server writing when the reset arrives.
void requestAndHangUp(int port, const std::string& target) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    const int small = 4096;
    ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &small, sizeof small);
    const timeval limit{5, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &limit, sizeof limit);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = htons(std::uint16_t(port));
    if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
        const std::string request = "GET " + target + " HTTP/1.0\r\nHost: 127.0.0.1\r\n\r\n";
        if (::write(fd, request.data(), request.size()) == ssize_t(request.size())) {
            char buffer[256];
            (void)!::read(fd, buffer, sizeof buffer); // the answer has started
        }
        const linger reset{1, 0};
        ::setsockopt(fd, SOL_SOCKET, SO_LINGER, &reset, sizeof reset);
    }
    ::close(fd);
}

// web/serve.py answers a path Python cannot look up (a NUL: realpath raised, the connection closed with no
// answer and a traceback) with 400, and a client that hangs up mid-answer (a ConnectionReset or BrokenPipe
// traceback) leaves nothing on standard error; the server goes on answering. Served: a folder with a
// 64 MB file, more than loopback's socket buffers take (the page's 1.3 MB wasm fit in them whole).
TEST_F(Browser, ServeAnswersBadPathsAndIsSilentWhenAClientHangsUp) {
    fs::create_directories(dir_ / "site");
    std::ofstream(dir_ / "site" / "index.html") << "<!doctype html>\n";
    std::ofstream(dir_ / "site" / "big.bin").close();
    fs::resize_file(dir_ / "site" / "big.bin", 64 << 20); // sparse: no 64 MB written to /tmp
    const int port = freePort();
    ASSERT_GT(port, 0);
    const fs::path serve = fs::path(SHADELAB_WEB_DRIVER).parent_path() / "serve.py";
    const fs::path errors = dir_ / "serve.err";
    const pid_t server = ::fork();
    if (server == 0) {
        const int err = ::open(errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
        if (err < 0 || ::dup2(err, STDERR_FILENO) < 0) ::_exit(126);
        ::execl("/usr/bin/python3", "/usr/bin/python3", serve.c_str(), (dir_ / "site").c_str(),
                std::to_string(port).c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ASSERT_GT(server, 0);
    const int index = statusOnceServing(port);
    EXPECT_EQ(index, 200) << "index.html (the server did not answer within 20 s if -1)";
    for (const char* bad : {"/%00", "/scenes/%00.json", "/index.html%00"})
        EXPECT_EQ(httpStatus(port, bad), 400) << bad;
    for (int i = 0; i < 3; ++i) requestAndHangUp(port, "/big.bin");
    std::this_thread::sleep_for(std::chrono::milliseconds(500)); // the handlers' threads meet the resets
    EXPECT_EQ(httpStatus(port, "/"), 200) << "the server answers after the hang-ups";
    ::kill(server, SIGTERM);
    int status = 0;
    ::waitpid(server, &status, 0);
    std::ifstream in(errors);
    const std::string err((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(err, "") << "the server's standard error";
}

// scripts/web.sh render: the browser's `shadelab render` (a PNG of the scene's size; exit 2 with the CLI's
// message for a bad scene; a folder as --out refused).
TEST_F(Browser, RenderScriptWritesThePngOrSaysWhy) {
    RunOptions options;
    options.program = SHADELAB_WEB_SH;
    options.timeout = std::chrono::seconds(60); // four runs, each well under the test's ctest TIMEOUT
    const Outcome ok =
        runWith({"render", "--size", "120x90", "--shading", "flat", "--out", "w.png"}, dir_, options);
    ASSERT_EQ(ok.exitCode, 0) << ok.err;
    const Image png = readPng(dir_ / "w.png");
    EXPECT_EQ(png.width, 120);
    EXPECT_EQ(png.height, 90);
    Scene scene;
    scene.width = 120;
    scene.height = 90;
    scene.shading = ShadingMode::Flat;
    const Comparison c = compareImages(png, nativeGles().render(scene), swiftShaderTolerance(png));
    EXPECT_TRUE(c.passed) << c.summary();

    std::ofstream(dir_ / "bad.json") << R"({"image": {"width": 0}})";
    const Outcome bad = runWith({"render", "bad.json", "--out", "b.png"}, dir_, options);
    const Outcome cli = runShadelab({"render", "bad.json", "--out", "b.png"}, dir_);
    EXPECT_EQ(bad.exitCode, 2) << bad.err;
    EXPECT_EQ(bad.err, cli.err);
    EXPECT_FALSE(fs::exists(dir_ / "b.png"));
    const Outcome folder = runWith({"render", "--out", "."}, dir_, options);
    EXPECT_EQ(folder.exitCode, 2) << folder.err;
    // What WebGL 2 lacks is a run-time failure named by the renderer, as natively (DESIGN §7).
    const Outcome reversed = runWith({"render", "--depth", "reversed", "--out", "r.png"}, dir_, options);
    EXPECT_EQ(reversed.exitCode, 1) << reversed.err;
    EXPECT_TRUE(reversed.err.starts_with("shadelab: depth reversed: needs glClipControl")) << reversed.err;
    EXPECT_EQ(reversed.err.find("Stacktrace"), std::string::npos) << reversed.err;
    EXPECT_FALSE(fs::exists(dir_ / "r.png"));
}

} // namespace
} // namespace shadelab::test
