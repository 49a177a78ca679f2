// The worked example of docs/ci-engineers.md "Screenshot regression in your CI" (examples/ci/), run as a CI
// job runs it: on a copy of the example, against the shadelab under test. It passes as committed; a reference
// changed in a block of pixels fails with the render, the difference image and the comparison's JSON left in
// the artifacts folder; a mask over that block passes again; a driver without references is named as missing;
// --bless writes the references of the driver that drew them.
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/run_process.h"
#include "shadelab/image/image.h"
#include "shadelab/image/image_file.h"

namespace {

using namespace shadelab::cli_test;
namespace fs = std::filesystem;

class CiExample : public ::testing::Test {
protected:
    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "shadelab-ci-example-XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr)
            << "mkdtemp " << pattern << ": " << std::strerror(errno);
        dir_ = pattern;
        example_ = dir_ / "ci";
        fs::copy(fs::path(SHADELAB_SOURCE_DIR) / "examples" / "ci", example_, fs::copy_options::recursive);
        fs::remove_all(example_ / "screenshot-artifacts"); // a developer's run of the example, if any
        artifacts_ = dir_ / "artifacts";
    }
    void TearDown() override {
        std::error_code ignored;
        if (!dir_.empty()) fs::remove_all(dir_, ignored);
    }

    // Runs the example job with the shadelab under test; `environment` adds NAME=value entries. `script` is
    // the path bash is given, from dir_ (the copy's script by default; a relative path or a link to it).
    Outcome job(std::vector<std::string> args = {}, const std::vector<std::string>& environment = {},
                std::string script = {}) {
        if (script.empty()) script = (example_ / "screenshot-regression.sh").string();
        args.insert(args.begin(), {script, "--shadelab", shadelabExe(), "--artifacts", artifacts_.string()});
        RunOptions options;
        options.program = "/bin/bash";
        options.environment = childEnvironment(Display::Inherit, environment);
        return runWith(args, dir_, options);
    }

    fs::path dir_, example_, artifacts_;
};

TEST_F(CiExample, PassesAsCommittedAndLeavesNoArtifacts) {
    const Outcome run = job();
    EXPECT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_NE(run.out.find("driver: llvmpipe"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("pass: phong-sphere"), std::string::npos) << run.out;
    EXPECT_NE(run.out.find("pass: toon-spot"), std::string::npos) << run.out;
    EXPECT_TRUE(fs::is_empty(artifacts_)) << "a pass leaves nothing to upload";
}

TEST_F(CiExample, AChangedReferenceFailsWithItsArtifactsAndAMaskOverTheChangePasses) {
    const fs::path reference = example_ / "references" / "llvmpipe" / "toon-spot.png";
    shadelab::Image image = shadelab::readPng(reference);
    shadelab::fillRect(image, 10, 10, 12, 12, {255, 0, 255, 255});
    shadelab::writePng(image, reference);
    fs::create_directories(artifacts_);
    writeFile(artifacts_ / "notes.txt", "the user's own file");

    const Outcome failed = job();
    EXPECT_EQ(failed.exitCode, 1) << describe(failed);
    EXPECT_NE(failed.out.find("pass: phong-sphere"), std::string::npos) << failed.out;
    EXPECT_NE(failed.out.find("FAIL: toon-spot"), std::string::npos) << failed.out;
    EXPECT_TRUE(fs::exists(artifacts_ / "toon-spot.png")) << "the render";
    EXPECT_TRUE(fs::exists(artifacts_ / "toon-spot.diff.png")) << "the difference image";
    EXPECT_FALSE(fs::exists(artifacts_ / "phong-sphere.png")) << "only the failing scene's files";
    EXPECT_EQ(readFile(artifacts_ / "notes.txt"), "the user's own file");
    const nlohmann::json figures = nlohmann::json::parse(readFile(artifacts_ / "toon-spot.json"));
    EXPECT_EQ(figures["passed"], false);
    EXPECT_EQ(figures["outliers"], 144) << "the 12x12 block, every pixel of it beyond --max";

    shadelab::Image mask(image.width, image.height);
    shadelab::fillRect(mask, 0, 0, image.width, image.height, {255, 255, 255, 255});
    shadelab::fillRect(mask, 10, 10, 12, 12, {0, 0, 0, 255});
    fs::create_directories(example_ / "masks");
    shadelab::writePng(mask, example_ / "masks" / "toon-spot.png");
    const Outcome masked = job();
    EXPECT_EQ(masked.exitCode, 0) << describe(masked);
}

// Each driver rasterizes its own way: softpipe (Mesa's other software rasterizer) finds no references of
// its own and is told to bless them; once blessed, it passes against them.
TEST_F(CiExample, ADriverWithoutReferencesIsToldToBlessThem) {
    const std::vector<std::string> softpipe{"GALLIUM_DRIVER=softpipe", "LIBGL_ALWAYS_SOFTWARE=1"};
    const Outcome missing = job({}, softpipe);
    ASSERT_NE(missing.out.find("driver: softpipe"), std::string::npos)
        << "softpipe was not chosen, so this test shows nothing: " << describe(missing);
    EXPECT_EQ(missing.exitCode, 2) << describe(missing);
    EXPECT_NE(missing.out.find("MISSING: phong-sphere has no reference for softpipe"), std::string::npos)
        << missing.out;

    const Outcome bless = job({"--bless"}, softpipe);
    EXPECT_EQ(bless.exitCode, 0) << describe(bless);
    EXPECT_TRUE(fs::exists(example_ / "references" / "softpipe" / "toon-spot.png"));
    const Outcome again = job({}, softpipe);
    EXPECT_EQ(again.exitCode, 0) << describe(again);
}

// A CI image or a developer's shell may export CDPATH: bash's cd then prints the folder it found through it,
// and a script that takes its own folder from `cd ... && pwd` gets the path twice. Started by a relative
// path (CDPATH applies to relative paths only), the job must still find its scenes.
TEST_F(CiExample, PassesWithCdpathExported) {
    const Outcome run = job({}, {"CDPATH=" + dir_.string()}, "ci/screenshot-regression.sh");
    EXPECT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_NE(run.out.find("pass: phong-sphere"), std::string::npos) << describe(run);
}

// A job started through a symbolic link in another folder (a CI step's bin/ of links) reads the scenes,
// references and masks beside the script itself, not beside the link.
TEST_F(CiExample, PassesWhenRunThroughASymbolicLinkInAnotherFolder) {
    const fs::path bin = dir_ / "bin";
    fs::create_directory(bin);
    fs::create_symlink(example_ / "screenshot-regression.sh", bin / "screenshot-regression");
    const Outcome run = job({}, {}, (bin / "screenshot-regression").string());
    EXPECT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_NE(run.out.find("pass: toon-spot"), std::string::npos) << describe(run);
}

TEST_F(CiExample, AnUnknownArgumentIsRefused) {
    const Outcome run = job({"--frobnicate"});
    EXPECT_EQ(run.exitCode, 2) << describe(run);
    EXPECT_NE(run.err.find("unknown argument '--frobnicate'"), std::string::npos) << run.err;
}

} // namespace
