// One way in for every value (shadelab/scene/scene_values.h): each bad value goes through both doors —
// a scene file (parseScene) and the flag that sets the same value (applyOverrides, which the command line,
// the demo and the page share) — and both must refuse it with the same words after the field's name. The
// expected texts come from DESIGN §4's ranges, not from scene_check.cpp.
#include "shadelab/scene/scene_flags.h"

#include <functional>
#include <optional>
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "input_error.h"
#include "shadelab/errors.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_values.h"

namespace shadelab::app {
namespace {

struct BadValue {
    const char* name;
    const char* scene;      // a scene file holding the value
    const char* sceneField; // its JSON path
    std::optional<std::string> SceneOverrides::*flag;
    const char* flagText;  // the same value as the flag's text
    const char* flagField; // how the flag's message names it
    const char* refusal;   // what both messages say after "<field>: " (a part of it, for the long ones)
};

std::ostream& operator<<(std::ostream& out, const BadValue& v) {
    return out << v.name;
}

const BadValue kBadValues[] = {
    {"WidthZero", R"({"image": {"width": 0}})", "image.width", &SceneOverrides::size, "0x10", "--size width",
     "must be between 1 and 16384, got 0"},
    {"WidthTooLarge", R"({"image": {"width": 20000}})", "image.width", &SceneOverrides::size, "20000x20000",
     "--size width", "must be between 1 and 16384, got 20000"},
    {"HeightTooLarge", R"({"image": {"height": 16385}})", "image.height", &SceneOverrides::size, "64x16385",
     "--size height", "must be between 1 and 16384, got 16385"},
    {"SubdivisionsNegative", R"({"objects": [{"subdivisions": -1}]})", "objects[0].subdivisions",
     &SceneOverrides::subdivisions, "-1", "--subdivisions", "must be between 0 and 10, got -1"},
    {"SubdivisionsAboveMaximum", R"({"objects": [{"subdivisions": 11}]})", "objects[0].subdivisions",
     &SceneOverrides::subdivisions, "11", "--subdivisions", "level 11 would need about "},
    {"SubdivisionsHuge", R"({"objects": [{"subdivisions": 999999999}]})", "objects[0].subdivisions",
     &SceneOverrides::subdivisions, "999999999", "--subdivisions", "the maximum supported level is 10"},
    {"ToleranceZero", R"({"tolerance_px": 0})", "tolerance_px", &SceneOverrides::tolerancePx, "0",
     "--tolerance-px", "must be > 0, got 0"},
    {"ToleranceNegative", R"({"tolerance_px": -0.5})", "tolerance_px", &SceneOverrides::tolerancePx, "-0.5",
     "--tolerance-px", "must be > 0, got -0.5"},
    {"ToleranceUnderflowsToZero", R"({"tolerance_px": 1e-400})", "tolerance_px", &SceneOverrides::tolerancePx,
     "1e-400", "--tolerance-px", "must be > 0, got 0"},
    {"ToleranceOverflows", R"({"tolerance_px": 1e400})", "tolerance_px", &SceneOverrides::tolerancePx,
     "1e400", "--tolerance-px", "must be finite, got 1e400"},
    {"ViewOneSidedSplit", R"({"view": "split:phong"})", "view", &SceneOverrides::view, "split:phong",
     "--view", "\"split:phong\": a split names two sides"},
    {"ViewControlCharacter", R"({"view": "sce\u001bne"})", "view", &SceneOverrides::view, "sce\x1bne",
     "--view",
     "\"sce\\u001bne\": expected scene, error, profile, outside, ndc, split:A,B or side-by-side:A,B"},
    {"ViewLong", R"({"view": "scenescenescenescenescenescenescenescenescene"})", "view",
     &SceneOverrides::view, "scenescenescenescenescenescenescenescenescene", "--view",
     "\"scenescenescenescenescenescenescenescene...\""},
};

std::string refusal(const std::function<void()>& attempt) {
    const std::string message = test::inputErrorOf(attempt);
    return message.empty() ? "accepted" : message;
}

class BothDoors : public ::testing::TestWithParam<BadValue> {};

TEST_P(BothDoors, RefuseTheValueInTheSameWords) {
    const BadValue& v = GetParam();
    const std::string fromFile = refusal([&] { parseScene(v.scene, "s.json"); });
    SceneOverrides o;
    o.*v.flag = v.flagText;
    const std::string fromFlag = refusal([&] { applyOverrides(Scene{}, o, ""); });

    const std::string filePrefix = "s.json: " + std::string(v.sceneField) + ": ";
    const std::string flagPrefix = std::string(v.flagField) + ": ";
    ASSERT_EQ(fromFile.substr(0, filePrefix.size()), filePrefix) << fromFile;
    ASSERT_EQ(fromFlag.substr(0, flagPrefix.size()), flagPrefix) << fromFlag;
    const std::string fileRest = fromFile.substr(filePrefix.size()),
                      flagRest = fromFlag.substr(flagPrefix.size());
    EXPECT_EQ(fileRest, flagRest);
    EXPECT_NE(fileRest.find(v.refusal), std::string::npos) << fileRest;
    EXPECT_EQ(fromFlag.find('\x1b'), std::string::npos) << "a control character reached the message";
}

INSTANTIATE_TEST_SUITE_P(OneDoorPerValue, BothDoors, ::testing::ValuesIn(kBadValues),
                         [](const ::testing::TestParamInfo<BadValue>& info) { return info.param.name; });

// A scene built in code (or changed by the demo) meets the same checks through validateScene.
TEST(OneDoorPerValue, ValidateSceneUsesTheSameChecks) {
    Scene scene;
    scene.tolerancePx = 0;
    EXPECT_EQ(refusal([&] { validateScene(scene); }), "tolerance_px: must be > 0, got 0");
    scene = Scene{};
    scene.objects[0].subdivisions = -2; // not the auto sentinel
    EXPECT_EQ(refusal([&] { validateScene(scene); }),
              "objects[0].subdivisions: must be between 0 and 10, got -2");
    scene = Scene{};
    scene.height = 0;
    EXPECT_EQ(refusal([&] { validateScene(scene); }), "image.height: must be between 1 and 16384, got 0");
}

// The flags keep their own syntax: what is not a number of the right form is refused by the flag, naming the
// range it takes from the shared one.
TEST(OneDoorPerValue, FlagSyntaxQuotesTheSharedRange) {
    SceneOverrides size;
    size.size = "abc";
    EXPECT_EQ(refusal([&] { applyOverrides(Scene{}, size, ""); }), "--size: expected WxH with W and H in " +
                                                                       toString(kImageSizeRange) +
                                                                       " (e.g. 512x512), got \"abc\"");
    for (const char* bad :
         {"512x", "x512", "+5x5", " 5x5", "5x5 ", "5x5x5", "1e3x5", "5X5", "1234567890x5", "-5x5"}) {
        size.size = bad;
        EXPECT_NE(refusal([&] { applyOverrides(Scene{}, size, ""); }).find("--size: expected WxH"),
                  std::string::npos)
            << bad;
    }
    size.size = "640x48";
    const Scene sized = applyOverrides(Scene{}, size, "");
    EXPECT_EQ(sized.width, 640);
    EXPECT_EQ(sized.height, 48);
    SceneOverrides level;
    for (const char* bad : {"+3", "3 ", "0x3", "--3", ""}) {
        level.subdivisions = bad;
        EXPECT_NE(
            refusal([&] { applyOverrides(Scene{}, level, ""); }).find("--subdivisions: expected a level"),
            std::string::npos)
            << bad;
    }
    level.subdivisions = "1.5";
    EXPECT_EQ(refusal([&] { applyOverrides(Scene{}, level, ""); }),
              "--subdivisions: expected a level 0..10 or auto, got \"1.5\"");
}

// Each named value's flag gives the scene file's message with its own name for the field, and lists the
// vocabulary itself (the --shading list was once typed by hand and had to be edited when exact arrived).
TEST(OneDoorPerValue, FlagsAndSceneFilesRefuseASpellingAlike) {
    struct Field {
        const char* key;
        std::optional<std::string> SceneOverrides::*flag;
    };
    for (const Field& f :
         {Field{"shading", &SceneOverrides::shading}, Field{"lighting", &SceneOverrides::lighting},
          Field{"depth", &SceneOverrides::depth}, Field{"overlay", &SceneOverrides::overlay}}) {
        SceneOverrides o;
        o.*f.flag = "nonsense\x1b[31m";
        const std::string fromFlag = refusal([&] { applyOverrides(Scene{}, o, ""); });
        const std::string fromFile = refusal(
            [&] { parseScene(std::string(R"({")") + f.key + R"(": "nonsense\u001b[31m"})", "s.json"); });
        SCOPED_TRACE(f.key);
        EXPECT_EQ(fromFlag.substr(0, 2), "--");
        EXPECT_EQ(fromFlag.substr(2), fromFile.substr(std::string("s.json: ").size()));
        EXPECT_EQ(fromFlag.find('\x1b'), std::string::npos) << "a control character reached the message";
    }
    SceneOverrides o;
    o.shading = "x";
    const std::string message = refusal([&] { applyOverrides(Scene{}, o, ""); });
    for (ShadingMode mode : kAllShadingModes)
        EXPECT_NE(message.find(toString(mode)), std::string::npos) << message;
}

} // namespace
} // namespace shadelab::app
