// Every help text lists every value (STYLE 5: one spelling everywhere): for each vocabulary a flag takes,
// every spelling of its one table (vocabulary.h, view.h kViewNames) appears, as a whole word, in the text
// --help prints for that flag (sceneFlags, which the command line's --help and the page's tables read).
// `--view`'s help left out outside and ndc while both were views.
#include <cctype>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_flags.h"
#include "shadelab/scene/view.h"

namespace shadelab::app {
namespace {

// `word` in `text` with no letter, digit or '-' on either side ("phong" is not found in "blinn-phong").
bool hasWord(std::string_view text, std::string_view word) {
    const auto inWord = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-'; };
    for (std::size_t at = text.find(word); at != std::string_view::npos; at = text.find(word, at + 1)) {
        const bool startsWord = at == 0 || !inWord(text[at - 1]);
        const std::size_t end = at + word.size();
        if (startsWord && (end == text.size() || !inWord(text[end]))) return true;
    }
    return false;
}

std::string helpOf(std::string_view flag) {
    for (const SceneFlag& f : sceneFlags())
        if (f.name == flag) return f.help;
    ADD_FAILURE() << "no flag --" << flag;
    return "";
}

template <class Enum, std::size_t N> std::vector<std::string> spellings(const std::array<Enum, N>& values) {
    std::vector<std::string> out;
    for (Enum value : values) out.emplace_back(toString(value));
    return out;
}

TEST(FlagHelp, ListsEveryValueOfItsVocabulary) {
    std::vector<std::string> views;
    for (const ViewName& view : kViewNames) views.emplace_back(view.name);
    const std::vector<std::pair<std::string_view, std::vector<std::string>>> flags = {
        {"shading", spellings(kAllShadingModes)},
        {"lighting", spellings(kLightingModels)},
        {"term", spellings(kLightingTerms)},
        {"perspective-matrix", spellings(kPerspectiveMatrices)},
        {"normal-matrix", spellings(kNormalMatrixRules)},
        {"depth", spellings(kDepthModes)},
        {"overlay", spellings(kOverlays)},
        {"view", views},
    };
    for (const auto& [flag, values] : flags) {
        const std::string help = helpOf(flag);
        for (const std::string& value : values)
            EXPECT_TRUE(hasWord(help, value)) << "--" << flag << ": " << value << " missing from " << help;
    }
}

// --view's help says, for each view, the key that switches it and what it shows: the row of its table.
TEST(FlagHelp, ViewHelpGivesEachViewsKeyAndLine) {
    const std::string help = helpOf("view");
    for (const ViewName& view : kViewNames) {
        EXPECT_NE(help.find(view.help), std::string::npos) << view.name << " in " << help;
        if (!view.key.empty()) {
            EXPECT_NE(help.find(std::string(view.key) + ": "), std::string::npos) << view.name;
        }
    }
}

// One row per view: no two spell a view or take a key alike.
TEST(FlagHelp, ViewTableHasOneRowPerView) {
    for (std::size_t i = 0; i < kViewNames.size(); ++i)
        for (std::size_t j = i + 1; j < kViewNames.size(); ++j) {
            EXPECT_NE(kViewNames[i].kind, kViewNames[j].kind);
            EXPECT_NE(kViewNames[i].name, kViewNames[j].name);
            if (!kViewNames[i].key.empty()) {
                EXPECT_NE(kViewNames[i].key, kViewNames[j].key);
            }
        }
}

} // namespace
} // namespace shadelab::app
