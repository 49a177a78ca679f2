// The window's panel and help draw every character they show (src/app/shells/panel_font.h): the font atlas
// the panel builds holds a real glyph — not ImGui's fallback — for each character of the bundled lessons'
// titles and captions, the key help, the views' table and lines, and the panel's matrix text. No window and
// no GL: ImGui rasterizes the atlas on the CPU.
#include "app/shells/panel_font.h"

#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>
#include <imgui.h>

#include "app/demo/demo_state.h"
#include "app/demo/matrices_text.h"
#include "app/demo/view_explanations.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_file.h"

namespace shadelab::app {
namespace {

namespace fs = std::filesystem;

// The code points of UTF-8 `text`, decoded here on its own (not with ImGui's decoder, which maps a bad
// sequence to U+FFFD and would hide it); a malformed sequence fails the test.
std::vector<char32_t> codePoints(std::string_view text) {
    std::vector<char32_t> out;
    for (std::size_t i = 0; i < text.size();) {
        const auto lead = static_cast<unsigned char>(text[i]);
        const int length = lead < 0x80           ? 1
                           : (lead >> 5) == 0x6  ? 2
                           : (lead >> 4) == 0xE  ? 3
                           : (lead >> 3) == 0x1E ? 4
                                                 : 0;
        if (length == 0 || i + std::size_t(length) > text.size()) {
            ADD_FAILURE() << "malformed UTF-8 at byte " << i << " of: " << text;
            return out;
        }
        char32_t c = length == 1 ? lead : lead & (0x7F >> length);
        for (int k = 1; k < length; ++k) c = (c << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
        out.push_back(c);
        i += std::size_t(length);
    }
    return out;
}

std::string utf8(char32_t c) {
    std::string s;
    if (c < 0x80) {
        s += char(c);
    } else if (c < 0x800) {
        s += char(0xC0 | (c >> 6));
        s += char(0x80 | (c & 0x3F));
    } else {
        s += char(0xE0 | (c >> 12));
        s += char(0x80 | ((c >> 6) & 0x3F));
        s += char(0x80 | (c & 0x3F));
    }
    return s;
}

// Every text the panel and the help show that is not made from numbers alone, each with where it is from.
std::vector<std::pair<std::string, std::string>> shownTexts() {
    std::vector<std::pair<std::string, std::string>> texts;
    const fs::path lessons = SHADELAB_LESSONS_DIR;
    for (const auto& entry : fs::directory_iterator(lessons)) {
        if (entry.path().extension() != ".json") continue;
        const Lesson lesson = loadLesson(entry.path());
        const std::string name = entry.path().filename().string();
        texts.emplace_back(name + " title", lesson.title);
        for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
            const std::string step = name + " step " + std::to_string(i + 1);
            texts.emplace_back(step + " title", lesson.steps[i].title);
            texts.emplace_back(step + " caption", lesson.steps[i].caption);
            texts.emplace_back(step + " matrices", matricesPanelText(lesson.steps[i].scene, 0));
            texts.emplace_back(step + " what you are seeing", whatYouAreSeeing(lesson.steps[i].scene));
        }
    }
    texts.emplace_back("key help", keyHelpText());
    texts.emplace_back("views' table", viewHelpText());
    Scene scene;
    for (const ViewKind kind : {ViewKind::Scene, ViewKind::Error, ViewKind::Split, ViewKind::Profile,
                                ViewKind::Outside, ViewKind::Ndc})
        for (const ShadingMode shading : kAllShadingModes)
            for (const LightingModel lighting : kLightingModels) {
                scene.view.kind = kind;
                scene.shading = shading;
                scene.lighting = lighting;
                texts.emplace_back("what you are seeing (" + toString(scene.view) + ")",
                                   whatYouAreSeeing(scene));
            }
    const DemoState state{Scene{}};
    texts.emplace_back("status", statusText(state));
    return texts;
}

TEST(PanelFont, HoldsAGlyphForEveryCharacterThePanelShows) {
    ImFontAtlas atlas;
    ImFont* font = addPanelFont(atlas, 1.0);
    ASSERT_NE(font, nullptr);
    ASSERT_TRUE(atlas.Build());
    std::map<char32_t, std::string> missing; // the character, and the first text that shows it
    std::set<char32_t> seen;
    std::size_t lessonTexts = 0;
    for (const auto& [where, text] : shownTexts()) {
        if (where.find(".json") != std::string::npos) ++lessonTexts;
        for (const char32_t c : codePoints(text)) {
            if (c == '\n' || c == '\t') continue; // layout, not glyphs
            seen.insert(c);
            const bool held = c <= 0xFFFF && font->FindGlyphNoFallback(ImWchar(c)) != nullptr;
            if (!held) missing.emplace(c, where);
        }
    }
    EXPECT_GT(lessonTexts, 0u) << "no lesson read from " << SHADELAB_LESSONS_DIR;
    // The lecture's notation is there to be checked: the texts are not ASCII only.
    for (const char32_t c : {U'α', U'β', U'ψ', U'φ', U'ᵀ', U'⁻', U'¹', U'·', U'−', U'×', U'Σ', U'λ', U'→'})
        EXPECT_TRUE(seen.count(c)) << "no text shows " << utf8(c) << " any more: choose another to check";
    for (const auto& [c, where] : missing) {
        char code[16];
        std::snprintf(code, sizeof code, "U+%04X", unsigned(c));
        ADD_FAILURE() << "the panel's font has no glyph for " << utf8(c) << " (" << code << "), shown in "
                      << where;
    }
    std::printf("%zu distinct characters shown, %zu without a glyph; atlas %dx%d\n", seen.size(),
                missing.size(), atlas.TexWidth, atlas.TexHeight);
}

// --ui-scale rasterizes the font at its size (sharp), rather than scaling a small one up.
TEST(PanelFont, UiScaleRasterizesAtTheScaledSize) {
    ImFontAtlas small, large;
    ImFont* one = addPanelFont(small, 1.0);
    ImFont* two = addPanelFont(large, 2.0);
    ASSERT_TRUE(small.Build());
    ASSERT_TRUE(large.Build());
    EXPECT_FLOAT_EQ(one->FontSize, kPanelFontPixels);
    EXPECT_FLOAT_EQ(two->FontSize, 2 * kPanelFontPixels);
    const ImFontGlyph* a1 = one->FindGlyphNoFallback(ImWchar(U'α'));
    const ImFontGlyph* a2 = two->FindGlyphNoFallback(ImWchar(U'α'));
    ASSERT_TRUE(a1 && a2);
    // The glyph's bitmap is twice as tall, to within the rasterizer's pixel rounding.
    EXPECT_NEAR(a2->Y1 - a2->Y0, 2 * (a1->Y1 - a1->Y0), 2.0f);
}

} // namespace
} // namespace shadelab::app
