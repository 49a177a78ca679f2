// The teapot and models from files through the command line (DESIGN §1, §4): scenes/teapot.json renders a
// teapot; a "mesh" path is relative to the scene file's folder, whatever the working directory, in render,
// check and a lesson's steps; a model that cannot be read stops the command with exit 2 naming the object;
// `report` on a teapot scene measures the teapot's levels 0..8, a row per level.
#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"
#include "cli/run_process.h"
#include "shadelab/geometry/teapot.h"
#include "shadelab/image/image_file.h"

namespace shadelab::cli_test {
namespace {

// An octahedron of radius 1, counter-clockwise seen from outside, without normals (the loader makes them).
constexpr std::string_view kOctahedronObj = "v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n"
                                            "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\n"
                                            "f 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";

std::string meshScene(const std::string& mesh) {
    return R"({"image": {"width": 64, "height": 48}, "objects": [{"mesh": ")" + mesh +
           R"(", "material": {"diffuse": [0.8, 0.8, 0.8]}}]})";
}

// The bounding box of the pixels that differ from the top left one (the background), and how many there are.
struct Coverage {
    int left = 1 << 30, right = -1, top = 1 << 30, bottom = -1;
    std::size_t pixels = 0;
};
Coverage coverage(const Image& image) {
    Coverage c;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::size_t at = 4 * (std::size_t(y) * std::size_t(image.width) + std::size_t(x));
            if (std::equal(image.rgba.begin() + long(at), image.rgba.begin() + long(at) + 3,
                           image.rgba.begin()))
                continue;
            ++c.pixels;
            c.left = std::min(c.left, x);
            c.right = std::max(c.right, x);
            c.top = std::min(c.top, y);
            c.bottom = std::max(c.bottom, y);
        }
    return c;
}

TEST_F(CliTest, TheBundledTeapotSceneRendersATeapot) {
    const std::string scene = std::string(SHADELAB_TEST_DATA) + "/../scenes/teapot.json";
    const Outcome run = shadelab({"render", scene, "--out", "teapot.png"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    const Image image = readPng(dir_ / "teapot.png");
    const Coverage c = coverage(image);
    // Not empty: the teapot fills a good part of the picture...
    EXPECT_GT(double(c.pixels), 0.15 * image.width * image.height) << c.pixels << " pixels drawn";
    // ...and it is the teapot, not a sphere: the spout and the handle make it half again as wide as tall
    // (object coordinates: about 3.2 wide, 2 high).
    const double width = c.right - c.left + 1, height = c.bottom - c.top + 1;
    EXPECT_GT(width / height, 1.4) << width << " x " << height << " pixels";
}

TEST_F(CliTest, AMeshPathIsRelativeToTheSceneFilesFolder) {
    fs::create_directories(dir_ / "scenes" / "models");
    fs::create_directories(dir_ / "elsewhere");
    writeFile(dir_ / "scenes" / "models" / "octahedron.obj", kOctahedronObj);
    writeFile(dir_ / "scenes" / "octahedron.json", meshScene("models/octahedron.obj"));
    // Run from a folder that has no models/ of its own: only the scene's folder can resolve the path.
    const Outcome run =
        runShadelab({"render", "../scenes/octahedron.json", "--out", "octahedron.png"}, dir_ / "elsewhere");
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_GT(coverage(readPng(dir_ / "elsewhere" / "octahedron.png")).pixels, 200u);
    // `check` reads it as render does, and so does a lesson's step that names the scene from its own folder.
    const Outcome check = runShadelab({"check", "../scenes/octahedron.json"}, dir_ / "elsewhere");
    EXPECT_EQ(check.exitCode, 0) << describe(check);
    fs::create_directories(dir_ / "lessons");
    writeFile(
        dir_ / "lessons" / "l.json",
        R"({"title": "Models", "steps": [{"title": "An octahedron", "scene": "../scenes/octahedron.json"},
                  {"title": "Again, flat", "shading": "flat"}]})");
    const Outcome lesson = runShadelab({"check", "../lessons/l.json"}, dir_ / "elsewhere");
    EXPECT_EQ(lesson.exitCode, 0) << describe(lesson);
}

TEST_F(CliTest, AMeshFromStandardInputIsRelativeToTheWorkingDirectory) {
    fs::create_directories(dir_ / "models");
    writeFile(dir_ / "models" / "octahedron.obj", kOctahedronObj);
    RunOptions options;
    options.stdinText = meshScene("models/octahedron.obj");
    const Outcome run = runWith({"render", "-", "--out", "stdin.png"}, dir_, options);
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_GT(coverage(readPng(dir_ / "stdin.png")).pixels, 200u);
}

TEST_F(CliTest, AMissingMeshStopsEveryCommandWithExit2NamingTheObject) {
    writeFile(dir_ / "missing.json", meshScene("models/missing.obj"));
    writeFile(dir_ / "l.json", R"({"title": "M", "steps": [{"title": "Missing", "scene": "missing.json"}]})");
    const std::vector<std::vector<std::string>> commands = {
        {"render", "missing.json", "--out", "out.png"},
        {"reference", "missing.json", "--out", "out.png"},
        {"check", "missing.json"},
        {"check", "l.json"},
        {"slides", "l.json", "--out-dir", "slides"},
        {"report", "missing.json", "--out", "report", "--levels", "0..0", "--no-plot"},
    };
    for (const auto& args : commands) {
        const Outcome run = shadelab(args);
        EXPECT_EQ(run.exitCode, 2) << describe(run);
        EXPECT_NE(run.err.find("objects[0].mesh"), std::string::npos) << describe(run);
        EXPECT_NE(run.err.find("missing.json"), std::string::npos) << "names the scene file\n"
                                                                   << describe(run);
        EXPECT_FALSE(fs::exists(dir_ / "out.png")) << args[0] << " wrote its output";
        EXPECT_FALSE(fs::exists(dir_ / "slides" / "1-missing.png")) << args[0] << " wrote a slide";
    }
}

// report.csv's rows as (level, triangles) per row, from the columns of that name.
std::vector<std::pair<std::string, std::string>> levelsAndTriangles(const std::string& csv) {
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);
    const auto split = [](const std::string& text) {
        std::vector<std::string> cells;
        std::istringstream row(text);
        for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
        return cells;
    };
    const std::vector<std::string> header = split(line);
    const auto column = [&](const std::string& name) {
        return std::size_t(std::find(header.begin(), header.end(), name) - header.begin());
    };
    const std::size_t level = column("level"), triangles = column("triangles");
    std::vector<std::pair<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        const std::vector<std::string> cells = split(line);
        if (cells.size() > std::max(level, triangles)) rows.emplace_back(cells[level], cells[triangles]);
    }
    return rows;
}

TEST_F(CliTest, TheReportOnATeapotMeasuresATeapotRowPerLevel) {
    writeFile(dir_ / "teapot.json", R"({"image": {"width": 32, "height": 24}, "camera": {"eye": [0, 1, 5]},
        "objects": [{"shape": "teapot", "subdivisions": 2}]})");
    // 0..3, and "auto": each row counts the teapot's triangles at its level (teapot.h), not a sphere's.
    const Outcome run = shadelab({"report", "teapot.json", "--out", "report", "--levels", "0..3", "--frames",
                                  "1", "--warmup", "1", "--no-plot"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    const auto rows = levelsAndTriangles(readFile(dir_ / "report" / "report.csv"));
    ASSERT_EQ(rows.size(), 2u * 4u * 5u) << "lighting models x shading modes x (levels 0..3 and auto)";
    std::vector<int> perLevel(4, 0);
    for (const auto& [level, triangles] : rows) {
        if (level == "auto") continue;
        const int n = std::stoi(level);
        ASSERT_TRUE(n >= 0 && n <= 3) << level;
        ++perLevel[std::size_t(n)];
        EXPECT_EQ(triangles, std::to_string(teapotTriangleCount(n))) << "level " << n;
    }
    EXPECT_EQ(perLevel, std::vector<int>(4, 8)) << "a row per mode and model at each level";
}

} // namespace
} // namespace shadelab::cli_test
