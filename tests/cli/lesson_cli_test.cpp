// `shadelab check` and `shadelab slides` end to end (docs/lecturers.md "Lessons"): each slide without its
// band is what `shadelab render` makes of the step's scene, written with the scene's own flags rather than by
// the lesson code; with the band, the picture above it is that render and the band holds the text; the output
// folder follows --out's rules. Built into cli_test (one executable, one link).
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/demo/demo_state.h"
#include "cli/run_process.h"
#include "shadelab/image/image.h"
#include "shadelab/image/image_file.h"

namespace shadelab::cli_test {
namespace {

namespace fs = std::filesystem;

// Three steps: a scene file beside the lesson, then changes to it; the second step's caption wraps.
constexpr const char* kBase = R"({"image": {"width": 96, "height": 64}, "objects": [{"subdivisions": 2}]})";
constexpr const char* kLesson = R"({"title": "Shading", "steps": [
  {"title": "Flat shading", "caption": "One normal per face.", "scene": "base.json", "shading": "flat"},
  {"title": "Gouraud: lit at the vertices", "caption": "Lit at the vertices, then the colours are interpolated across the face.\nA second line.",
   "shading": "gouraud", "subdivisions": 4},
  {"title": "Phong, Blinn-Phong lighting", "caption": "", "shading": "phong", "lighting": "blinn-phong"}]})";
// The same three pictures through render's flags, with what each step keeps from the one before.
const std::vector<std::vector<std::string>> kRenderFlags = {
    {"--shading", "flat"},
    {"--shading", "gouraud", "--subdivisions", "4"},
    {"--shading", "phong", "--subdivisions", "4", "--lighting", "blinn-phong"}};
const std::vector<std::string> kSlideNames = {"01-flat-shading.png", "02-gouraud-lit-at-the-vertices.png",
                                              "03-phong-blinn-phong-lighting.png"};

class LessonCliTest : public ::testing::Test {
protected:
    void SetUp() override {
        static std::atomic<int> counter{0};
        dir_ = fs::temp_directory_path() /
               ("shadelab-lesson-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        fs::remove_all(dir_);
        fs::create_directory(dir_);
        writeFile(dir_ / "base.json", kBase);
        writeFile(dir_ / "lesson.json", kLesson);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }
    Outcome shadelab(const std::vector<std::string>& args) const { return runShadelab(args, dir_); }
    // `shadelab render base.json` with the step's flags: the picture each slide must be.
    Image rendered(std::size_t step, const std::string& size = "") const {
        std::vector<std::string> args = {"render", "base.json", "--out", "render.png"};
        args.insert(args.end(), kRenderFlags[step].begin(), kRenderFlags[step].end());
        if (!size.empty()) args.insert(args.end(), {"--size", size});
        const Outcome run = shadelab(args);
        EXPECT_EQ(run.exitCode, 0) << describe(run);
        Image image = readPng(dir_ / "render.png");
        fs::remove(dir_ / "render.png");
        return image;
    }

    fs::path dir_;
};

TEST_F(LessonCliTest, SlidesWithoutCaptionsAreTheRendersOfTheSteps) {
    const Outcome run = shadelab({"slides", "lesson.json", "--out-dir", "slides", "--no-captions"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_EQ(listing(dir_ / "slides"), std::set<std::string>(kSlideNames.begin(), kSlideNames.end()))
        << "one file per step, named in order, nothing else left";
    for (std::size_t i = 0; i < kSlideNames.size(); ++i) {
        EXPECT_NE(run.out.find("slide " + std::to_string(i + 1) + " of 3: slides/" + kSlideNames[i]),
                  std::string::npos)
            << "progress\n"
            << run.out;
        const Comparison same = compareImages(readPng(dir_ / "slides" / kSlideNames[i]), rendered(i), {});
        EXPECT_TRUE(same.passed && same.maxDelta == 0) << kSlideNames[i] << ": " << same.summary();
    }
    // Step 2 is not step 1: the comparison can fail.
    EXPECT_FALSE(compareImages(rendered(0), rendered(1), {}).passed);
}

TEST_F(LessonCliTest, CaptionBandIsAtTheBottomOverTheRender) {
    const Outcome run = shadelab({"slides", "lesson.json", "--out-dir", "slides", "--size", "320x180"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    for (std::size_t i = 0; i < kSlideNames.size(); ++i) {
        const Image slide = readPng(dir_ / "slides" / kSlideNames[i]);
        ASSERT_EQ(slide.width, 320);
        ASSERT_EQ(slide.height, 180);
        const char* titles[] = {"Flat shading", "Gouraud: lit at the vertices",
                                "Phong, Blinn-Phong lighting"};
        const std::string captions[] = {
            "One normal per face.",
            std::string("Lit at the vertices, then the colours are interpolated across the face.\n") +
                "A second line.",
            ""};
        const Image band = app::lessonBandImage(titles[i], captions[i], 320, 180);
        ASSERT_GT(band.height, 0);
        ASSERT_LE(band.height, 180 * 2 / 5) << "at most 40 % of the picture";
        const int top = 180 - band.height;
        // Above the band: the render at the largest size of its aspect there, bars beside it.
        const app::PictureRect place = app::fitPicture(320, 180, 320, top);
        const Image plain = rendered(i, std::to_string(place.width) + "x" + std::to_string(place.height));
        int differingAbove = 0, light = 0;
        for (int y = 0; y < 180; ++y)
            for (int x = 0; x < 320; ++x) {
                const std::uint8_t* s = slide.pixel(x, y);
                const bool inPicture = place.contains(x, y);
                const std::uint8_t* p = inPicture ? plain.pixel(x - place.x, y - place.y) : slide.pixel(0, 0);
                if (y < top) differingAbove += std::equal(s, s + 3, p) ? 0 : 1;
                if (y >= top && s[0] > 200 && s[1] > 200) ++light;
            }
        EXPECT_EQ(differingAbove, 0) << kSlideNames[i] << ": the picture above the band is the render";
        EXPECT_GT(light, 40) << kSlideNames[i] << ": the band's text is drawn";
    }
    // The longer caption wraps to more lines: its band is taller.
    EXPECT_GT(app::lessonBandImage(kSlideNames[1], std::string(200, 'x'), 320, 180).height,
              app::lessonBandImage(kSlideNames[1], "x", 320, 180).height);
}

TEST_F(LessonCliTest, SlidesFolderFollowsTheOutputRules) {
    // The lesson's own folder is refused, by name and through another spelling.
    for (const std::string& own : {std::string("."), dir_.string() + "/./"}) {
        const Outcome run = shadelab({"slides", "lesson.json", "--out-dir", own});
        EXPECT_EQ(run.exitCode, 2) << describe(run);
        EXPECT_NE(run.err.find("--out-dir"), std::string::npos) << run.err;
        EXPECT_NE(run.err.find("the lesson's own folder"), std::string::npos) << run.err;
    }
    // A folder where a slide would go: refused before anything is drawn, nothing written.
    fs::create_directories(dir_ / "slides" / kSlideNames[1]);
    const Outcome blocked = shadelab({"slides", "lesson.json", "--out-dir", "slides"});
    EXPECT_EQ(blocked.exitCode, 2) << describe(blocked);
    EXPECT_NE(blocked.err.find(kSlideNames[1]), std::string::npos) << blocked.err;
    EXPECT_EQ(listing(dir_ / "slides"), std::set<std::string>{kSlideNames[1] + "/"});
    // An existing slide is replaced, a missing folder made with its parents.
    fs::remove(dir_ / "slides" / kSlideNames[1]);
    writeFile(dir_ / "slides" / kSlideNames[0], "old");
    const Outcome replaced = shadelab({"slides", "lesson.json", "--out-dir", "slides"});
    ASSERT_EQ(replaced.exitCode, 0) << describe(replaced);
    EXPECT_NE(readFile(dir_ / "slides" / kSlideNames[0]), "old");
    const Outcome made = shadelab({"slides", "lesson.json", "--out-dir", "a/b"});
    ASSERT_EQ(made.exitCode, 0) << describe(made);
    EXPECT_EQ(listing(dir_ / "a" / "b").size(), 3u);
    // A bad lesson: the JSON path named, no folder made.
    writeFile(dir_ / "bad.json", R"({"title": "t", "steps": [{"title": "t", "shading": "glossy"}]})");
    const Outcome bad = shadelab({"slides", "bad.json", "--out-dir", "never"});
    EXPECT_EQ(bad.exitCode, 2) << describe(bad);
    EXPECT_NE(bad.err.find("bad.json: steps[0]: shading: unknown value \"glossy\""), std::string::npos)
        << bad.err;
    EXPECT_FALSE(fs::exists(dir_ / "never"));
    const Outcome size = shadelab({"slides", "lesson.json", "--out-dir", "s", "--size", "0x9"});
    EXPECT_EQ(size.exitCode, 2) << describe(size);
    EXPECT_NE(size.err.find("--size"), std::string::npos) << size.err;
}

TEST_F(LessonCliTest, CheckSaysWhatAFileIsAndDrawsNothing) {
    writeFile(dir_ / "missing.json", R"({"title": "t", "steps": [{"title": "a", "scene": "gone.json"}]})");
    writeFile(dir_ / "patch.json", "");
    const std::set<std::string> before = listing(dir_);
    const Outcome lesson = shadelab({"check", "lesson.json"});
    EXPECT_EQ(lesson.exitCode, 0) << describe(lesson);
    EXPECT_NE(lesson.out.find("a lesson, valid: \"Shading\", 3 steps"), std::string::npos) << lesson.out;
    EXPECT_NE(lesson.out.find("3. Phong, Blinn-Phong lighting"), std::string::npos) << lesson.out;
    // A step that patches objects says which.
    writeFile(dir_ / "patch.json",
              R"({"title": "P", "steps": [{"title": "Three", "scene": {"objects": [{}, {}, {}]}},
        {"title": "Shiny", "objects": {"1": {"material": {"shininess": 200}}}}]})");
    const Outcome patch = shadelab({"check", "patch.json"});
    EXPECT_EQ(patch.exitCode, 0) << describe(patch);
    EXPECT_NE(patch.out.find("  1. Three\n  2. Shiny (changes objects[1])\n"), std::string::npos)
        << patch.out;
    const Outcome scene = shadelab({"check", "base.json"});
    EXPECT_EQ(scene.exitCode, 0) << describe(scene);
    EXPECT_NE(scene.out.find("a scene, valid"), std::string::npos) << scene.out;
    const Outcome missing = shadelab({"check", "missing.json"});
    EXPECT_EQ(missing.exitCode, 2) << describe(missing);
    EXPECT_NE(missing.err.find("missing.json: steps[0].scene"), std::string::npos) << missing.err;
    EXPECT_NE(missing.err.find("gone.json"), std::string::npos) << missing.err;
    // A lesson where a scene is expected says which commands take it.
    const Outcome render = shadelab({"render", "lesson.json", "--out", "x.png"});
    EXPECT_EQ(render.exitCode, 2) << describe(render);
    EXPECT_NE(render.err.find("a lesson"), std::string::npos) << render.err;
    EXPECT_NE(render.err.find("shadelab slides"), std::string::npos) << render.err;
    EXPECT_EQ(listing(dir_), before) << "check and a refused render write nothing";
}

} // namespace
} // namespace shadelab::cli_test
