// The command line end to end, against DESIGN §5 (not against its implementation): exit codes, messages that
// name the bad argument or JSON path and its value, atomic output (no partial or temporary file is ever
// left), flags overriding the scene file, and the demo's headless showcase when there is no display.
// The binary runs through fork/execve, never a shell, each test in a fresh temporary folder.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <ostream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <png.h>

#include "cli/run_process.h"
#include "shadelab/image/image.h"
#include "shadelab/image/image_file.h"
#include "shadelab/scene/scene.h"
#include "shadelab/shading/lighting.h"
#include "shadelab/vocabulary.h"

namespace {

using namespace shadelab::cli_test;

namespace fs = std::filesystem;

struct PngSize {
    std::uint32_t width = 0, height = 0;
};

std::uint32_t bigEndian32(const std::string& bytes, std::size_t offset) {
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < 4; ++i) value = value << 8 | std::uint8_t(bytes[offset + i]);
    return value;
}

// The signature and the IHDR chunk, which the PNG spec requires first: length 13 at 8, type at 12,
// width at 16, height at 20, all big-endian.
std::optional<PngSize> pngSize(const std::string& bytes) {
    static constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
    if (bytes.size() < 24 || std::string_view(bytes).substr(0, 8) != kSignature) return std::nullopt;
    if (bigEndian32(bytes, 8) != 13 || bytes.compare(12, 4, "IHDR") != 0) return std::nullopt;
    return PngSize{bigEndian32(bytes, 16), bigEndian32(bytes, 20)};
}

// A scene that renders fast: 64×64, one low-level sphere, the default light.
std::string smallScene(std::string_view shading = "phong", std::string_view lighting = "blinn-phong",
                       int subdivisions = 3, int width = 64, int height = 64) {
    return R"({ "image": { "width": )" + std::to_string(width) + R"(, "height": )" + std::to_string(height) +
           R"( }, "shading": ")" + std::string(shading) + R"(", "lighting": ")" + std::string(lighting) +
           R"(", "objects": [ { "subdivisions": )" + std::to_string(subdivisions) + " } ] }\n";
}

class CliTest : public ::testing::Test {
protected:
    void SetUp() override {
        static std::atomic<int> counter{0};
        std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
        for (char& c : name)
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        dir_ = fs::temp_directory_path() /
               ("shadelab-cli-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + "-" + name);
        fs::remove_all(dir_);
        fs::create_directory(dir_);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }

    Outcome shadelab(const std::vector<std::string>& args, Display display = Display::Inherit) const {
        return runShadelab(args, dir_, display);
    }
    // Renders `args` and returns the PNG's bytes, failing the test if the run or the file is not right.
    std::string renderBytes(std::vector<std::string> args, const std::string& out) const {
        args.insert(args.end(), {"--out", out});
        const Outcome run = shadelab(args);
        EXPECT_EQ(run.exitCode, 0) << describe(run);
        const std::string bytes = readFile(dir_ / out);
        EXPECT_TRUE(pngSize(bytes)) << out << " is not a PNG\n" << describe(run);
        return bytes;
    }

    fs::path dir_;
};

// --- Success: a PNG and nothing else ------------------------------------------------------------------

TEST_F(CliTest, RenderWithoutSceneWritesOnlyThePng) {
    const Outcome run = shadelab({"render", "--size", "64x64", "--out", "X.png"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_EQ(listing(dir_), std::set<std::string>{"X.png"});
    const auto size = pngSize(readFile(dir_ / "X.png"));
    ASSERT_TRUE(size) << "X.png is not a PNG";
    EXPECT_EQ(size->width, 64u);
    EXPECT_EQ(size->height, 64u);
}

// The lecture's matrices for a scene, alone or beside the picture; never mixed into a PNG on standard
// output.
TEST_F(CliTest, PrintMatricesPrintsTheCameraAndEveryObject) {
    const Outcome alone = shadelab({"render", "--print-matrices", "--perspective-matrix", "unnegated"});
    ASSERT_EQ(alone.exitCode, 0) << describe(alone);
    EXPECT_TRUE(listing(dir_).empty()) << "nothing is written without --out";
    for (const char* part :
         {"e = [    0         0         4      ]", "M_cam = [u v w e]^-1", "M_proj, perspective", "w = z < 0",
          "M (object 1", "normal matrix ((M_cam M)^-1)^T"})
        EXPECT_NE(alone.out.find(part), std::string::npos) << part << " in\n" << alone.out;
    writeFile(dir_ / "two.json", R"({"image": {"width": 32, "height": 32},
                                     "objects": [{"center": [-1, 0, 0]}, {"center": [1, 0, 0]}]})");
    const Outcome both = shadelab({"render", "two.json", "--print-matrices", "--out", "two.png"});
    ASSERT_EQ(both.exitCode, 0) << describe(both);
    EXPECT_NE(both.out.find("M (object 2"), std::string::npos) << both.out;
    EXPECT_TRUE(pngSize(readFile(dir_ / "two.png"))) << "--out still renders";
    // Entries of any magnitude stand apart: M_cam's -w.e is -1.41e+17 here, beside -0.7071.
    writeFile(dir_ / "far.json", R"({"camera": {"eye": [1e17, 0, -1e17]}})");
    const Outcome far = shadelab({"render", "far.json", "--print-matrices"});
    ASSERT_EQ(far.exitCode, 0) << describe(far);
    EXPECT_NE(far.out.find("   0.7071    0        -0.7071 -1.41e+17 ]"), std::string::npos) << far.out;
    const Outcome piped = shadelab({"render", "--print-matrices", "--out", "-"});
    EXPECT_EQ(piped.exitCode, 2) << describe(piped);
    EXPECT_NE(piped.err.find("--print-matrices"), std::string::npos) << piped.err;
    EXPECT_EQ(piped.out, "") << "neither matrices nor a PNG";
}

// The `count` rows of numbers printed under the first line of `text` that starts with `heading` (its own
// row too when it holds one, as "u = [ ... ]" does): each "[ a b c ]" read as numbers. Note lines such as
// "[l,r] = ..." are skipped.
std::vector<std::vector<double>> printedRows(const std::string& text, std::string_view heading,
                                             std::size_t count) {
    std::vector<std::vector<double>> rows;
    std::istringstream in(text);
    bool found = false;
    for (std::string line; rows.size() < count && std::getline(in, line);) {
        found = found || line.starts_with(heading);
        const std::size_t open = line.find('[');
        if (!found || open == std::string::npos || line.find(']') == std::string::npos ||
            std::isalpha(static_cast<unsigned char>(line[open + 1])))
            continue;
        std::istringstream numbers(line.substr(open + 1));
        std::vector<double> row;
        for (double x; numbers >> x;) row.push_back(x);
        rows.push_back(row);
    }
    return rows;
}

// The printed entries have 4 decimals (or 3 significant digits below 1e-3): half a unit of the last one,
// with room for a tie rounded either way.
constexpr double kPrintedTolerance = 5.1e-5;

void expectPrinted(const std::vector<std::vector<double>>& printed,
                   const std::vector<std::vector<double>>& expected, const std::string& name,
                   const std::string& text) {
    ASSERT_EQ(printed.size(), expected.size()) << name << " in\n" << text;
    for (std::size_t r = 0; r < expected.size(); ++r) {
        ASSERT_EQ(printed[r].size(), expected[r].size()) << name << " row " << r << " in\n" << text;
        for (std::size_t c = 0; c < expected[r].size(); ++c)
            EXPECT_NEAR(printed[r][c], expected[r][c], kPrintedTolerance)
                << name << " [" << r << "][" << c << "]";
    }
}

// Rows of a 3x3 given by its columns.
std::vector<std::vector<double>> rowsOf(const glm::dvec3& c0, const glm::dvec3& c1, const glm::dvec3& c2) {
    return {{c0.x, c1.x, c2.x}, {c0.y, c1.y, c2.y}, {c0.z, c1.z, c2.z}};
}

// The printed matrices of a rotated camera and an object whose M_cam M is a rotation times a non-uniform,
// mirrored scale, held to the lecture's formulas computed here: the camera frame, M_cam's rows (u, -u.e),
// (v, -v.e), (w, -w.e), M = translate(c) scale(r s), and the normal matrix ((M_cam M)^-1)^T (DESIGN §2; the
// heading names no other scale). An axis-aligned camera and a diagonal M would not tell the normal matrix
// from (M_cam M)^-1, nor from M_cam M up to a scale: here all three differ.
TEST_F(CliTest, PrintMatricesOfARotatedCameraAndAScaledObjectAreTheLecturesFormulas) {
    const glm::dvec3 eyeWorld{2.3, 1.7, 3.1}, targetWorld{0.2, -0.4, 0.5}, upWorld{0.2, 1, 0.1};
    const glm::dvec3 centerWorld{0.4, -0.3, 0.2}, scale{1.8, -0.45, 0.9};
    const double radius = 1.3;
    writeFile(dir_ / "tilted.json", R"({"camera": {"eye": [2.3, 1.7, 3.1], "target": [0.2, -0.4, 0.5],
                                                   "up": [0.2, 1, 0.1]},
                                        "objects": [{"center": [0.4, -0.3, 0.2], "radius": 1.3,
                                                     "scale": [1.8, -0.45, 0.9]}]})");
    const Outcome run = shadelab({"render", "tilted.json", "--print-matrices"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    const std::string& text = run.out;

    // The lecture's camera frame, and M_cam = [u v w e]^-1 written out by rows.
    const glm::dvec3 w = glm::normalize(eyeWorld - targetWorld);
    const glm::dvec3 u = glm::normalize(glm::cross(upWorld, w));
    const glm::dvec3 v = glm::cross(w, u);
    expectPrinted(printedRows(text, "e = ", 1), {{eyeWorld.x, eyeWorld.y, eyeWorld.z}}, "e", text);
    expectPrinted(printedRows(text, "u = ", 1), {{u.x, u.y, u.z}}, "u", text);
    expectPrinted(printedRows(text, "v = ", 1), {{v.x, v.y, v.z}}, "v", text);
    expectPrinted(printedRows(text, "w = ", 1), {{w.x, w.y, w.z}}, "w", text);
    expectPrinted(printedRows(text, "M_cam", 4),
                  {{u.x, u.y, u.z, -glm::dot(u, eyeWorld)},
                   {v.x, v.y, v.z, -glm::dot(v, eyeWorld)},
                   {w.x, w.y, w.z, -glm::dot(w, eyeWorld)},
                   {0, 0, 0, 1}},
                  "M_cam", text);
    const glm::dvec3 semiAxes = radius * scale;
    expectPrinted(printedRows(text, "M (object 1", 4),
                  {{semiAxes.x, 0, 0, centerWorld.x},
                   {0, semiAxes.y, 0, centerWorld.y},
                   {0, 0, semiAxes.z, centerWorld.z},
                   {0, 0, 0, 1}},
                  "M", text);

    // The upper 3x3 of M_cam M has columns R s_i e_i, R's rows being u, v, w; the rows of its inverse are
    // the cross products of its columns over its determinant, so these are the columns of the inverse's
    // transpose.
    const glm::dvec3 a0 = semiAxes.x * glm::dvec3(u.x, v.x, w.x), a1 = semiAxes.y * glm::dvec3(u.y, v.y, w.y),
                     a2 = semiAxes.z * glm::dvec3(u.z, v.z, w.z);
    const double det = glm::dot(a0, glm::cross(a1, a2));
    const glm::dvec3 n0 = glm::cross(a1, a2) / det, n1 = glm::cross(a2, a0) / det,
                     n2 = glm::cross(a0, a1) / det;
    const std::vector<std::vector<double>> normalExpected = rowsOf(n0, n1, n2);
    // This scene tells the normal matrix from the inverse (its transpose) and from M_cam M itself.
    double fromInverse = 0, fromModelView = 0;
    const std::vector<std::vector<double>> modelView = rowsOf(a0, a1, a2);
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 3; ++c) {
            fromInverse = std::max(fromInverse, std::abs(normalExpected[r][c] - normalExpected[c][r]));
            fromModelView = std::max(fromModelView, std::abs(normalExpected[r][c] - modelView[r][c]));
        }
    ASSERT_GT(fromInverse, 0.1) << "choose a camera and scale where (M_cam M)^-1 is not symmetric";
    ASSERT_GT(fromModelView, 0.1);
    EXPECT_NE(text.find("normal matrix ((M_cam M)^-1)^T, 3x3"), std::string::npos) << text;
    expectPrinted(printedRows(text, "normal matrix", 3), normalExpected, "normal matrix", text);
}

TEST_F(CliTest, RenderSceneFileToAbsolutePath) {
    writeFile(dir_ / "scene.json", smallScene());
    const Outcome run =
        shadelab({"render", (dir_ / "scene.json").string(), "--out", (dir_ / "out.png").string()});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_EQ(listing(dir_), (std::set<std::string>{"out.png", "scene.json"}));
    const auto size = pngSize(readFile(dir_ / "out.png"));
    ASSERT_TRUE(size) << "out.png is not a PNG";
    EXPECT_EQ(size->width, 64u) << "the scene's image.width";
    EXPECT_EQ(size->height, 64u) << "the scene's image.height";
}

TEST_F(CliTest, RenderWithExplicitEglBackend) {
    const Outcome run = shadelab({"render", "--backend", "egl", "--size", "64x64", "--out", "out.png"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_EQ(listing(dir_), std::set<std::string>{"out.png"});
    EXPECT_TRUE(pngSize(readFile(dir_ / "out.png")));
}

TEST_F(CliTest, RenderWithOsmesaBackend) {
    const Outcome run = shadelab({"render", "--backend", "osmesa", "--size", "64x64", "--out", "out.png"});
    if (run.exitCode != 0 && run.err.find("without OSMesa") != std::string::npos)
        GTEST_SKIP() << "this shadelab was built without OSMesa: " << run.err;
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_EQ(listing(dir_), std::set<std::string>{"out.png"});
    const auto size = pngSize(readFile(dir_ / "out.png"));
    ASSERT_TRUE(size) << "out.png is not a PNG";
    EXPECT_EQ(size->width, 64u);
    EXPECT_EQ(size->height, 64u);
}

// --api gles (DESIGN §7): the same picture as desktop OpenGL, from an OpenGL ES context that says so.
TEST_F(CliTest, RenderWithOpenGlEsGivesTheDesktopPicture) {
    writeFile(dir_ / "scene.json", smallScene("phong", "blinn-phong", 4, 96, 80));
    const std::string gl = renderBytes({"render", "scene.json", "--api", "gl"}, "gl.png");
    const Outcome run = shadelab({"render", "scene.json", "--api", "gles", "--verbose", "--out", "gles.png"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_TRUE(std::regex_search(run.err, std::regex("OpenGL ES 3\\.0 context: .+, OpenGL ES 3\\.[0-9]")))
        << "the context asked for and the version the driver gives\n"
        << describe(run);
    EXPECT_EQ(readFile(dir_ / "gles.png"), gl) << "OpenGL ES and OpenGL drew different pixels";
}

TEST_F(CliTest, VerboseNamesTheContextAndRenderer) {
    const Outcome run = shadelab({"render", "--size", "16x16", "--verbose", "--out", "out.png"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_TRUE(std::regex_search(run.err, std::regex("^shadelab: EGL (device [0-9]+ \\(.+\\)|surfaceless "
                                                      "platform), OpenGL 3\\.3 core context: .+, OpenGL")))
        << describe(run);
}

// EGL_EXT_platform_device: Mesa lists its software device, so the listing and --egl-device 0 work here.
TEST_F(CliTest, EglDevicesAreListedAndChosen) {
    const Outcome list = shadelab({"render", "--egl-device", "list"});
    ASSERT_EQ(list.exitCode, 0) << describe(list);
    ASSERT_TRUE(std::regex_search(list.out, std::regex("^0: .+: .+OpenGL"))) << describe(list);
    const Outcome gles = shadelab({"render", "--egl-device", "list", "--api", "gles"});
    ASSERT_EQ(gles.exitCode, 0) << describe(gles);
    EXPECT_NE(gles.out.find("OpenGL ES"), std::string::npos) << describe(gles);
    EXPECT_EQ(listing(dir_), std::set<std::string>{}) << "listing wrote a file";

    const std::string chosen = renderBytes({"render", "--size", "48x48", "--egl-device", "0"}, "d0.png");
    const std::string automatic = renderBytes({"render", "--size", "48x48"}, "auto.png");
    EXPECT_EQ(chosen, automatic);
    const Outcome verbose =
        shadelab({"render", "--size", "8x8", "--egl-device", "0", "--verbose", "--out", "v.png"});
    EXPECT_NE(verbose.err.find("EGL device 0 ("), std::string::npos) << describe(verbose);
}

// The regression kit: `shadelab compare` is the tests' comparison from a shell. 0 within the
// tolerance, 1 beyond it (the figures printed, --diff written), 2 for a file that is not there; a mask's
// black pixels are not compared.
TEST_F(CliTest, CompareJudgesAsTheTestsDo) {
    ASSERT_EQ(shadelab({"render", "--size", "64x64", "--out", "a.png"}).exitCode, 0);
    ASSERT_EQ(shadelab({"render", "--size", "64x64", "--shading", "flat", "--out", "b.png"}).exitCode, 0);
    const Outcome same = shadelab({"compare", "a.png", "a.png"});
    EXPECT_EQ(same.exitCode, 0) << describe(same);
    EXPECT_TRUE(same.out.starts_with("pass: max delta 0")) << same.out;
    const Outcome differ = shadelab({"compare", "a.png", "b.png", "--diff", "d.png"});
    EXPECT_EQ(differ.exitCode, 1) << describe(differ);
    EXPECT_TRUE(differ.out.starts_with("FAIL: max delta ")) << differ.out;
    EXPECT_TRUE(pngSize(readFile(dir_ / "d.png"))) << "the difference image";
    const shadelab::Image a = shadelab::readPng(dir_ / "a.png"), b = shadelab::readPng(dir_ / "b.png");
    const shadelab::Comparison c = shadelab::compareImages(a, b, shadelab::Tolerance{});
    EXPECT_NE(differ.out.find("max delta " + std::to_string(c.maxDelta) + ","), std::string::npos)
        << "the same figure as compareImages: " << c.summary() << " vs " << differ.out;
    const Outcome loose = shadelab({"compare", "a.png", "b.png", "--max", "255", "--mean", "255"});
    EXPECT_EQ(loose.exitCode, 0) << describe(loose);
    const shadelab::Image black(64, 64); // all zero: nothing is compared
    shadelab::writePng(black, dir_ / "mask.png");
    const Outcome masked = shadelab({"compare", "a.png", "b.png", "--mask", "mask.png"});
    EXPECT_EQ(masked.exitCode, 0) << describe(masked);
    const Outcome missing = shadelab({"compare", "a.png", "nothere.png"});
    EXPECT_EQ(missing.exitCode, 2) << describe(missing);
    EXPECT_NE(missing.err.find("nothere.png"), std::string::npos) << describe(missing);
}

shadelab::Image filled(int width, int height, std::uint8_t value) {
    shadelab::Image image(width, height);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = i % 4 == 3 ? 255 : value;
    return image;
}

// `compare --json` is the summary as one object for a CI dashboard: the same figures as
// compareImages, the limits, the sizes (both, when they differ), passed as the exit code says, the diff's
// path when one was written.
TEST_F(CliTest, CompareJsonCarriesTheFiguresOfTheSummary) {
    ASSERT_EQ(shadelab({"render", "--size", "64x64", "--out", "a.png"}).exitCode, 0);
    ASSERT_EQ(shadelab({"render", "--size", "64x64", "--shading", "flat", "--out", "b.png"}).exitCode, 0);
    ASSERT_EQ(shadelab({"render", "--size", "32x48", "--out", "small.png"}).exitCode, 0);
    shadelab::Image mask(64, 64);
    shadelab::fillRect(mask, 0, 20, 64, 24, {255, 255, 255, 255}); // compares rows 20..43 only
    shadelab::writePng(mask, dir_ / "mask.png");
    const shadelab::Image a = shadelab::readPng(dir_ / "a.png"), b = shadelab::readPng(dir_ / "b.png");
    const shadelab::Comparison c = shadelab::compareImages(a, b, shadelab::Tolerance{2, 0.5, 3}, &mask);
    ASSERT_FALSE(c.passed) << "flat and phong must differ for this test: " << c.summary();

    const Outcome differ = shadelab({"compare", "a.png", "b.png", "--max", "2", "--mean", "0.5", "--outliers",
                                     "3", "--mask", "mask.png", "--diff", "d.png", "--json"});
    EXPECT_EQ(differ.exitCode, 1) << describe(differ);
    const nlohmann::json j = nlohmann::json::parse(differ.out); // nothing but the object on standard output
    EXPECT_EQ(j["actual"], "a.png");
    EXPECT_EQ(j["expected"], "b.png");
    EXPECT_EQ(j["mask"], "mask.png");
    EXPECT_EQ(j["passed"], false);
    EXPECT_EQ(j["size_matches"], true);
    EXPECT_EQ(j["max_delta"], c.maxDelta);
    EXPECT_DOUBLE_EQ(j["mean_delta"].get<double>(), c.meanDelta);
    EXPECT_EQ(j["outliers"], c.outliers);
    EXPECT_EQ(j["compared_pixels"], 64 * 24);
    EXPECT_EQ(j["pixels"], 64 * 64);
    EXPECT_EQ(j["limits"], (nlohmann::json{{"max", 2}, {"mean", 0.5}, {"outliers", 3}}));
    EXPECT_EQ(j["diff"], "d.png");
    EXPECT_TRUE(pngSize(readFile(dir_ / "d.png"))) << "the difference image";

    const Outcome same = shadelab({"compare", "a.png", "a.png", "--diff", "none.png", "--json"});
    EXPECT_EQ(same.exitCode, 0) << describe(same);
    const nlohmann::json k = nlohmann::json::parse(same.out);
    EXPECT_EQ(k["passed"], true);
    EXPECT_EQ(k["max_delta"], 0);
    EXPECT_EQ(k["mask"], nullptr);
    EXPECT_EQ(k["diff"], nullptr) << "no difference image is written for a pass";
    EXPECT_FALSE(fs::exists(dir_ / "none.png"));

    const Outcome sizes = shadelab({"compare", "a.png", "small.png", "--json"});
    EXPECT_EQ(sizes.exitCode, 1) << describe(sizes);
    const nlohmann::json m = nlohmann::json::parse(sizes.out);
    EXPECT_EQ(m["size_matches"], false);
    EXPECT_EQ(m["passed"], false);
    EXPECT_EQ(m["actual_size"], (nlohmann::json{{"width", 64}, {"height", 64}}));
    EXPECT_EQ(m["expected_size"], (nlohmann::json{{"width", 32}, {"height", 48}}));
    EXPECT_FALSE(m.contains("max_delta")) << "no figures for images of different sizes";
}

// The mean is over the compared pixels: a mask that keeps one row must not dilute a difference everywhere
// (10/255 apart failed --mean 5 without a mask and passed with one, "mean 1.0").
TEST_F(CliTest, CompareMeanIsOverTheComparedPixels) {
    shadelab::writePng(filled(16, 16, 100), dir_ / "a.png");
    shadelab::writePng(filled(16, 16, 110), dir_ / "b.png");
    shadelab::Image mask = filled(16, 16, 0);
    std::fill_n(mask.rgba.begin(), 16 * 4, std::uint8_t(255)); // the first row is compared
    shadelab::writePng(mask, dir_ / "mask.png");
    const Outcome plain = shadelab({"compare", "a.png", "b.png", "--max", "255", "--mean", "5"});
    EXPECT_EQ(plain.exitCode, 1) << describe(plain);
    const Outcome masked =
        shadelab({"compare", "a.png", "b.png", "--max", "255", "--mean", "5", "--mask", "mask.png"});
    EXPECT_EQ(masked.exitCode, 1) << describe(masked);
    EXPECT_NE(masked.out.find("mean delta 10.0000 over the 16 compared pixels of 256"), std::string::npos)
        << masked.out;
    const Outcome help = shadelab({"compare", "--help"});
    EXPECT_NE(help.out.find("over the compared pixels"), std::string::npos) << help.out;
}

// A 16-bit PNG holding the samples s·257 of an 8-bit one, written by libpng as linear data with a gAMA
// chunk of 1.0 (PNG_FORMAT_LINEAR_RGB).
void writeSixteenBitPng(const shadelab::Image& image, const fs::path& path) {
    std::vector<std::uint16_t> samples;
    for (std::size_t i = 0; i < image.rgba.size(); ++i)
        if (i % 4 != 3) samples.push_back(std::uint16_t(image.rgba[i] * 257));
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = png_uint_32(image.width);
    png.height = png_uint_32(image.height);
    png.format = PNG_FORMAT_LINEAR_RGB;
    ASSERT_TRUE(png_image_write_to_file(&png, path.c_str(), 0, samples.data(), 0, nullptr)) << png.message;
}

// compare reads the stored samples: a 16-bit file (with its gAMA chunk) and the 8-bit file of the same
// picture are identical ("max delta 58" before: the 16-bit file was converted as linear light to sRGB).
TEST_F(CliTest, CompareReadsTheStoredSamplesOfSixteenBitFiles) {
    shadelab::Image picture(16, 8);
    for (std::size_t i = 0; i < picture.rgba.size(); ++i) picture.rgba[i] = std::uint8_t(i * 37 % 256);
    shadelab::writePng(picture, dir_ / "eight.png");
    writeSixteenBitPng(picture, dir_ / "sixteen.png");
    ASSERT_EQ(readFile(dir_ / "sixteen.png")[24], 16) << "IHDR's bit depth: the file is not 16-bit";
    const Outcome r = shadelab({"compare", "sixteen.png", "eight.png"});
    EXPECT_EQ(r.exitCode, 0) << describe(r);
    EXPECT_TRUE(r.out.starts_with("pass: max delta 0,")) << r.out;
}

std::uint32_t crc32Of(std::string_view bytes) {
    std::uint32_t crc = 0xffffffffu;
    for (const char byte : bytes) {
        crc ^= std::uint8_t(byte);
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

std::string pngChunk(std::string_view type, std::string_view data) {
    auto big32 = [](std::uint32_t v) {
        return std::string{char(v >> 24), char(v >> 16 & 0xff), char(v >> 8 & 0xff), char(v & 0xff)};
    };
    const std::string body = std::string(type) + std::string(data);
    return big32(std::uint32_t(data.size())) + body + big32(crc32Of(body));
}

// A 69-byte file whose (valid) header claims 32768x32768 pixels cost 4.2 GB and 16 s before "image too
// large": the header is checked against what the file can hold before anything is allocated.
TEST_F(CliTest, CompareRefusesAForgedHeaderBeforeAllocating) {
    std::string ihdr = {0, 0, char(0x80), 0, 0, 0, char(0x80), 0, 8, 2, 0, 0, 0}; // 32768x32768, 8-bit RGB
    const std::string idat = {0x78, 0x01, 0x01, 0x00, 0x00, char(0xff), char(0xff)};
    const std::string forged = std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", ihdr) +
                               pngChunk("IDAT", idat) + pngChunk("IEND", "");
    writeFile(dir_ / "forged.png", forged);
    shadelab::writePng(filled(8, 8, 0), dir_ / "b.png");
    const auto start = std::chrono::steady_clock::now();
    const Outcome r = shadelab({"compare", "forged.png", "b.png"});
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find("32768x32768"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("cannot hold"), std::string::npos) << r.err;
}

// --diff is an output: never one of the inputs (by inode, so no link or hard link either), never standard
// output (which carries the summary); refused with exit 2 before anything is read.
TEST_F(CliTest, CompareDiffNamingAnInputIsRefused) {
    shadelab::writePng(filled(8, 8, 0), dir_ / "a.png");
    shadelab::writePng(filled(8, 8, 200), dir_ / "b.png");
    shadelab::writePng(filled(8, 8, 255), dir_ / "mask.png");
    fs::create_symlink("b.png", dir_ / "link.png");
    fs::create_hard_link(dir_ / "mask.png", dir_ / "hard.png");
    const std::string before =
        readFile(dir_ / "a.png") + readFile(dir_ / "b.png") + readFile(dir_ / "mask.png");
    for (const char* diff : {"a.png", "b.png", "link.png", "hard.png"}) {
        const Outcome r = shadelab({"compare", "a.png", "b.png", "--mask", "mask.png", "--diff", diff});
        EXPECT_EQ(r.exitCode, 2) << diff << ": " << describe(r);
        EXPECT_NE(r.err.find("--diff"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("is the input file"), std::string::npos) << r.err;
        EXPECT_TRUE(r.out.empty()) << "refused before comparing: " << r.out;
    }
    EXPECT_EQ(readFile(dir_ / "a.png") + readFile(dir_ / "b.png") + readFile(dir_ / "mask.png"), before);
    EXPECT_TRUE(fs::is_symlink(dir_ / "link.png"));
    const Outcome dash = shadelab({"compare", "a.png", "b.png", "--diff", "-"});
    EXPECT_EQ(dash.exitCode, 2) << describe(dash);
    EXPECT_NE(dash.err.find("--diff -"), std::string::npos) << dash.err;
    EXPECT_TRUE(dash.out.empty()) << "no PNG interleaved with the summary";
}

// Different sizes: both named, and the difference image still written (a pixel only one image has is a
// full difference).
TEST_F(CliTest, CompareOfDifferentSizesNamesBothAndWritesTheDiff) {
    shadelab::writePng(filled(16, 16, 0), dir_ / "a.png");
    shadelab::writePng(filled(16, 8, 0), dir_ / "b.png");
    const Outcome r = shadelab({"compare", "a.png", "b.png", "--diff", "d.png"});
    EXPECT_EQ(r.exitCode, 1) << describe(r);
    EXPECT_NE(r.out.find("actual 16x16, expected 16x8"), std::string::npos) << r.out;
    const std::optional<PngSize> size = pngSize(readFile(dir_ / "d.png"));
    ASSERT_TRUE(size) << "no difference image";
    EXPECT_EQ(size->width, 16u);
    EXPECT_EQ(size->height, 16u);
}

// A name with a newline or an escape sequence is escaped in every message, so it cannot forge a line such
// as "pass: …" on standard error or recolour a terminal.
TEST_F(CliTest, ControlBytesInArgumentsAreEscapedInEveryMessage) {
    const std::string evil = "x\npass: max delta 0\x1b[0m";
    writeFile(dir_ / (evil + ".png"), "not a PNG");
    shadelab::writePng(filled(8, 8, 0), dir_ / "b.png");
    const std::vector<std::vector<std::string>> runs = {
        {"compare", evil + ".png", "b.png"},
        {"compare", "b.png", evil + "-missing.png"},
        {"render", "--backend", evil, "--out", "o.png"},
        {"render", "--api", evil, "--out", "o.png"},
        {"render", "--egl-device", evil, "--out", "o.png"},
        {"report", "--levels", evil, "--out", "R"},
    };
    for (const std::vector<std::string>& args : runs) {
        const Outcome r = shadelab(args);
        EXPECT_EQ(r.exitCode, 2) << args[0] << " " << args[1] << ": " << describe(r);
        EXPECT_EQ(r.err.find("\npass:"), std::string::npos) << "a forged line: " << r.err;
        EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << "a raw escape: " << r.err;
        EXPECT_NE(r.err.find("pass: max delta 0"), std::string::npos) << "the name, quoted back: " << r.err;
    }
}

// A split view's levels go through the work limit as --subdivisions does: 64 spheres at level 10 on two
// sides drew 2 × 268 M triangles (35 s, exit 0) although --subdivisions 10 alone is refused.
TEST_F(CliTest, SplitViewLevelsGoThroughTheWorkLimit) {
    std::string objects;
    for (int i = 0; i < 64; ++i)
        objects += std::string(i ? ", " : "") + R"({"center": [)" + std::to_string(i % 8 - 4) + ", " +
                   std::to_string(i / 8 - 4) + R"(, 0], "radius": 0.4, "subdivisions": 0})";
    writeFile(dir_ / "many.json", R"({"image": {"width": 64, "height": 64}, "objects": [)" + objects + "]}");
    const auto start = std::chrono::steady_clock::now();
    const Outcome r =
        shadelab({"render", "many.json", "--view", "split:phong@10,gouraud@10", "--out", "s.png"});
    EXPECT_EQ(r.exitCode, 2) << describe(r);
    EXPECT_NE(r.err.find("once per side of the split"), std::string::npos) << r.err;
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10)) << "refused before drawing";
    EXPECT_FALSE(fs::exists(dir_ / "s.png"));
}

// `reference` takes render's context flags (checked, no effect), so one command line switches.
TEST_F(CliTest, ReferenceAcceptsRendersContextFlags) {
    for (const std::vector<std::string>& flags :
         {std::vector<std::string>{"--backend", "osmesa", "--specialize", "off"},
          std::vector<std::string>{"--backend", "egl", "--api", "gles"}}) {
        std::vector<std::string> args = {"reference", "--size", "32x32", "--out", "r.png"};
        args.insert(args.end(), flags.begin(), flags.end());
        const Outcome run = shadelab(args);
        ASSERT_EQ(run.exitCode, 0) << describe(run);
        EXPECT_TRUE(pngSize(readFile(dir_ / "r.png")));
    }
}

// Colours are linear 0..1; [200, 30, 30] is valid but is a warning naming the field.
TEST_F(CliTest, ColourAboveTenIsAWarningNamingTheField) {
    writeFile(dir_ / "scene.json", R"({ "objects": [ { "material": { "diffuse": [200, 30, 30] } } ] })");
    const Outcome run = shadelab({"render", "scene.json", "--size", "16x16", "--out", "out.png"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_NE(run.err.find("warning: scene.json: objects[0].material.diffuse: [200, 30, 30]"),
              std::string::npos)
        << describe(run);
    EXPECT_NE(run.err.find("linear 0..1"), std::string::npos) << describe(run);
    const Outcome plain = shadelab({"render", "--size", "16x16", "--out", "plain.png"});
    EXPECT_EQ(plain.err.find("warning"), std::string::npos) << describe(plain);
}

// A subcommand's --help is about that subcommand, without the demo's key table.
TEST_F(CliTest, SubcommandHelpLeavesOutTheDemoKeys) {
    for (const char* command : {"render", "reference", "report", "bench"}) {
        const Outcome run = shadelab({command, "--help"});
        EXPECT_EQ(run.exitCode, 0) << describe(run);
        EXPECT_EQ(run.out.find("Demo keys"), std::string::npos) << command << "\n" << run.out;
    }
    const Outcome top = shadelab({"--help"});
    EXPECT_NE(top.out.find("Demo keys"), std::string::npos) << top.out;
    // And the views' table under it, a line per view and shading mode (what it draws, where, the formula).
    EXPECT_NE(top.out.find("Views (what each shows):\nscene    the objects as the camera sees them; in "),
              std::string::npos)
        << top.out;
    EXPECT_NE(top.out.find("\nndc      the objects after M_proj·M_cam"), std::string::npos) << top.out;
}

// `bench`'s table carries no colour escapes when it is not written to a terminal.
TEST_F(CliTest, BenchWritesNoColourEscapesIntoAPipe) {
    const Outcome run =
        shadelab({"bench", "--filter", "sphere/build/level0/", "--frames", "3", "--warmup", "0"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_NE(run.out.find("sphere/build/level0"), std::string::npos) << run.out;
    EXPECT_EQ(run.out.find('\x1b'), std::string::npos) << "an ANSI escape in piped output";
}

TEST_F(CliTest, ReferenceWithoutSceneWritesOnlyThePng) {
    const Outcome run = shadelab({"reference", "--size", "64x64", "--out", "ref.png"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_EQ(listing(dir_), std::set<std::string>{"ref.png"});
    const auto size = pngSize(readFile(dir_ / "ref.png"));
    ASSERT_TRUE(size) << "ref.png is not a PNG";
    EXPECT_EQ(size->width, 64u);
    EXPECT_EQ(size->height, 64u);
}

TEST_F(CliTest, ReferenceSceneFile) {
    writeFile(dir_ / "scene.json", smallScene());
    const Outcome run = shadelab({"reference", "scene.json", "--out", "ref.png"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_EQ(listing(dir_), (std::set<std::string>{"ref.png", "scene.json"}));
    const auto size = pngSize(readFile(dir_ / "ref.png"));
    ASSERT_TRUE(size) << "ref.png is not a PNG";
    EXPECT_EQ(size->width, 64u);
    EXPECT_EQ(size->height, 64u);
}

// --- Flags override the scene file --------------------------------------------------------------------

// A flag's help lists exactly the spellings it accepts (both come from the vocabularies), so
// `exact` is in --shading's help and every spelling in a help is accepted.
TEST_F(CliTest, FlagHelpListsEverySpellingTheFlagAccepts) {
    const Outcome help = shadelab({"render", "--help"});
    ASSERT_EQ(help.exitCode, 0) << help.err;
    const auto helpLine = [&](std::string_view flag) {
        const std::size_t at = help.out.find(std::string(flag) + " ");
        EXPECT_NE(at, std::string::npos) << flag << " is not in render --help:\n" << help.out;
        if (at == std::string::npos) return std::string();
        // The description runs until the next option's line (CLI11 wraps it onto indented lines).
        const std::size_t end = help.out.find("\n  -", at);
        return help.out.substr(at, end - at);
    };
    const auto check = [&](std::string_view flag, const auto& vocabulary) {
        const std::string line = helpLine(flag);
        const std::string listed = shadelab::joinNames(vocabulary);
        EXPECT_NE(line.find(listed), std::string::npos)
            << flag << "'s help does not list " << listed << ": " << line;
        for (const auto value : vocabulary) {
            const std::string spelling(shadelab::toString(value));
            const Outcome run =
                shadelab({"render", std::string(flag), spelling, "--size", "16x16", "--out", "v.png"});
            EXPECT_EQ(run.exitCode, 0) << flag << " " << spelling << " is listed but refused: " << run.err;
        }
    };
    check("--shading", shadelab::kAllShadingModes);
    check("--lighting", shadelab::kLightingModels);
    check("--depth", shadelab::kDepthModes);
    check("--overlay", shadelab::kOverlays);
    EXPECT_NE(helpLine("--shading").find("exact"), std::string::npos);
}

TEST_F(CliTest, ShadingFlagOverridesScene) {
    writeFile(dir_ / "flat.json", smallScene("flat"));
    writeFile(dir_ / "phong.json", smallScene("phong"));
    const std::string overridden =
        renderBytes({"render", "flat.json", "--shading", "phong"}, "overridden.png");
    const std::string phong = renderBytes({"render", "phong.json"}, "phong.png");
    const std::string flat = renderBytes({"render", "flat.json"}, "flat.png");
    EXPECT_TRUE(overridden == phong) << "flat scene + --shading phong differs from the phong scene";
    EXPECT_TRUE(overridden != flat) << "--shading phong was ignored: the image equals the flat one";
}

TEST_F(CliTest, LightingFlagOverridesScene) {
    writeFile(dir_ / "phong.json", smallScene("phong", "phong"));
    writeFile(dir_ / "blinn.json", smallScene("phong", "blinn-phong"));
    const std::string overridden =
        renderBytes({"render", "phong.json", "--lighting", "blinn-phong"}, "o.png");
    const std::string blinn = renderBytes({"render", "blinn.json"}, "blinn.png");
    const std::string phong = renderBytes({"render", "phong.json"}, "phong.png");
    EXPECT_TRUE(overridden == blinn)
        << "phong scene + --lighting blinn-phong differs from the blinn-phong scene";
    EXPECT_TRUE(overridden != phong) << "--lighting blinn-phong was ignored: the image equals the phong one";
}

TEST_F(CliTest, SubdivisionsFlagOverridesScene) {
    writeFile(dir_ / "coarse.json", smallScene("flat", "blinn-phong", 1));
    writeFile(dir_ / "fine.json", smallScene("flat", "blinn-phong", 4));
    const std::string overridden = renderBytes({"render", "coarse.json", "--subdivisions", "4"}, "o.png");
    const std::string fine = renderBytes({"render", "fine.json"}, "fine.png");
    const std::string coarse = renderBytes({"render", "coarse.json"}, "coarse.png");
    EXPECT_TRUE(overridden == fine) << "level-1 scene + --subdivisions 4 differs from the level-4 scene";
    EXPECT_TRUE(overridden != coarse) << "--subdivisions 4 was ignored: the image equals the level-1 one";
}

TEST_F(CliTest, SizeFlagOverridesScene) {
    writeFile(dir_ / "scene.json", smallScene("phong", "blinn-phong", 3, 48, 48));
    const auto size = pngSize(renderBytes({"render", "scene.json", "--size", "64x32"}, "out.png"));
    ASSERT_TRUE(size);
    EXPECT_EQ(size->width, 64u) << "IHDR width";
    EXPECT_EQ(size->height, 32u) << "IHDR height";
}

// --- Output files are replaced only on success --------------------------------------------------------

constexpr std::string_view kPrecious = "not a PNG: the bytes of an earlier run that must survive a failure\n";

TEST_F(CliTest, FailedRenderLeavesExistingOutputUnchanged) {
    writeFile(dir_ / "out.png", kPrecious);
    const Outcome run = shadelab({"render", "--shading", "bogus", "--size", "64x64", "--out", "out.png"});
    EXPECT_EQ(run.exitCode, 2) << describe(run);
    EXPECT_EQ(readFile(dir_ / "out.png"), kPrecious);
    EXPECT_EQ(listing(dir_), std::set<std::string>{"out.png"});
}

TEST_F(CliTest, FailedReferenceLeavesExistingOutputUnchanged) {
    writeFile(dir_ / "out.png", kPrecious);
    const Outcome run =
        shadelab({"reference", "--subdivisions", "11", "--size", "64x64", "--out", "out.png"});
    EXPECT_EQ(run.exitCode, 2) << describe(run);
    EXPECT_EQ(readFile(dir_ / "out.png"), kPrecious);
    EXPECT_EQ(listing(dir_), std::set<std::string>{"out.png"});
}

TEST_F(CliTest, SuccessfulRenderReplacesExistingOutput) {
    writeFile(dir_ / "out.png", kPrecious);
    const Outcome run = shadelab({"render", "--size", "64x64", "--out", "out.png"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_TRUE(pngSize(readFile(dir_ / "out.png"))) << "out.png was not replaced by a PNG";
    EXPECT_EQ(listing(dir_), std::set<std::string>{"out.png"});
}

// An I/O failure is a run-time failure (exit 1), not bad input: /proc exists but takes no new files.
TEST_F(CliTest, UnwritableOutputFolderIsRuntimeFailure) {
    const std::string out = "/proc/shadelab-cli-test-" + std::to_string(::getpid()) + ".png";
    const Outcome run = shadelab({"render", "--size", "64x64", "--out", out});
    EXPECT_EQ(run.exitCode, 1) << describe(run);
    EXPECT_NE(run.err.find(out), std::string::npos) << "stderr does not name the output path\n"
                                                    << describe(run);
    EXPECT_FALSE(fs::exists(out));
    EXPECT_TRUE(listing(dir_).empty());
}

// --- Help and the demo --------------------------------------------------------------------------------

TEST_F(CliTest, HelpListsTheSubcommands) {
    const Outcome run = shadelab({"--help"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_NE(run.out.find("render"), std::string::npos) << describe(run);
    EXPECT_NE(run.out.find("reference"), std::string::npos) << describe(run);
    EXPECT_TRUE(listing(dir_).empty());
}

TEST_F(CliTest, DemoWithoutDisplayWritesShowcase) {
    const fs::path out = dir_ / "s.png";
    const Outcome run = shadelab({"--showcase-out", out.string()}, Display::None);
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_NE(run.out.find(out.string()), std::string::npos) << "the showcase path is not printed\n"
                                                             << describe(run);
    EXPECT_NE((run.out + run.err).find("display"), std::string::npos)
        << "it does not say there is no display\n"
        << describe(run);
    EXPECT_EQ(listing(dir_), std::set<std::string>{"s.png"});
    const auto size = pngSize(readFile(out));
    ASSERT_TRUE(size) << "s.png is not a PNG";
    // 4 tiles of 256 px wide; per lighting model a row of pictures and a row of their error heatmaps.
    EXPECT_EQ(size->width, 4 * 256);
    EXPECT_GT(size->height, 4 * 256) << "the showcase has 4 rows of tiles (plus labels)";
}

// --- Bad input: exit code 2, a message naming the argument or JSON path and the value, no file left ----

enum class Prepare { Nothing, SceneFile, SceneIsDirectory, OutIsDirectory };

struct BadInput {
    const char* name;
    std::vector<std::string> args;
    std::vector<std::string> mentions; // substrings stderr must contain: what is wrong and the bad value
    Prepare prepare = Prepare::Nothing;
    std::string scene = smallScene(); // written to scene.json for Prepare::SceneFile
    const char* pattern = nullptr;    // a regex stderr must also match, where substrings are not enough
    Display display = Display::Inherit;
};

std::ostream& operator<<(std::ostream& out, const BadInput& c) {
    return out << c.name;
}

const std::string kNegativeAttenuation =
    R"({ "lights": [ { "type": "point", "position": [3, 3, 5], "attenuation": [1, 0, -1] } ] })";

const BadInput kBadInputs[] = {
    {.name = "shading_bogus",
     .args = {"render", "--shading", "bogus", "--size", "64x64", "--out", "out.png"},
     .mentions = {"--shading", "bogus"}},
    {.name = "lighting_bogus",
     .args = {"render", "--lighting", "bogus", "--size", "64x64", "--out", "out.png"},
     .mentions = {"--lighting", "bogus"}},
    {.name = "subdivisions_above_maximum",
     .args = {"render", "--subdivisions", "11", "--size", "64x64", "--out", "out.png"},
     .mentions = {"--subdivisions", "11", "MiB"},
     .pattern = R"(maximum\D*10\b)"},
    {.name = "subdivisions_negative",
     .args = {"render", "--subdivisions", "-1", "--size", "64x64", "--out", "out.png"},
     .mentions = {"--subdivisions", "-1"}},
    {.name = "size_zero_width",
     .args = {"render", "--size", "0x10", "--out", "out.png"},
     .mentions = {"--size width", "between 1 and 16384", "got 0"}},
    {.name = "size_too_large",
     .args = {"render", "--size", "20000x20000", "--out", "out.png"},
     .mentions = {"--size width", "between 1 and 16384", "got 20000"}},
    {.name = "size_not_wxh",
     .args = {"render", "--size", "abc", "--out", "out.png"},
     .mentions = {"--size", "abc"}},
    {.name = "backend_vulkan",
     .args = {"render", "--backend", "vulkan", "--size", "64x64", "--out", "out.png"},
     .mentions = {"--backend", "vulkan"}},
    {.name = "out_missing", .args = {"render", "--size", "64x64"}, .mentions = {"--out"}},
    {.name = "out_folder_missing",
     .args = {"render", "--size", "64x64", "--out", "no-such-folder/out.png"},
     .mentions = {"--out", "no-such-folder"}},
    {.name = "out_is_directory",
     .args = {"render", "--size", "64x64", "--out", "out.png"},
     .mentions = {"--out", "out.png"},
     .prepare = Prepare::OutIsDirectory},
    {.name = "scene_missing",
     .args = {"render", "no-such-scene.json", "--size", "64x64", "--out", "out.png"},
     .mentions = {"no-such-scene.json"}},
    {.name = "scene_is_directory",
     .args = {"render", "scene.json", "--size", "64x64", "--out", "out.png"},
     .mentions = {"scene.json"},
     .prepare = Prepare::SceneIsDirectory},
    {.name = "scene_malformed_json",
     .args = {"render", "scene.json", "--size", "64x64", "--out", "out.png"},
     .mentions = {"scene.json"},
     .prepare = Prepare::SceneFile,
     .scene = R"({ "shading": "phong", "objects": [ { "radius": 1 )"},
    {.name = "scene_unknown_key",
     .args = {"render", "scene.json", "--size", "64x64", "--out", "out.png"},
     .mentions = {"objects[0]", "radious"},
     .prepare = Prepare::SceneFile,
     .scene = R"({ "objects": [ { "radius": 1, "radious": 2 } ] })"},
    {.name = "scene_negative_attenuation",
     .args = {"render", "scene.json", "--size", "64x64", "--out", "out.png"},
     .mentions = {"lights[0].attenuation[2]", "-1"},
     .prepare = Prepare::SceneFile,
     .scene = kNegativeAttenuation},
    // A mistyped subcommand is the bad argument; the message must name it, not only the flags after it.
    {.name = "unknown_subcommand",
     .args = {"rendr", "--size", "64x64", "--out", "out.png"},
     .mentions = {"rendr"}},
    {.name = "extra_positional",
     .args = {"render", "scene.json", "extra.json", "--size", "64x64", "--out", "out.png"},
     .mentions = {"extra.json"},
     .prepare = Prepare::SceneFile},
    {.name = "reference_shading_bogus",
     .args = {"reference", "--shading", "bogus", "--size", "64x64", "--out", "out.png"},
     .mentions = {"--shading", "bogus"}},
    {.name = "reference_scene_negative_attenuation",
     .args = {"reference", "scene.json", "--size", "64x64", "--out", "out.png"},
     .mentions = {"lights[0].attenuation[2]", "-1"},
     .prepare = Prepare::SceneFile,
     .scene = kNegativeAttenuation},
    {.name = "reference_out_missing", .args = {"reference", "--size", "64x64"}, .mentions = {"--out"}},
    {.name = "subdivisions_not_an_integer",
     .args = {"render", "--subdivisions", "1.5", "--size", "64x64", "--out", "out.png"},
     .mentions = {"--subdivisions", "1.5"}},
    {.name = "out_empty", .args = {"render", "--size", "64x64", "--out", ""}, .mentions = {"--out"}},
    {.name = "scene_non_finite_number",
     .args = {"render", "scene.json", "--size", "64x64", "--out", "out.png"},
     .mentions = {"objects[0].radius", "1e999"},
     .prepare = Prepare::SceneFile,
     .scene = R"({ "objects": [ { "radius": 1e999 } ] })"},
    {.name = "scene_wrong_type",
     .args = {"render", "scene.json", "--size", "64x64", "--out", "out.png"},
     .mentions = {"shading", "3"},
     .prepare = Prepare::SceneFile,
     .scene = R"({ "shading": 3 })"},
    // The demo validates its arguments before it looks for a display or renders the showcase.
    // Messages that say what to do.
    {.name = "json_comment",
     .args = {"render", "scene.json", "--out", "out.png"},
     .mentions = {"scene.json", "JSON has no comments"},
     .prepare = Prepare::SceneFile,
     .scene = "{\n  // flat, for the handout\n  \"shading\": \"flat\"\n}\n"},
    {.name = "option_misspelt",
     .args = {"render", "--shadding", "flat", "--out", "out.png"},
     .mentions = {"--shadding", "did you mean --shading?"}},
    {.name = "reference_backend_bogus",
     .args = {"reference", "--backend", "bogus", "--size", "8x8", "--out", "out.png"},
     .mentions = {"--backend", "bogus"}},
    {.name = "bench_filter_matches_nothing",
     .args = {"bench", "--filter", "no-such-benchmark", "--frames", "3", "--warmup", "0"},
     .mentions = {"--filter", "no-such-benchmark", "matches no benchmark"}},
    {.name = "api_bogus",
     .args = {"render", "--api", "vulkan", "--size", "8x8", "--out", "out.png"},
     .mentions = {"--api", "vulkan", "gl", "gles"}},
    {.name = "api_gles_with_osmesa",
     .args = {"render", "--api", "gles", "--backend", "osmesa", "--size", "8x8", "--out", "out.png"},
     .mentions = {"--api gles", "OSMesa", "--backend egl"}},
    {.name = "egl_device_not_a_number",
     .args = {"render", "--egl-device", "gpu0", "--size", "8x8", "--out", "out.png"},
     .mentions = {"--egl-device", "gpu0", "list"}},
    {.name = "egl_device_out_of_range",
     .args = {"render", "--egl-device", "99", "--size", "8x8", "--out", "out.png"},
     .mentions = {"--egl-device 99", "EGL device", "--egl-device list"}},
    {.name = "egl_device_with_osmesa",
     .args = {"render", "--backend", "osmesa", "--egl-device", "0", "--size", "8x8", "--out", "out.png"},
     .mentions = {"--egl-device", "EGL backend"}},
    {.name = "render_without_out", .args = {"render", "--size", "8x8"}, .mentions = {"--out is required"}},
    {.name = "demo_scene_missing",
     .args = {"no-such-scene.json", "--showcase-out", "s.png"},
     .mentions = {"no-such-scene.json"},
     .display = Display::None},
    {.name = "showcase_out_folder_missing",
     .args = {"--showcase-out", "no-such-folder/s.png"},
     .mentions = {"--showcase-out", "no-such-folder"},
     .display = Display::None},
};

class CliBadInputTest : public CliTest, public ::testing::WithParamInterface<BadInput> {};

TEST_P(CliBadInputTest, ExitsWithTwoNamesTheValueAndWritesNothing) {
    const BadInput& c = GetParam();
    switch (c.prepare) {
    case Prepare::Nothing:
        break;
    case Prepare::SceneFile:
        writeFile(dir_ / "scene.json", c.scene);
        break;
    case Prepare::SceneIsDirectory:
        fs::create_directory(dir_ / "scene.json");
        break;
    case Prepare::OutIsDirectory:
        fs::create_directory(dir_ / "out.png");
        break;
    }
    const std::set<std::string> before = listing(dir_);
    const Outcome run = shadelab(c.args, c.display);
    EXPECT_EQ(run.exitCode, 2) << describe(run);
    for (const std::string& mention : c.mentions)
        EXPECT_NE(run.err.find(mention), std::string::npos) << "stderr does not mention " << mention << "\n"
                                                            << describe(run);
    if (c.pattern) {
        EXPECT_TRUE(std::regex_search(run.err, std::regex(c.pattern)))
            << "stderr does not match /" << c.pattern << "/\n"
            << describe(run);
    }
    EXPECT_EQ(listing(dir_), before) << "a file was written or left behind";
}

INSTANTIATE_TEST_SUITE_P(Table, CliBadInputTest, ::testing::ValuesIn(kBadInputs),
                         [](const ::testing::TestParamInfo<BadInput>& info) { return info.param.name; });

} // namespace
