// Lesson files (shadelab/scene/lesson.h): steps, their scenes and changes, and every refusal naming its JSON
// path.
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "input_error.h"
#include "shadelab/errors.h"
#include "shadelab/scene/lesson.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_file.h"

namespace shadelab {
namespace {

namespace fs = std::filesystem;

// Scene files by the path a step names; anything else cannot be read.
SceneTextReader filesOf(std::map<std::string, std::string> files) {
    return [files = std::move(files)](const std::string& path) {
        auto it = files.find(path);
        if (it == files.end()) throw InputError("cannot read scene file: No such file or directory");
        return it->second;
    };
}

const SceneTextReader kNoFiles = filesOf({});

// The message parseLesson gives, or "" when it accepts the text.
std::string refusal(const std::string& text, const SceneTextReader& read = kNoFiles) {
    return test::inputErrorOf([&] { (void)parseLesson(text, "lesson.json", read); });
}

TEST(Lesson, StepsKeepThePreviousSceneAndApplyTheirChanges) {
    const Lesson lesson = parseLesson(R"({"title": "Shading", "steps": [
        {"title": "Flat", "caption": "One normal\nper face.", "scene": {"shading": "flat",
         "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0]}}},
        {"title": "Gouraud", "shading": "gouraud", "camera": {"eye": [0, 0, 7]}},
        {"title": "Level 2", "subdivisions": 2},
        {"title": "New scene", "scene": {"lighting": "blinn-phong"}}]})",
                                      "lesson.json", kNoFiles);
    ASSERT_EQ(lesson.steps.size(), 4u);
    EXPECT_EQ(lesson.title, "Shading");
    EXPECT_EQ(lesson.steps[0].caption, "One normal\nper face.");
    EXPECT_EQ(lesson.steps[0].scene.shading, ShadingMode::Flat);
    // The change is merged: the eye moves, the target and up stay what step 1 wrote.
    EXPECT_EQ(lesson.steps[1].scene.shading, ShadingMode::Gouraud);
    EXPECT_EQ(lesson.steps[1].scene.eye, glm::dvec3(0, 0, 7));
    EXPECT_EQ(lesson.steps[1].scene.up, glm::dvec3(0, 1, 0));
    EXPECT_EQ(lesson.steps[1].caption, "");
    // A step without a scene keeps the previous step's, changes included.
    EXPECT_EQ(lesson.steps[2].scene.shading, ShadingMode::Gouraud);
    EXPECT_EQ(lesson.steps[2].scene.objects.at(0).subdivisions, 2);
    // A new scene starts again from the defaults.
    const Scene defaults;
    EXPECT_EQ(lesson.steps[3].scene.shading, defaults.shading);
    EXPECT_EQ(lesson.steps[3].scene.lighting, LightingModel::BlinnPhong);
    EXPECT_EQ(lesson.steps[3].scene.eye, defaults.eye);
}

TEST(Lesson, AFirstStepWithoutASceneDrawsTheDefaults) {
    const Lesson lesson = parseLesson(R"({"title": "T", "steps": [{"title": "Only"}]})", "l", kNoFiles);
    ASSERT_EQ(lesson.steps.size(), 1u);
    EXPECT_EQ(lesson.steps[0].scene, Scene{});
}

TEST(Lesson, SubdivisionsSetEveryObjectsLevelOrAuto) {
    const Lesson lesson = parseLesson(R"({"title": "T", "steps": [
        {"title": "Two", "scene": {"objects": [{"center": [-1, 0, 0]}, {"center": [1, 0, 0]}]},
         "subdivisions": 5},
        {"title": "Auto", "subdivisions": "auto"}]})",
                                      "l", kNoFiles);
    for (const SceneObject& object : lesson.steps[0].scene.objects) EXPECT_EQ(object.subdivisions, 5);
    for (const SceneObject& object : lesson.steps[1].scene.objects)
        EXPECT_EQ(object.subdivisions, kAutoSubdivisions);
    EXPECT_EQ(lesson.steps[1].scene.objects.at(1).center, glm::dvec3(1, 0, 0));
}

TEST(Lesson, ASceneFileIsReadByThePathAsWritten) {
    const std::string text = R"({"shading": "toon", "toon_bands": 3})";
    const Lesson lesson = parseLesson(
        R"({"title": "T", "steps": [{"title": "A", "scene": "../scenes/x.json", "term": "diffuse"}]})", "l",
        filesOf({{"../scenes/x.json", text}}));
    Scene expected = parseScene(text);
    expected.term = LightingTerm::Diffuse;
    EXPECT_EQ(lesson.steps[0].scene, expected);
}

TEST(Lesson, AMissingSceneFileNamesTheLessonTheStepAndTheFile) {
    const std::string message =
        refusal(R"({"title": "T", "steps": [{"title": "A"}, {"title": "B", "scene": "gone.json"}]})");
    EXPECT_EQ(message, "lesson.json: steps[1].scene (\"gone.json\"): cannot read scene file: No such file or "
                       "directory");
}

TEST(Lesson, ABadSceneFileIsRefusedWithItsOwnPath) {
    const std::string message =
        refusal(R"({"title": "T", "steps": [{"title": "A", "scene": "x.json"}]})",
                filesOf({{"x.json", R"({"lights": [{"type": "point", "position": 1}]})"}}));
    EXPECT_EQ(
        message.rfind("lesson.json: steps[0].scene (\"x.json\"): lights[0].position: must be an array of 3 "
                      "numbers",
                      0),
        0u)
        << message;
}

// The same value, refused by a scene and by a lesson's change, in the same words after the step's path.
TEST(Lesson, AChangeIsRefusedInTheScenesOwnWords) {
    for (const std::string change :
         {R"("shading": "glossy")", R"("lighting": 3)", R"("view": "split:flat")", R"("toon_bands": 99)",
          R"("camera": {"eye": [0, 0, 0]})", R"("subdivisions": 11)", R"("overlay": "edges")"}) {
        std::string sceneMessage;
        try {
            const std::string key = change.substr(1, change.find('"', 1) - 1);
            std::string sceneText = "{" + change + "}";
            if (key == "subdivisions") sceneText = R"({"objects": [{"subdivisions": 11}]})";
            parseScene(sceneText, "scene.json");
            ADD_FAILURE() << "the scene accepted " << change;
            continue;
        } catch (const InputError& e) {
            sceneMessage = e.what();
        }
        const std::string message =
            refusal(R"({"title": "T", "steps": [{"title": "A"}, {"title": "B", )" + change + "}]}");
        const std::string sceneReason = sceneMessage.substr(std::string("scene.json: ").size());
        EXPECT_EQ(message, "lesson.json: steps[1]: " + sceneReason) << change;
    }
}

TEST(Lesson, EveryRefusalNamesItsJsonPath) {
    const std::map<std::string, std::string> cases = {
        {R"([])", "lesson.json: the top level: must be an object, got array of 0 elements"},
        {R"({"steps": [{"title": "A"}]})", "lesson.json: title: missing; a lesson has a title"},
        {R"({"title": "T"})", "lesson.json: steps: must be an array of at least one step, got nothing"},
        {R"({"title": "T", "steps": []})",
         "lesson.json: steps: must be an array of at least one step, got array of 0 elements"},
        {R"({"title": "T", "steps": [{"title": "A"}], "step": 1})",
         "lesson.json: step: unknown key; expected one of title, steps"},
        {R"({"title": "T", "steps": [{"caption": "no title"}]})",
         "lesson.json: steps[0].title: missing; every step has a title"},
        {R"({"title": "T", "steps": [{"title": ""}]})", "lesson.json: steps[0].title: must not be empty"},
        {R"({"title": "T", "steps": [{"title": 7}]})",
         "lesson.json: steps[0].title: must be a string, got number 7"},
        {R"({"title": "T", "steps": [{"title": "A", "shadng": "flat"}]})",
         "lesson.json: steps[0].shadng: unknown key; expected one of title, caption, notes, scene, image, "
         "camera, "
         "projection, perspective_matrix, shading, lighting, term, toon_bands, tolerance_px, depth, "
         "vertex_normals, normal_matrix, overlay, view, view_at, view_observer, objects, lights, "
         "subdivisions, all_objects"},
        {R"({"title": "T", "steps": [{"title": "A", "shading": null}]})",
         "lesson.json: steps[0].shading: must be a value, got null"},
        {R"({"title": "T", "steps": [{"title": "A", "scene": 3}]})",
         "lesson.json: steps[0].scene: must be a scene (an object) or the path of a scene file (a string), "
         "got "
         "number 3"},
        {R"({"title": "T", "steps": [{"title": "A", "scene": "/etc/passwd"}]})",
         "lesson.json: steps[0].scene: must be a path relative to the lesson's folder, got \"/etc/passwd\""},
        {R"({"title": "T", "steps": [{"title": "A", "scene": {"shading": "glossy"}}]})",
         "lesson.json: steps[0].scene: shading: unknown value \"glossy\"; expected one of flat, gouraud, "
         "phong, toon, exact"},
        {R"({"title": "T", "steps": [{"title": "A\u0007"}]})",
         "lesson.json: steps[0].title: must be printable text, got \"A\\u0007\": U+0007 (a control "
         "character) at byte 1; remove it"},
        {R"({"title": "T", "steps": [{"title": "A", "caption": "1\n2\n3\n4\n5\n6\n7\n8\n9"}]})",
         "lesson.json: steps[0].caption: must be at most 8 lines, got 9"},
        {R"({"title": "T", "steps": [{"title": "A", "subdivisions": [1]}]})",
         "lesson.json: steps[0].subdivisions: must be a level (a number) or \"auto\", got array of 1 "
         "element"},
    };
    for (const auto& [text, expected] : cases) EXPECT_EQ(refusal(text), expected) << text;
}

TEST(Lesson, SizesAreBounded) {
    std::string steps;
    for (std::size_t i = 0; i <= kMaxLessonSteps; ++i)
        steps += std::string(i ? "," : "") + R"({"title": "S"})";
    EXPECT_EQ(refusal(R"({"title": "T", "steps": [)" + steps + "]}"),
              "lesson.json: steps: must hold at most 500 steps, got 501");
    const std::string longTitle(kMaxStepTitleBytes + 1, 'x');
    EXPECT_EQ(refusal(R"({"title": "T", "steps": [{"title": ")" + longTitle + R"("}]})"),
              "lesson.json: steps[0].title: must be at most 120 bytes, got 121");
}

// "-" is standard input on the command line, and the window, check and slides would wait on it; a NUL
// would cut the path short and read another file.
TEST(Lesson, AStepsSceneIsAFileBesideTheLessonNeverStandardInputOrACutPath) {
    const SceneTextReader anything = [](const std::string&) { return std::string("{}"); };
    EXPECT_EQ(
        refusal(R"({"title": "T", "steps": [{"title": "A", "scene": "-"}]})", anything),
        "lesson.json: steps[0].scene: must name a scene file relative to the lesson's folder, got \"-\" "
        "(standard input is no step's scene); write \"./-\" for a file named -");
    EXPECT_EQ(
        refusal(R"({"title": "T", "steps": [{"title": "A", "scene": "a.json\u0000.png"}]})", anything),
        "lesson.json: steps[0].scene: must be a path without a NUL byte, got \"a.json\\u0000.png\"; name "
        "the scene file relative to the lesson's folder");
    EXPECT_EQ(refusal(R"({"title": "T", "steps": [{"title": "A", "scene": "./-"}]})", anything), "");
}

// A file many steps name is read and parsed once; the lesson's work is bounded as a scene's is.
TEST(Lesson, EachSceneFileIsReadOnceAndTheLessonsWorkIsBounded) {
    std::map<std::string, int> reads;
    const std::string scene = R"({"shading": "flat")" + std::string(400 * 1024, ' ') + "}";
    const SceneTextReader counting = [&](const std::string& path) {
        ++reads[path];
        return scene;
    };
    auto stepsNaming = [](std::size_t count) {
        std::string steps;
        for (std::size_t i = 0; i < count; ++i)
            steps += std::string(i ? "," : "") + R"({"title": "S", "scene": "big.json"})";
        return R"({"title": "T", "steps": [)" + steps + "]}";
    };
    const Lesson lesson = parseLesson(stepsNaming(20), "lesson.json", counting);
    EXPECT_EQ(reads["big.json"], 1) << "20 steps name one file";
    EXPECT_EQ(lesson.sceneFiles, std::vector<std::string>{"big.json"});
    EXPECT_EQ(lesson.steps.at(19).file, "big.json");
    // 200 steps of a 400 KiB scene parse 80 MiB: past the 64 MiB (four largest scenes) a lesson may parse.
    // Each step counts its file (409,619 bytes) and its own 32: the 164th passes 64 MiB.
    const std::string refused = refusal(stepsNaming(200), counting);
    EXPECT_NE(refused.find("lesson.json: steps[163]: the steps so far parse 64 MiB of scene text in all"),
              std::string::npos)
        << refused;
}

// Text drawn on a slide and printed in a terminal carries nothing hidden: the bidi overrides reorder a
// terminal's line, U+2028 breaks a one-line title, U+200B and U+FEFF are invisible.
TEST(Lesson, TitlesAndCaptionsRefuseFormatCharacters) {
    const std::pair<const char*, const char*> cases[] = {{"\u202e", "U+202E"}, {"\u2066", "U+2066"},
                                                         {"\u2069", "U+2069"}, {"\u2028", "U+2028"},
                                                         {"\u200b", "U+200B"}, {"\ufeff", "U+FEFF"}};
    for (const auto& [escaped, name] : cases) {
        const std::string title =
            refusal(R"({"title": "T", "steps": [{"title": "ab)" + std::string(escaped) + R"(cd"}]})");
        EXPECT_NE(title.find("steps[0].title: must be printable text"), std::string::npos) << title;
        EXPECT_NE(title.find(std::string(name) + " (an invisible format character, or one that reorders or "
                                                 "breaks the line) at byte 2; remove it"),
                  std::string::npos)
            << title;
        const std::string caption = refusal(R"({"title": "T", "steps": [{"title": "A", "caption": "x)" +
                                            std::string(escaped) + R"("}]})");
        EXPECT_NE(caption.find("steps[0].caption: must be printable text"), std::string::npos) << caption;
    }
    // Letters of any script pass, as do the caption's line breaks.
    EXPECT_EQ(refusal(R"({"title": "Phong α = 8, ß, я", "steps": [{"title": "é", "caption": "a\nb"}]})"), "");
}

// "The same teapot with different parameters": a step changes one object, or every object, and keeps the
// scene's list; an array still replaces the list.
TEST(Lesson, AStepPatchesOneObjectOrEveryObjectAndKeepsTheList) {
    const Lesson lesson = parseLesson(R"({"title": "T", "steps": [
        {"title": "Three", "scene": {"objects": [{"center": [-2, 0, 0]}, {"center": [0, 0, 0]},
                                                 {"center": [2, 0, 0], "material": {"shininess": 8}}]}},
        {"title": "Shiny middle", "objects": {"1": {"material": {"shininess": 200}}}},
        {"title": "All red", "all_objects": {"material": {"diffuse": [1, 0, 0]}}},
        {"title": "Both", "all_objects": {"radius": 0.5}, "objects": {"2": {"radius": 0.25}}},
        {"title": "One", "objects": [{"center": [0, 1, 0]}]}]})",
                                      "lesson.json", kNoFiles);
    const auto& steps = lesson.steps;
    ASSERT_EQ(steps.size(), 5u);
    EXPECT_TRUE(steps[0].changedObjects.empty());
    ASSERT_EQ(steps[1].scene.objects.size(), 3u);
    EXPECT_EQ(steps[1].scene.objects[1].material.shininess, 200);
    EXPECT_EQ(steps[1].scene.objects[2].material.shininess, 8) << "the others keep theirs";
    EXPECT_EQ(steps[1].scene.objects[1].center, glm::dvec3(0)) << "merged, not replaced";
    EXPECT_EQ(steps[1].changedObjects, std::vector<std::size_t>{1});
    for (const SceneObject& object : steps[2].scene.objects)
        EXPECT_EQ(object.material.diffuse, glm::dvec3(1, 0, 0));
    EXPECT_EQ(steps[2].scene.objects[1].material.shininess, 200) << "the earlier change stays";
    EXPECT_EQ(steps[2].changedObjects, (std::vector<std::size_t>{0, 1, 2}));
    // "all_objects" first, then the one object named.
    EXPECT_EQ(steps[3].scene.objects[0].radius, 0.5);
    EXPECT_EQ(steps[3].scene.objects[2].radius, 0.25);
    ASSERT_EQ(steps[4].scene.objects.size(), 1u);
    EXPECT_TRUE(steps[4].changedObjects.empty());
    // A first step without a scene patches the default sphere.
    const Lesson defaults = parseLesson(
        R"({"title": "T", "steps": [{"title": "A", "objects": {"0": {"radius": 2}}}]})", "l", kNoFiles);
    EXPECT_EQ(defaults.steps[0].scene.objects.at(0).radius, 2);
}

TEST(Lesson, AnObjectPatchNamesAnObjectOfTheList) {
    const std::string two = R"({"title": "T", "steps": [{"title": "A", "scene": {"objects": [{}, {}]}, )";
    EXPECT_EQ(
        refusal(two + R"("objects": {"2": {"radius": 2}}}]})"),
        "lesson.json: steps[0].objects.2: must be the index of one of the scene's 2 objects (0..1), got "
        "\"2\"; \"all_objects\" changes every object, an array replaces the list");
    EXPECT_NE(refusal(two + R"("objects": {"first": {"radius": 2}}}]})").find("got \"first\""),
              std::string::npos);
    EXPECT_EQ(refusal(two + R"("objects": {"1": 3}}]})"),
              "lesson.json: steps[0].objects.1: must be an object's changes (an object), got number 3");
    EXPECT_EQ(
        refusal(two + R"("all_objects": [1]}]})"),
        "lesson.json: steps[0].all_objects: must be the changes every object takes (an object), got array "
        "of 1 element");
    // A change the scene refuses is named with the object's path.
    EXPECT_NE(refusal(two + R"("objects": {"1": {"radius": -1}}}]})")
                  .find("lesson.json: steps[0]: objects[1].radius"),
              std::string::npos)
        << refusal(two + R"("objects": {"1": {"radius": -1}}}]})");
    EXPECT_EQ(
        refusal(
            R"({"title": "T", "steps": [{"title": "A", "scene": {"objects": []}, "objects": {"0": {}}}]})"),
        "lesson.json: steps[0].objects.0: the scene has no objects to change, got \"0\"; \"all_objects\" "
        "changes every object, an array replaces the list");
}

TEST(Lesson, TellsALessonFromAScene) {
    EXPECT_TRUE(isLessonText(R"({"title": "T", "steps": []})"));
    EXPECT_FALSE(isLessonText(R"({"shading": "flat"})"));
    EXPECT_FALSE(isLessonText("not json"));
    EXPECT_FALSE(isLessonText(R"(["steps"])"));
}

TEST(Lesson, SlideNamesSortInStepOrderAndAreSafe) {
    EXPECT_EQ(slideFileName(2, 14, "The view volume"), "03-the-view-volume.png");
    EXPECT_EQ(slideFileName(0, 100, "Phong vs. Blinn-Phong (α = 8)"), "001-phong-vs-blinn-phong-alpha-8.png");
    EXPECT_EQ(slideFileName(9, 9, "../../etc/passwd"), "10-etc-passwd.png");
    EXPECT_EQ(slideFileName(0, 1, "✓✓✓"), "01-step.png");
    EXPECT_EQ(slideFileName(0, 1, std::string(300, 'a')).size(), std::string("01-").size() + 64 + 4);
    // Cut at a word's end, never inside one.
    EXPECT_EQ(slideFileName(0, 1, std::string(60, 'a') + " bbbbbbbbbb"),
              "01-" + std::string(60, 'a') + ".png");
}

// The lecture's symbols keep their meaning: the two normal-matrix slides are told apart by their names.
TEST(Lesson, SlideNamesSpellOutTheLecturesSymbols) {
    EXPECT_EQ(slideFileName(16, 21, "Normals transformed by M: wrong on purpose"),
              "17-normals-transformed-by-m-wrong-on-purpose.png");
    EXPECT_EQ(slideFileName(17, 21, "Normals transformed by (M⁻¹)ᵀ"),
              "18-normals-transformed-by-m-inverse-transpose.png");
    EXPECT_EQ(slideFileName(11, 21, "Attenuation: 1/(a + b·t + c·t²)"),
              "12-attenuation-1-a-b-t-c-t-squared.png");
    EXPECT_EQ(slideFileName(2, 21, "Projection normalization: the cube [-1,1]³"),
              "03-projection-normalization-the-cube-minus-1-1-cubed.png");
    EXPECT_EQ(slideFileName(3, 21, "The WebGL -1: the picture is empty"),
              "04-the-webgl-minus-1-the-picture-is-empty.png");
    EXPECT_EQ(slideFileName(0, 1, "Specular term: k_s·I_s·max(v·r, 0)^α"),
              "01-specular-term-k-s-i-s-max-v-r-0-alpha.png");
    EXPECT_EQ(slideFileName(0, 1, "Blinn-Phong: β, ψ and φ"), "01-blinn-phong-beta-psi-and-phi.png");
    EXPECT_EQ(slideFileName(0, 1, "Vertices p₀, p₁"), "01-vertices-p0-p1.png");
    EXPECT_EQ(slideFileName(0, 1, "Éclairage à la main"), "01-eclairage-a-la-main.png");
}

TEST(Lesson, LoadLessonReadsItsScenesBesideIt) {
    const fs::path folder = fs::temp_directory_path() / ("shadelab-lesson-" + std::to_string(::getpid()));
    fs::create_directories(folder / "scenes");
    std::ofstream(folder / "scenes" / "a.json") << R"({"shading": "flat"})";
    std::ofstream(folder / "lesson.json")
        << R"({"title": "T", "steps": [{"title": "A", "scene": "scenes/a.json"}]})";
    const Lesson lesson = loadLesson(folder / "lesson.json");
    EXPECT_EQ(lesson.steps.at(0).scene.shading, ShadingMode::Flat);
    std::ofstream(folder / "bad.json") << R"({"title": "T", "steps": [{"title": "A", "scene": "scenes"}]})";
    try {
        loadLesson(folder / "bad.json");
        ADD_FAILURE() << "a folder was read as a scene";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.json: steps[0].scene (\"scenes\"): "), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("it is a directory"), std::string::npos) << e.what();
    }
    fs::remove_all(folder);
}

} // namespace
} // namespace shadelab
