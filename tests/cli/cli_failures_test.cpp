// What a failed run of the command line does, against DESIGN §5: bad input exits with 2 and a message naming
// the argument or JSON path and its value, and writes nothing (a table of cases); an I/O failure exits
// with 1; an existing output is replaced only on success; control bytes in an argument are escaped in every
// message; a split view's levels are refused by the work limit before drawing. Each test in a fresh
// temporary folder (cli_fixture.h). Built into cli_test.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <ostream>
#include <regex>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "cli/cli_fixture.h"
#include "cli/run_process.h"
#include "shadelab/image/image_file.h"

namespace {

using namespace shadelab::cli_test;

namespace fs = std::filesystem;

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
