// `shadelab slides --deck` end to end (docs/lecturers.md "Lessons"): one HTML file holding every slide in
// order, each the same picture as the PNG `--out-dir` writes, the steps' notes under them as text (never
// markup), and the deck's output refused where it would replace an input or mix with the progress lines.
// Built into cli_test.
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli/run_process.h"
#include "shadelab/image/image.h"
#include "shadelab/image/image_file.h"

namespace shadelab::cli_test {
namespace {

namespace fs = std::filesystem;

constexpr const char* kLesson = R"({"title": "Shading & <more>", "steps": [
  {"title": "Flat shading", "caption": "One normal per face.", "notes": "Ask: <script>alert(1)</script> & why?\nSecond line.",
   "image": {"width": 64, "height": 48}, "objects": [{"subdivisions": 1}], "shading": "flat"},
  {"title": "Gouraud \"lit\" at the vertices", "shading": "gouraud"},
  {"title": "Phong", "caption": "Per pixel.", "notes": "Phong's notes.", "shading": "phong"}]})";

// The bytes of each `data:image/png;base64,` picture in the deck, in order.
std::vector<std::string> deckPictures(const std::string& html) {
    static const std::string kPrefix = "data:image/png;base64,";
    std::vector<std::string> pictures;
    for (std::size_t at = html.find(kPrefix); at != std::string::npos; at = html.find(kPrefix, at)) {
        at += kPrefix.size();
        std::string bytes;
        unsigned value = 0;
        int bits = 0;
        for (; at < html.size() && html[at] != '"'; ++at) {
            const char c = html[at];
            if (c == '=') continue;
            const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
            const std::size_t digit = digits.find(c);
            if (digit == std::string::npos) return {}; // not base64: the test fails on the count
            value = (value << 6) | unsigned(digit);
            bits += 6;
            if (bits >= 8) {
                bits -= 8;
                bytes += char((value >> bits) & 0xFF);
            }
        }
        pictures.push_back(bytes);
    }
    return pictures;
}

class DeckTest : public ::testing::Test {
protected:
    void SetUp() override {
        static std::atomic<int> counter{0};
        dir_ = fs::temp_directory_path() /
               ("shadelab-deck-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        fs::remove_all(dir_);
        fs::create_directory(dir_);
        writeFile(dir_ / "lesson.json", kLesson);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }
    Outcome shadelab(const std::vector<std::string>& args) const { return runShadelab(args, dir_); }
    fs::path dir_;
};

TEST_F(DeckTest, HoldsEverySlideInOrderWithItsNotesAsText) {
    const Outcome run = shadelab({"slides", "lesson.json", "--out-dir", "slides", "--deck", "deck.html"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_NE(run.out.find("wrote the deck of 3 slides: deck.html"), std::string::npos) << run.out;
    const std::string html = readFile(dir_ / "deck.html");
    const std::vector<std::string> pictures = deckPictures(html);
    const std::vector<std::string> names = {"01-flat-shading.png", "02-gouraud-lit-at-the-vertices.png",
                                            "03-phong.png"};
    ASSERT_EQ(pictures.size(), names.size()) << "one picture per step";
    for (std::size_t i = 0; i < names.size(); ++i) {
        writeFile(dir_ / "picture.png", pictures[i]);
        const Image inDeck = readPng(dir_ / "picture.png"), slide = readPng(dir_ / "slides" / names[i]);
        EXPECT_TRUE(inDeck.width == slide.width && inDeck.height == slide.height && inDeck.rgba == slide.rgba)
            << "the deck's picture " << i + 1 << " is not slide " << names[i];
    }
    // In order: the steps' titles as the pictures' descriptions, escaped.
    const std::size_t flat = html.find("alt=\"Flat shading\""),
                      gouraud = html.find("alt=\"Gouraud &quot;lit&quot; at the vertices\""),
                      phong = html.find("alt=\"Phong\"");
    EXPECT_TRUE(flat != std::string::npos && gouraud != std::string::npos && phong != std::string::npos &&
                flat < gouraud && gouraud < phong)
        << html.substr(0, 2000);
    // The notes are text: what looks like markup in them is escaped, and they sit with their own slide.
    EXPECT_EQ(html.find("<script>alert"), std::string::npos);
    const std::size_t notes =
        html.find("Ask: &lt;script&gt;alert(1)&lt;/script&gt; &amp; why?\nSecond line.");
    EXPECT_TRUE(notes != std::string::npos && flat < notes && notes < gouraud);
    const std::size_t phongNotes = html.find("Phong&#39;s notes.");
    EXPECT_TRUE(phongNotes != std::string::npos && phong < phongNotes);
    EXPECT_NE(html.find("<title>Shading &amp; &lt;more&gt;</title>"), std::string::npos);
    // Nothing is fetched from anywhere.
    EXPECT_EQ(html.find("://"), std::string::npos);
    EXPECT_EQ(html.find("src=\"//"), std::string::npos);
    EXPECT_EQ(html.find("src=\"/"), std::string::npos);
}

TEST_F(DeckTest, AloneItWritesNoPngAndItsOutputIsChecked) {
    Outcome run = shadelab({"slides", "lesson.json", "--deck", "deck.html"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_EQ(listing(dir_), (std::set<std::string>{"deck.html", "lesson.json"}));

    const std::string lesson = readFile(dir_ / "lesson.json");
    const struct {
        std::vector<std::string> args;
        std::string message;
    } refused[] = {
        {{"slides", "lesson.json"}, "give --out-dir DIR (a PNG per step), --deck FILE.html"},
        {{"slides", "lesson.json", "--deck", "deck.png"}, "--deck: \"deck.png\" is not named .html"},
        {{"slides", "lesson.json", "--deck", "-"}, "--deck: - is standard output"},
        {{"slides", "lesson.json", "--deck", "lesson.json"}, "--deck"},
    };
    for (const auto& [args, message] : refused) {
        run = shadelab(args);
        EXPECT_EQ(run.exitCode, 2) << describe(run);
        EXPECT_NE(run.err.find(message), std::string::npos) << describe(run);
        EXPECT_EQ(readFile(dir_ / "lesson.json"), lesson) << "the lesson is an input, never replaced";
    }
    EXPECT_EQ(listing(dir_), (std::set<std::string>{"deck.html", "lesson.json"})) << "nothing half-written";
}

TEST_F(DeckTest, NotesAreCheckedAsTheCaptionIs) {
    writeFile(dir_ / "long.json",
              R"({"title": "T", "steps": [{"title": "A", "notes": ")" + std::string(8001, 'x') + R"("}]})");
    const Outcome run = shadelab({"check", "long.json"});
    EXPECT_EQ(run.exitCode, 2) << describe(run);
    EXPECT_NE(run.err.find("steps[0].notes: must be at most 8000 bytes, got 8001"), std::string::npos)
        << describe(run);
}

} // namespace
} // namespace shadelab::cli_test
