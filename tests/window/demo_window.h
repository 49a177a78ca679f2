// The demo window end to end, in a real X window: each test starts its own Xvfb and `shadelab` on a fixed
// scene, types keys with xdotool, and checks three things agree for every state a key reaches:
//   - the title and the scene JSON that S saves say what the key should have done;
//   - the window, captured with libX11's XGetImage, shows what `shadelab render` gives for that JSON;
//   - the PNG that S saves is that same picture.
// Esc must exit 0 with zero KHR_debug messages. Without Xvfb or xdotool the tests skip with the
// reason, except in CI (CI set), where that fails.
// This header holds what the test files share (demo_keys_test.cpp: keys and views; demo_presenting_test.cpp:
// panel, presenting, lessons and help; demo_screenshot_test.cpp: what S saves and where).
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "shadelab/image/image.h"
#include "tolerances.h"
#include "window/demo_process.h"

namespace shadelab::window_test {

using Clock = std::chrono::steady_clock;

// Why the regression tolerance: llvmpipe is deterministic, and the window and `render` draw the same
// scene through the same renderer; only the render target differs (the window's default framebuffer, an
// FBO). They may disagree by float rounding at a few silhouette pixels. Measured: at most ±1/255 in a
// channel and no pixel beyond it, in all 9 states at 320×240 and at 400×300; the S screenshot is exact.
// The budget of 24 edge pixels and mean 0.05/255 are those of the regression references.
inline constexpr Tolerance kWindowTolerance = test::kRegressionTolerance;
inline constexpr Tolerance kExact = test::kIdentical;

// The X server may still be applying the demo's last frame when a capture is asked for; a capture that
// does not match yet is retried for this long before it counts as a failure.
inline constexpr Seconds kSettleLimit{2};

// The window of the key tests: small, so a capture and a render take milliseconds.
inline constexpr int kWidth = 320, kHeight = 240;
inline const std::string kSize = std::to_string(kWidth) + "x" + std::to_string(kHeight);

// One sphere at level `level` (3: coarse enough that flat and Gouraud differ visibly), a point light and
// a directional light, shininess 16.
std::string sceneJson(int width, int height, int level, const char* shading, const char* lighting);

// "Suite.Test" of the running test, for file names.
std::string testName();

// Passes if `actual` matches `expected` within `tolerance`; otherwise writes actual, expected and diff PNGs
// to window-failures/ in the build folder and names them.
testing::AssertionResult matches(const Image& actual, const Image& expected, const Tolerance& tolerance,
                                 const std::string& what);

Image crop(const Image& image, int x0, int y0, int width, int height);

// Every pixel of `image` the same colour: a bar, or a window with nothing of the scene in it.
bool uniform(const Image& image);

// Captures the window until it matches `expected` (or kSettleLimit passes); returns the last capture. With
// (x0, y0), the part of the window there of `expected`'s size is compared (a picture between bars).
Image settledCapture(const XWindow& window, const Image& expected, int x0 = -1, int y0 = 0);

double msSince(Clock::time_point start);

// A fresh folder under TMPDIR for one test, removed with everything in it.
class ScratchDir {
public:
    ScratchDir();
    ~ScratchDir();
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

// Owns, in destruction order, the demos, the X server and the scratch folder of one test: whatever
// fails, the demos are killed before Xvfb and nothing is left in TMPDIR.
class DemoWindow : public testing::Test {
public:
    const fs::path& scratch() const { return scratch_->path(); }

    fs::path writeScene(const std::string& name, const std::string& json) const;

    DemoProcess& startDemo(const std::string& name, std::vector<std::string> args,
                           const std::vector<std::string>& environment = {});

    // Esc exits 0, and the KHR_debug callback saw nothing of shadelab's own during the whole run (on
    // OpenGL ES the demo counts Dear ImGui's desktop-only calls apart: src/app/shells/panel.cpp).
    static void expectCleanQuit(DemoProcess& demo);

protected:
    void SetUp() override;
    void TearDown() override;

private:
    XTools tools_;
    std::unique_ptr<ScratchDir> scratch_;
    std::unique_ptr<XServer> server_;
    std::vector<std::unique_ptr<DemoProcess>> demos_;
};

} // namespace shadelab::window_test
