// Lessons, slides and text outputs under hostile input, end to end (docs/lecturers.md "Lessons", "Output
// files"): what sits in --out-dir under a slide's name (a step's scene, a link, a FIFO, a folder), a step
// that names standard input, outputs that are standard output under another name, and `check` refusing
// exactly what the drawing commands refuse, naming the lesson, the step and its file. Every case states its
// exit code, what the message names, and that nothing was written or replaced. Built into cli_test.
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/run_process.h"

namespace shadelab::cli_test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScene = R"({"image": {"width": 48, "height": 32}, "objects": [{"subdivisions": 1}]})";

class LessonHostileTest : public ::testing::Test {
protected:
    void SetUp() override {
        static std::atomic<int> counter{0};
        dir_ = fs::temp_directory_path() /
               ("shadelab-lesson-hostile-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "lesson");
        fs::create_directories(dir_ / "out");
        writeFile(dir_ / "lesson" / "base.json", kScene);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }
    // lesson/lesson.json: one step "Intro" (slide 01-intro.png) on `scene`, then a second step.
    void writeLesson(const std::string& scene) const {
        writeFile(dir_ / "lesson" / "lesson.json",
                  R"({"title": "T", "steps": [{"title": "Intro", "scene": ")" + scene +
                      R"("}, {"title": "Second", "shading": "flat"}]})");
    }
    Outcome shadelab(const std::vector<std::string>& args, RunOptions options = {}) const {
        options.environment = childEnvironment(Display::Inherit);
        return runWith(args, dir_, options);
    }
    Outcome slides() const { return shadelab({"slides", "lesson/lesson.json", "--out-dir", "out"}); }

    fs::path dir_;
};

void expectRefused(const Outcome& run, const std::vector<std::string>& named) {
    EXPECT_EQ(run.exitCode, 2) << describe(run);
    for (const std::string& text : named)
        EXPECT_NE(run.err.find(text), std::string::npos) << text << "\n" << run.err;
}

// A step's scene file is an input like the lesson: a slide named like it never replaces it.
TEST_F(LessonHostileTest, SlidesNeverReplaceAStepsSceneFile) {
    writeFile(dir_ / "out" / "01-intro.png", kScene); // a scene file that happens to carry a slide's name
    writeLesson("../out/01-intro.png");
    expectRefused(slides(), {"--out-dir", "01-intro.png", "is the input file", "choose another output path"});
    EXPECT_EQ(readFile(dir_ / "out" / "01-intro.png"), kScene);
    EXPECT_EQ(listing(dir_ / "out"), std::set<std::string>{"01-intro.png"}) << "no slide drawn, nothing left";
}

// A slide is created inside --out-dir and replaces only a regular file there: a link under a slide's name is
// never followed, whether to a step's scene, a file outside the folder or /dev/null.
TEST_F(LessonHostileTest, SlidesNeverWriteThroughALinkInTheFolder) {
    writeLesson("base.json");
    writeFile(dir_ / "outside.txt", "keep me");
    for (const fs::path& target :
         {dir_ / "lesson" / "base.json", dir_ / "outside.txt", fs::path("/dev/null")}) {
        fs::remove_all(dir_ / "out");
        fs::create_directories(dir_ / "out");
        fs::create_symlink(target, dir_ / "out" / "02-second.png");
        expectRefused(slides(), {"--out-dir", "02-second.png", "is a symbolic link", "never through a link"});
        EXPECT_TRUE(fs::is_symlink(dir_ / "out" / "02-second.png")) << target;
        EXPECT_FALSE(fs::exists(dir_ / "out" / "01-intro.png")) << "refused before the first slide";
    }
    EXPECT_EQ(readFile(dir_ / "lesson" / "base.json"), kScene);
    EXPECT_EQ(readFile(dir_ / "outside.txt"), "keep me");
    // A regular file there is the one thing replaced.
    fs::remove(dir_ / "out" / "02-second.png");
    writeFile(dir_ / "out" / "02-second.png", "old slide");
    const Outcome replaced = slides();
    ASSERT_EQ(replaced.exitCode, 0) << describe(replaced);
    EXPECT_NE(readFile(dir_ / "out" / "02-second.png"), "old slide");
}

// Nothing waits without a deadline: a FIFO under a slide's name and a step naming standard input are refused
// before any work (runWith's timeout fails a hang), with stdin open and holding a valid scene.
TEST_F(LessonHostileTest, AFifoSlideAndAStandardInputStepAreRefusedAtOnce) {
    writeLesson("base.json");
    ASSERT_EQ(::mkfifo((dir_ / "out" / "01-intro.png").c_str(), 0600), 0);
    RunOptions quick;
    quick.timeout = std::chrono::seconds(20);
    expectRefused(shadelab({"slides", "lesson/lesson.json", "--out-dir", "out"}, quick),
                  {"--out-dir", "01-intro.png", "is a FIFO", "remove"});
    writeLesson("-");
    RunOptions withStdin = quick;
    withStdin.stdinText = kScene;
    for (const std::string command : {"check", "slides"}) {
        std::vector<std::string> args = {command, "lesson/lesson.json"};
        if (command == "slides") args.insert(args.end(), {"--out-dir", "elsewhere"});
        expectRefused(shadelab(args, withStdin),
                      {"lesson/lesson.json: steps[0].scene: must name a scene file relative to the lesson's "
                       "folder, got \"-\""});
    }
    EXPECT_FALSE(fs::exists(dir_ / "elsewhere"));
}

// `check` runs every check the drawing commands run: a lesson `check` calls valid draws, and what `render`
// refuses `check` refuses too, each message naming the lesson, the step and its scene file. `slides` refuses
// before the first slide, not half-way.
TEST_F(LessonHostileTest, CheckRefusesWhatRenderRefusesNamingLessonStepAndFile) {
    std::string budget = R"({"objects": [)";
    for (int i = 0; i < 17; ++i) budget += std::string(i ? "," : "") + R"({"subdivisions": 10})";
    const std::pair<std::string, std::string> cases[] = {
        {R"({"view": "outside", "lights": [{"type": "point", "position": [0, 0, -9e29]}]})",
         "view: the outside view"},
        {budget + "]}", "objects: the scene draws 71303168 triangles per frame"},
        {R"({"projection": {"near": 1e-10, "far": 10}})", "projection.near: with \"depth\": \"standard\""}};
    for (const auto& [scene, refusal] : cases) {
        writeFile(dir_ / "lesson" / "bad.json", scene);
        const Outcome render = shadelab({"render", "lesson/bad.json", "--out", "render.png"});
        expectRefused(render, {refusal});
        expectRefused(shadelab({"check", "lesson/bad.json"}), {"lesson/bad.json: " + refusal});
        writeFile(dir_ / "lesson" / "lesson.json",
                  R"({"title": "T", "steps": [{"title": "Fine", "scene": "base.json"},
                      {"title": "Far", "scene": "bad.json"}]})");
        const std::string where = R"(lesson/lesson.json: steps[1] ("Far", scene file "bad.json"): )";
        expectRefused(shadelab({"check", "lesson/lesson.json"}), {where + refusal});
        expectRefused(slides(), {where + refusal});
        EXPECT_TRUE(listing(dir_ / "out").empty()) << "no slide before the refusal";
    }
    EXPECT_FALSE(fs::exists(dir_ / "render.png"));
}

// Text on standard output and a PNG never share it, under any name for it.
TEST_F(LessonHostileTest, OutputsThatAreStandardOutputUnderAnotherNameAreRefused) {
    writeFile(dir_ / "a.png", "");
    const Outcome made = shadelab({"render", "lesson/base.json", "--out", "a.png"});
    ASSERT_EQ(made.exitCode, 0) << describe(made);
    for (const std::string alias : {"/dev/stdout", "/dev/fd/1", "/proc/self/fd/1"}) {
        const Outcome render = shadelab({"render", "lesson/base.json", "--print-matrices", "--out", alias});
        expectRefused(render, {"--out: \"" + alias + "\" is standard output", "--print-matrices"});
        EXPECT_EQ(render.out, "") << "nothing printed before the refusal";
        const Outcome compare = shadelab({"compare", "a.png", "a.png", "--json", "--diff", alias});
        expectRefused(compare, {"--diff: \"" + alias + "\" is standard output", "the JSON of --json"});
        EXPECT_EQ(compare.out, "");
    }
    // The file standard output is redirected to is standard output too.
    writeFile(dir_ / "matrices.txt", "");
    RunOptions redirected;
    redirected.stdoutPath = dir_ / "matrices.txt";
    expectRefused(
        shadelab({"render", "lesson/base.json", "--print-matrices", "--out", "matrices.txt"}, redirected),
        {"is standard output"});
    // Standard output appended to the scene itself (`--out - >> base.json`) would write the PNG into it.
    RunOptions ontoScene;
    ontoScene.stdoutPath = dir_ / "lesson" / "base.json";
    ontoScene.stdoutAppends = true;
    for (const std::string out : {"-", "/dev/stdout"})
        expectRefused(shadelab({"render", "lesson/base.json", "--out", out}, ontoScene),
                      {"is the input file \"lesson/base.json\"; writing it would destroy the input"});
    EXPECT_EQ(readFile(dir_ / "lesson" / "base.json"), kScene);
    // /dev/null takes both and loses nothing; a plain file is fine.
    EXPECT_EQ(shadelab({"render", "lesson/base.json", "--print-matrices", "--out", "/dev/null"}).exitCode, 0);
    EXPECT_EQ(shadelab({"render", "lesson/base.json", "--print-matrices", "--out", "m.png"}).exitCode, 0);
}

// A scene given to slides, a folder under a slide's name, text with hidden characters and glyphs the band's
// font lacks: each said in words that fit.
TEST_F(LessonHostileTest, SlidesMessagesSayWhatIsWrongAndWhatFits) {
    expectRefused(shadelab({"slides", "lesson/base.json", "--out-dir", "out"}),
                  {"lesson/base.json: a scene, not a lesson", "shadelab render"});
    writeLesson("base.json");
    fs::create_directories(dir_ / "out" / "01-intro.png");
    const Outcome folder = slides();
    expectRefused(folder, {"--out-dir: \"out/01-intro.png\" is a folder", "give another folder"});
    EXPECT_EQ(folder.err.find("--out FILE"), std::string::npos) << "--out's advice: " << folder.err;
    // U+202E in a title would reorder the terminal's line of `check`.
    writeFile(dir_ / "lesson" / "lesson.json", R"({"title": "T", "steps": [{"title": "a\u202eb"}]})");
    const Outcome bidi = shadelab({"check", "lesson/lesson.json"});
    expectRefused(bidi, {"steps[0].title: must be printable text", "U+202E"});
    EXPECT_EQ(bidi.err.find("\u202e"), std::string::npos) << "the character itself never reaches a terminal";
    // Letters the font has no glyph for are drawn as boxes: said, not refused.
    writeFile(dir_ / "lesson" / "lesson.json", R"({"title": "T", "steps": [{"title": "中文 ok"}]})");
    const Outcome glyphs = shadelab({"check", "lesson/lesson.json"});
    EXPECT_EQ(glyphs.exitCode, 0) << describe(glyphs);
    EXPECT_NE(glyphs.out.find("warning: steps[0].title: the band's font (DejaVu Sans Mono Bold) has no glyph "
                              "for U+4E2D, U+6587; each is drawn as a box"),
              std::string::npos)
        << glyphs.out;
}

} // namespace
} // namespace shadelab::cli_test
