// `render`, `reference`, `bench` and the help end to end, against DESIGN §5 (not against its implementation):
// a PNG and nothing else, the backends and contexts (EGL, OSMesa, OpenGL ES, a chosen EGL device),
// --print-matrices held to the lecture's formulas, flags overriding the scene file, each flag's help listing
// what it accepts, and the demo's headless showcase when there is no display. The binary runs through
// fork/execve, never a shell, each test in a fresh temporary folder (cli_fixture.h). Built into cli_test.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "cli/cli_fixture.h"
#include "cli/run_process.h"
#include "shadelab/scene/scene.h"
#include "shadelab/shading/lighting.h"
#include "shadelab/vocabulary.h"

namespace {

using namespace shadelab::cli_test;

namespace fs = std::filesystem;

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

} // namespace
