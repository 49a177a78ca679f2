// The worked example of docs/ci-engineers.md "Screenshot regression in your CI" (examples/ci/), run as a CI
// job runs it: on a copy of the example, against the shadelab under test. It passes as committed; a changed
// reference fails with the actual, expected and difference images, the page and the JSON pointing at them in
// the artifacts folder; a mask over the change passes; a driver without references has every scene NEW with
// its render kept; the expectations file's FAIL, SKIP and FLAKY decide through the job; --bless NAME and
// --bless-failed write only what they name; a reference whose scene is gone is reported; --junit is written.
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
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
using nlohmann::json;

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

    fs::path reference(const std::string& name, const std::string& driver = "llvmpipe") const {
        return example_ / "references" / driver / (name + ".png");
    }
    // A 12x12 magenta block at (10, 10) in a reference: 144 pixels beyond every per-channel limit.
    void changeReference(const std::string& name) const {
        shadelab::Image image = shadelab::readPng(reference(name));
        shadelab::fillRect(image, 10, 10, 12, 12, {255, 0, 255, 255});
        shadelab::writePng(image, reference(name));
    }
    void writeExpectations(const std::string& rules) const {
        writeFile(example_ / "expectations.txt", rules);
    }

    json reviewJson() const { return json::parse(readFile(artifacts_ / "review.json")); }
    // The case `name` of review.json, or null.
    json caseOf(const json& report, const std::string& name) const {
        for (const json& c : report.at("cases"))
            if (c.at("name") == name) return c;
        return nullptr;
    }
    std::string statusOf(const std::string& name) const {
        const json c = caseOf(reviewJson(), name);
        return c.is_null() ? "(no case)" : c.at("status").get<std::string>();
    }

    fs::path dir_, example_, artifacts_;
};

// Every string in `value` that names a PNG, wherever it sits in the case's object.
void collectPngPaths(const json& value, std::vector<std::string>& paths) {
    if (value.is_string()) {
        const std::string text = value.get<std::string>();
        if (text.size() > 4 && text.compare(text.size() - 4, 4, ".png") == 0) paths.push_back(text);
    } else if (value.is_structured()) {
        for (const json& item : value) collectPngPaths(item, paths);
    }
}

TEST_F(CiExample, PassesAsCommittedWithThePageTheJsonAndTheJUnit) {
    const Outcome run = job({"--junit", (dir_ / "junit.xml").string()});
    EXPECT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_NE(run.out.find("driver: llvmpipe"), std::string::npos) << run.out;
    EXPECT_EQ(statusOf("phong-sphere"), "pass");
    EXPECT_EQ(statusOf("toon-spot"), "pass");
    EXPECT_TRUE(fs::is_regular_file(artifacts_ / "review" / "index.html"));
    const std::string junit = readFile(dir_ / "junit.xml");
    EXPECT_NE(junit.find("name=\"phong-sphere\""), std::string::npos) << junit;
    EXPECT_NE(junit.find("name=\"toon-spot\""), std::string::npos) << junit;
    EXPECT_EQ(junit.find("<failure"), std::string::npos) << junit;
}

TEST_F(CiExample, AChangedReferenceFailsWithItsArtifactsAndAMaskOverTheChangePasses) {
    changeReference("toon-spot");
    fs::create_directories(artifacts_);
    writeFile(artifacts_ / "notes.txt", "the user's own file");

    const Outcome failed = job({"--junit", (dir_ / "junit.xml").string()});
    EXPECT_EQ(failed.exitCode, 1) << describe(failed);
    EXPECT_EQ(statusOf("phong-sphere"), "pass");
    EXPECT_EQ(statusOf("toon-spot"), "FAIL");
    EXPECT_EQ(readFile(artifacts_ / "notes.txt"), "the user's own file");
    EXPECT_NE(readFile(dir_ / "junit.xml").find("<failure"), std::string::npos);
    const std::string page = readFile(artifacts_ / "review" / "index.html");
    EXPECT_NE(page.find("toon-spot"), std::string::npos);

    // The JSON points at the actual, expected and difference images, and each of them is there to upload
    // (relative paths are from the JSON's folder or the page's).
    std::vector<std::string> paths;
    collectPngPaths(caseOf(reviewJson(), "toon-spot"), paths);
    EXPECT_GE(paths.size(), 3u) << reviewJson().dump(2);
    for (const std::string& path : paths) {
        const fs::path p(path);
        EXPECT_TRUE(p.is_absolute() ? fs::exists(p)
                                    : fs::exists(artifacts_ / p) || fs::exists(artifacts_ / "review" / p))
            << path;
    }
    const fs::path expectedCopy =
        artifacts_ / "review" /
        caseOf(reviewJson(), "toon-spot").at("files").at("expected").get<std::string>();
    EXPECT_EQ(readFile(expectedCopy), readFile(reference("toon-spot")))
        << "the expected image is the reference";

    shadelab::Image mask(160, 120);
    shadelab::fillRect(mask, 0, 0, 160, 120, {255, 255, 255, 255});
    shadelab::fillRect(mask, 10, 10, 12, 12, {0, 0, 0, 255});
    fs::create_directories(example_ / "masks");
    shadelab::writePng(mask, example_ / "masks" / "toon-spot.png");
    const Outcome masked = job();
    EXPECT_EQ(masked.exitCode, 0) << describe(masked);
}

// Each driver rasterizes its own way: softpipe (Mesa's other software rasterizer) finds no references of its
// own, so every scene is NEW with its render kept; --bless-failed writes them and names each one.
TEST_F(CiExample, ADriverWithoutReferencesHasEveryRenderKeptAsNew) {
    const std::vector<std::string> softpipe{"GALLIUM_DRIVER=softpipe", "LIBGL_ALWAYS_SOFTWARE=1"};
    const Outcome fresh = job({}, softpipe);
    ASSERT_NE(fresh.out.find("driver: softpipe"), std::string::npos)
        << "softpipe was not chosen, so this test shows nothing: " << describe(fresh);
    EXPECT_EQ(fresh.exitCode, 1) << describe(fresh);
    EXPECT_EQ(statusOf("phong-sphere"), "NEW");
    EXPECT_TRUE(fs::is_regular_file(artifacts_ / "renders" / "phong-sphere.png")) << "the render to bless";
    EXPECT_FALSE(fs::exists(example_ / "references" / "softpipe"))
        << "a run that blesses nothing writes nothing";

    const Outcome bless = job({"--bless-failed"}, softpipe);
    EXPECT_NE(bless.out.find("phong-sphere -> "), std::string::npos) << describe(bless);
    EXPECT_NE(bless.out.find("toon-spot -> "), std::string::npos) << describe(bless);
    EXPECT_EQ(readFile(reference("toon-spot", "softpipe")),
              readFile(artifacts_ / "renders" / "toon-spot.png"));
    const Outcome again = job({}, softpipe);
    EXPECT_EQ(again.exitCode, 0) << describe(again);
}

// --bless NAME writes that scene's render and nothing else.
TEST_F(CiExample, BlessNameWritesOnlyThatScene) {
    changeReference("toon-spot");
    changeReference("phong-sphere");
    const std::string phongBefore = readFile(reference("phong-sphere"));
    const Outcome bless = job({"--bless", "toon-spot"});
    EXPECT_NE(bless.out.find("toon-spot -> "), std::string::npos) << describe(bless);
    EXPECT_EQ(bless.out.find("phong-sphere -> "), std::string::npos) << describe(bless);
    EXPECT_EQ(readFile(reference("phong-sphere")), phongBefore);
    EXPECT_EQ(readFile(reference("toon-spot")), readFile(artifacts_ / "renders" / "toon-spot.png"));

    const Outcome after = job();
    EXPECT_EQ(after.exitCode, 1) << describe(after);
    EXPECT_EQ(statusOf("toon-spot"), "pass");
    EXPECT_EQ(statusOf("phong-sphere"), "FAIL");
}

// --bless-failed writes the failed scenes only: phong-sphere's reference, one channel of one pixel off
// (within the tolerance), passes and is not rewritten.
TEST_F(CiExample, BlessFailedWritesOnlyWhatFailed) {
    changeReference("toon-spot");
    shadelab::Image phong = shadelab::readPng(reference("phong-sphere"));
    phong.pixel(80, 60)[0] = std::uint8_t(phong.pixel(80, 60)[0] ^ 1);
    shadelab::writePng(phong, reference("phong-sphere"));
    const std::string phongBefore = readFile(reference("phong-sphere"));

    const Outcome bless = job({"--bless-failed"});
    EXPECT_NE(bless.out.find("toon-spot -> "), std::string::npos) << describe(bless);
    EXPECT_EQ(bless.out.find("phong-sphere -> "), std::string::npos) << describe(bless);
    EXPECT_EQ(readFile(reference("phong-sphere")), phongBefore) << "a passing scene is not rewritten";
    const Outcome after = job();
    EXPECT_EQ(after.exitCode, 0) << describe(after);
}

TEST_F(CiExample, TheExpectationsFileDecidesKnownFailuresThroughTheJob) {
    changeReference("toon-spot");
    struct Row {
        const char* rules;
        int exitCode;
        const char* status;
    };
    const Row rows[] = {
        {"toon-spot  llvm*  FAIL  # https://example.org/1\n", 0, "expected-fail"},
        {"toon-*  *  FLAKY  # https://example.org/2\n", 0, "flaky-fail"},
        {"toon-spot  llvmpipe  SKIP  # no reason to compare\n", 0, "skip"},
        {"toon-spot  softpipe  FAIL  # another driver's rule\n", 1, "FAIL"},
    };
    for (const Row& row : rows) {
        writeExpectations(row.rules);
        const Outcome run = job();
        EXPECT_EQ(run.exitCode, row.exitCode) << row.rules << describe(run);
        EXPECT_EQ(statusOf("toon-spot"), row.status) << row.rules;
    }
    // A FAIL rule on a scene that passes fails the job, so that the rule goes with the fix.
    writeExpectations("phong-sphere  *  FAIL  # fixed since\n");
    const Outcome unexpected = job();
    EXPECT_EQ(unexpected.exitCode, 1) << describe(unexpected);
    EXPECT_EQ(statusOf("phong-sphere"), "unexpected-pass");
}

// A reference whose scene was deleted is reported, not left silently.
TEST_F(CiExample, AReferenceWithNoSceneIsReportedStale) {
    fs::copy_file(reference("toon-spot"), reference("gone"));
    const Outcome run = job();
    EXPECT_EQ(run.exitCode, 1) << describe(run);
    EXPECT_EQ(statusOf("gone"), "STALE");
    EXPECT_NE(run.out.find("gone"), std::string::npos) << run.out;
}

// A scene's name is data: spaces, quotes and $(...) reach the program as they are.
TEST_F(CiExample, AHostileSceneNameIsOnlyAName) {
    const std::string name = "it's a $(touch pwned) `x`";
    fs::copy_file(example_ / "scenes" / "toon-spot.json", example_ / "scenes" / (name + ".json"));
    fs::copy_file(reference("toon-spot"), reference(name));
    const Outcome run = job();
    EXPECT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_EQ(statusOf(name), "pass");
    EXPECT_FALSE(fs::exists(dir_ / "pwned"));
}

// The GitLab and GitHub jobs run the same script with the same arguments: the one this project's CI runs.
TEST_F(CiExample, TheGitLabAndGitHubJobsRunTheSameScriptLine) {
    const std::regex scriptLine(R"((?:run: |- )(examples/ci/screenshot-regression\.sh[^\n]*))");
    std::smatch gitlab, github;
    const std::string gitlabText = readFile(example_ / "gitlab-ci.yml");
    const std::string githubText = readFile(example_ / "github-actions.yml");
    ASSERT_TRUE(std::regex_search(gitlabText, gitlab, scriptLine));
    ASSERT_TRUE(std::regex_search(githubText, github, scriptLine));
    EXPECT_EQ(gitlab[1].str(), github[1].str());
    for (const std::string& text : {gitlabText, githubText}) {
        EXPECT_NE(text.find("fetch -q --depth 1 \"$SHADELAB_GIT\" \"$SHADELAB_COMMIT\""), std::string::npos)
            << "the job pins a commit (git clone --branch takes none)";
        EXPECT_FALSE(std::regex_search(text, std::regex(R"((^|\n)\s*(- )?git clone)")))
            << "no clone by branch";
    }
}

// A CI image or a developer's shell may export CDPATH: bash's cd then prints the folder it found through it,
// and a script that takes its own folder from `cd ... && pwd` gets the path twice. Started by a relative
// path (CDPATH applies to relative paths only), the job must still find its scenes.
TEST_F(CiExample, PassesWithCdpathExported) {
    const Outcome run = job({}, {"CDPATH=" + dir_.string()}, "ci/screenshot-regression.sh");
    EXPECT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_EQ(statusOf("phong-sphere"), "pass");
}

// A job started through a symbolic link in another folder (a CI step's bin/ of links) reads the scenes,
// references and masks beside the script itself, not beside the link.
TEST_F(CiExample, PassesWhenRunThroughASymbolicLinkInAnotherFolder) {
    const fs::path bin = dir_ / "bin";
    fs::create_directory(bin);
    fs::create_symlink(example_ / "screenshot-regression.sh", bin / "screenshot-regression");
    const Outcome run = job({}, {}, (bin / "screenshot-regression").string());
    EXPECT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_EQ(statusOf("toon-spot"), "pass");
}

TEST_F(CiExample, BadArgumentsAreRefused) {
    const Outcome unknown = job({"--frobnicate"});
    EXPECT_EQ(unknown.exitCode, 2) << describe(unknown);
    EXPECT_NE(unknown.err.find("unknown argument '--frobnicate'"), std::string::npos) << unknown.err;
    const Outcome bare = job({"--bless"});
    EXPECT_EQ(bare.exitCode, 2) << describe(bare);
    EXPECT_NE(bare.err.find("--bless needs a value"), std::string::npos) << bare.err;
}

} // namespace
