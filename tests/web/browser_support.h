// What the page's browser tests share (tests/web/browser_*_test.cpp, one executable browser_test): the
// browser session (a batch of requests run by web/driver.py), the fixture that skips without a browser, and
// the comparisons with native renders. In a named namespace: GoogleTest requires one fixture class for all
// of a suite's tests, whichever file holds them.
#pragma once

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
#include "app/demo/view_explanations.h"
#include "cli/run_process.h"
#include "gl/gl_test_support.h"
#include "gl/projected_mesh.h"
#include "shadelab/errors.h"
#include "shadelab/exact/probe.h"
#include "shadelab/image/image_file.h"
#include "shadelab/io/text.h"
#include "shadelab/key_codes.h"
#include "shadelab/scene/lesson.h"
#include "shadelab/scene/scene_file.h"
#include "shadelab/scene/scene_flags.h"
#include "tolerances.h"

namespace shadelab::test::web_test {

namespace fs = std::filesystem;
using cli_test::describe;
using cli_test::Outcome;
using cli_test::RunOptions;
using cli_test::runShadelab;
using cli_test::runWith;
using nlohmann::json;

std::vector<std::uint8_t> base64Decode(const std::string& text);

// A session is a batch of requests run by one browser (driver.py session); each test builds one, runs it,
// and reads the answers.
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
    // Model files dropped on the canvas or picked with the model input (driver.py Page.model_files);
    // answers the page's message once it has loaded them.
    std::size_t dropFiles(const std::vector<fs::path>& paths) { return addFiles("drop-files", paths); }
    std::size_t pickFiles(const std::vector<fs::path>& paths) { return addFiles("pick-files", paths); }
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
    // Every <select> on the page: [{id, values, labels}] of its options.
    std::size_t menus() { return add({{"op", "menus"}}); }
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
    bool run(const fs::path& folder);

    const json& answer(std::size_t i) const { return answers_.at(i); }
    Image image(std::size_t i) const;
    ImageF imageF(std::size_t i) const;

private:
    std::size_t addFiles(const char* op, const std::vector<fs::path>& paths) {
        json list = json::array();
        for (const fs::path& p : paths) list.push_back(p.string());
        return add({{"op", op}, {"paths", list}});
    }
    std::size_t add(json request) {
        requests_.push_back(std::move(request));
        return requests_.size() - 1;
    }
    std::vector<json> requests_, answers_;
};

// Why no browser test can run here, or "".
std::string browserUnavailable();

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
void expectCleanConsole(const json& entries);

// Browser against native: the interior within 2/255; SwiftShader and llvmpipe rasterize the silhouette
// differently (measured: about 1 % of a sphere's pixels), so up to 1.5 % of the pixels may differ more.
Tolerance swiftShaderTolerance(const Image& image);

ImageF asFloat(const Image& image);

// Native OpenGL ES renders, the browser's counterpart (tests link the headless renderer).
HeadlessRenderer& nativeGles();

// Every analytic scene under each lighting model, in `mode` at `level`, loaded and captured through a float
// target (for session.imageF once the session has run).
struct AnalyticCapture {
    std::string label;
    Scene scene;
    std::size_t capture;
};
std::vector<AnalyticCapture> captureAnalyticCases(Session& session, ShadingMode mode, int level);

// A lecturer's lesson folder (scripts/web.sh serve --lessons DIR) with one lesson, whose name is markup,
// naming a scene in a subfolder; beside it what must not be listed or served: a scene, a file that is no
// JSON, a hidden lesson, and a link to a lesson outside the folder.
inline constexpr const char* kOwnLessonName = "<img src=x onerror=alert(1)>.json";
fs::path makeLessonFolder(const fs::path& dir);

} // namespace shadelab::test::web_test
