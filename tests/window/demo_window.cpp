#include "window/demo_window.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <utility>

#include "shadelab/image/image_file.h"

namespace shadelab::window_test {

std::string sceneJson(int width, int height, int level, const char* shading, const char* lighting) {
    char text[2048];
    std::snprintf(text, sizeof text, R"({
  "image": { "width": %d, "height": %d, "background": [0.02, 0.02, 0.03] },
  "camera": { "eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0] },
  "projection": { "type": "perspective", "fovy_deg": 40, "near": 0.5, "far": 20 },
  "shading": "%s",
  "lighting": "%s",
  "objects": [
    { "center": [0, 0, 0], "radius": 1.1, "subdivisions": %d,
      "material": { "ambient": [0.1, 0.1, 0.1], "diffuse": [0.75, 0.22, 0.18],
                    "specular": [1, 1, 1], "shininess": 16 } }
  ],
  "lights": [
    { "type": "point", "position": [3, 3, 5], "ambient": [0.1, 0.1, 0.1],
      "diffuse": [1, 1, 1], "specular": [1, 1, 1], "attenuation": [1, 0, 0] },
    { "type": "directional", "direction": [1, 0.4, -0.5],
      "diffuse": [0.15, 0.25, 0.55], "specular": [0.2, 0.2, 0.4] }
  ]
}
)",
                  width, height, shading, lighting, level);
    return text;
}

std::string testName() {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    return std::string(info->test_suite_name()) + "." + info->name();
}

testing::AssertionResult matches(const Image& actual, const Image& expected, const Tolerance& tolerance,
                                 const std::string& what) {
    const Comparison c = compareImages(actual, expected, tolerance);
    if (c.passed) return testing::AssertionSuccess() << what << ": " << c.summary();
    const fs::path dir = fs::current_path() / "window-failures";
    fs::create_directories(dir);
    std::string stem = testName() + "." + what;
    for (char& ch : stem)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '-') ch = '_';
    const fs::path actualPng = dir / (stem + ".actual.png"), expectedPng = dir / (stem + ".expected.png"),
                   diffPng = dir / (stem + ".diff.png");
    writePng(actual, actualPng);
    writePng(expected, expectedPng);
    if (c.sizeMatches) writePng(diffImage(actual, expected), diffPng);
    return testing::AssertionFailure()
           << what << ": " << c.summary() << "\n  actual:   " << actualPng.string()
           << "\n  expected: " << expectedPng.string()
           << (c.sizeMatches ? "\n  diff ×8:  " + diffPng.string() : "");
}

Image crop(const Image& image, int x0, int y0, int width, int height) {
    Image out(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) std::copy_n(image.pixel(x0 + x, y0 + y), 4, out.pixel(x, y));
    return out;
}

bool uniform(const Image& image) {
    for (std::size_t i = 4; i + 3 < image.rgba.size(); i += 4)
        if (!std::equal(image.rgba.begin() + std::ptrdiff_t(i), image.rgba.begin() + std::ptrdiff_t(i + 3),
                        image.rgba.begin()))
            return false;
    return true;
}

Image settledCapture(const XWindow& window, const Image& expected, int x0, int y0) {
    Image capture;
    pollUntil(
        [&] {
            capture = window.capture();
            if (x0 < 0) return compareImages(capture, expected, kWindowTolerance).passed;
            return capture.width >= x0 + expected.width && capture.height >= y0 + expected.height &&
                   compareImages(crop(capture, x0, y0, expected.width, expected.height), expected,
                                 kWindowTolerance)
                       .passed;
        },
        kSettleLimit);
    return capture;
}

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

ScratchDir::ScratchDir() {
    std::string pattern = (fs::temp_directory_path() / "shadelab-window-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp " + pattern + " failed");
    path_ = pattern;
}

ScratchDir::~ScratchDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
}

void DemoWindow::SetUp() {
    tools_ = XTools::find();
    if (!tools_.missing.empty()) {
        std::string missing;
        for (const std::string& m : tools_.missing) missing += (missing.empty() ? "" : ", ") + m;
        if (std::getenv("CI")) FAIL() << "CI is set but the window test needs " << missing;
        GTEST_SKIP() << "the window test needs " << missing << " (scripts/setup.sh installs them)";
    }
    scratch_ = std::make_unique<ScratchDir>();
    server_ = std::make_unique<XServer>(tools_, scratch());
    std::printf("Xvfb on display %s, scratch folder %s\n", server_->display().c_str(), scratch().c_str());
}

void DemoWindow::TearDown() {
    if (HasFailure())
        for (const auto& demo : demos_) std::printf("%s\n", demo->logs().c_str());
}

fs::path DemoWindow::writeScene(const std::string& name, const std::string& json) const {
    const fs::path path = scratch() / name;
    std::ofstream(path) << json;
    if (readText(path) != json) throw std::runtime_error("cannot write " + path.string());
    return path;
}

DemoProcess& DemoWindow::startDemo(const std::string& name, std::vector<std::string> args,
                                   const std::vector<std::string>& environment) {
    const auto start = Clock::now();
    demos_.push_back(
        std::make_unique<DemoProcess>(tools_, *server_, scratch(), name, std::move(args), environment));
    demos_.back()->window().focus();
    std::printf("%s: window %s up and focused in %.0f ms\n", name.c_str(),
                demos_.back()->window().id().c_str(), msSince(start));
    return *demos_.back();
}

void DemoWindow::expectCleanQuit(DemoProcess& demo) {
    const ExitStatus status = demo.quit();
    EXPECT_EQ(status.code, 0) << "after Escape the demo ended with " << status.describe();
    const std::string err = demo.err();
    EXPECT_NE(err.find("shadelab: 0 GL debug message(s)"), std::string::npos)
        << "stderr should report zero KHR_debug messages:\n"
        << err;
}

} // namespace shadelab::window_test
