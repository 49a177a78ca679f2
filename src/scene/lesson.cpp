// Lessons (shadelab/scene/lesson.h): the file read one way in, as scenes are. Each step's scene is a JSON
// tree (inline, read from the file it names, or the previous step's), the step's changes are merged into it,
// and the result goes through the scene parser, so every value is refused in the scene's own words.
#include "shadelab/scene/lesson.h"

#include <algorithm>
#include <array>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include "scene/scene_internal.h"
#include "shadelab/errors.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/scene_file.h"

namespace shadelab {

using namespace detail;

namespace {

// A step's own keys; every other key it may carry is a scene key (kSceneKeys) or "subdivisions".
constexpr std::array<std::string_view, 3> kStepKeys = {"title", "caption", "scene"};

std::vector<std::string_view> allowedStepKeys() {
    std::vector<std::string_view> keys(kStepKeys.begin(), kStepKeys.end());
    keys.insert(keys.end(), kSceneKeys.begin(), kSceneKeys.end());
    keys.emplace_back("subdivisions");
    return keys;
}

// Text a person wrote to be drawn on a slide: printable (no control byte but the caption's line breaks, valid
// UTF-8), within its size.
std::string readText(const Json& value, const std::string& path, std::size_t maxBytes, bool multiline) {
    const std::string& text = readString(value, path);
    if (text.size() > maxBytes)
        fail(path,
             "must be at most " + std::to_string(maxBytes) + " bytes, got " + std::to_string(text.size()));
    if (printable(text, multiline) != text || (multiline && text.find('\t') != std::string::npos))
        fail(path, std::string("must be printable text") + (multiline ? " (lines broken by \\n)" : "") +
                       ", got " + quotedValue(text));
    const auto lines = std::count(text.begin(), text.end(), '\n') + 1;
    if (multiline && lines > kMaxCaptionLines)
        fail(path,
             "must be at most " + std::to_string(kMaxCaptionLines) + " lines, got " + std::to_string(lines));
    return text;
}

// The scene a step starts from, as a tree: written inline, or read from the file it names.
Json stepBase(const Json& scene, const std::string& path, const SceneTextReader& readScene) {
    if (scene.is_object()) {
        try {
            sceneFromJson(scene); // refused with the inline scene's own path, before any change is merged
        } catch (const InputError& e) {
            fail(path, e.what());
        }
        return scene;
    }
    if (!scene.is_string())
        fail(path,
             "must be a scene (an object) or the path of a scene file (a string), got " + describe(scene));
    const std::string& file = scene.get_ref<const std::string&>();
    if (file.empty()) fail(path, "must name a scene file, got an empty string");
    if (file.front() == '/')
        fail(path, "must be a path relative to the lesson's folder, got " + quotedValue(file));
    try {
        const std::string text = readScene(file);
        Json tree = parseJson(text);
        sceneFromJson(tree);
        return tree;
    } catch (const InputError& e) {
        fail(path + " (" + quotedValue(file) + ")", e.what());
    }
}

// The step's changes merged into its base: objects merge key by key (RFC 7386), anything else replaces.
// "subdivisions" sets every object's level, as --subdivisions does.
void applyChanges(const Json& step, const std::string& path, Json& scene) {
    for (auto it = step.begin(); it != step.end(); ++it) {
        const std::string& key = it.key();
        if (std::find(kStepKeys.begin(), kStepKeys.end(), key) != kStepKeys.end()) continue;
        if (it->is_null()) fail(keyPath(path, key), "must be a value, got null");
        if (key == "subdivisions") continue;
        Json patch = Json::object();
        patch[key] = *it;
        scene.merge_patch(patch);
    }
    if (const Json* level = member(step, "subdivisions")) {
        if (!level->is_number() && !level->is_string())
            fail(keyPath(path, "subdivisions"),
                 "must be a level (a number) or \"auto\", got " + describe(*level));
        if (!scene.contains("objects")) scene["objects"] = Json::array({Json::object()});
        if (!scene["objects"].is_array()) return; // the scene parser names it
        for (Json& object : scene["objects"])
            if (object.is_object()) object["subdivisions"] = *level;
    }
}

LessonStep readStep(const Json& step, const std::string& path, const SceneTextReader& readScene,
                    Json& scene) {
    requireObject(step, path);
    static const std::vector<std::string_view> kAllowed = allowedStepKeys();
    checkKeys(step, path, kAllowed);
    LessonStep out;
    const Json* title = member(step, "title");
    if (!title) fail(keyPath(path, "title"), "missing; every step has a title");
    out.title = readText(*title, keyPath(path, "title"), kMaxStepTitleBytes, false);
    if (out.title.empty()) fail(keyPath(path, "title"), "must not be empty");
    if (const Json* caption = member(step, "caption"))
        out.caption = readText(*caption, keyPath(path, "caption"), kMaxCaptionBytes, true);
    if (const Json* base = member(step, "scene")) scene = stepBase(*base, keyPath(path, "scene"), readScene);
    applyChanges(step, path, scene);
    try {
        out.scene = sceneFromJson(scene);
    } catch (const InputError& e) {
        fail(path, e.what()); // a change the step made: "steps[2]: shading: must be one of ..."
    }
    return out;
}

} // namespace

bool detail::isLessonTree(const Json& tree) {
    return tree.is_object() && tree.contains("steps");
}

bool isLessonText(std::string_view jsonText) {
    try {
        return isLessonTree(parseJson(jsonText)); // the scene's limits: nesting, duplicate keys
    } catch (const InputError&) {
        return false;
    }
}

namespace {

// parseLesson on a tree already parsed.
Lesson lessonFromTree(const Json& root, std::string_view source, const SceneTextReader& readScene) {
    try {
        requireObject(root, "");
        static constexpr std::array<std::string_view, 2> kKeys = {"title", "steps"};
        checkKeys(root, "", kKeys);
        Lesson lesson;
        const Json* title = member(root, "title");
        if (!title) fail("title", "missing; a lesson has a title");
        lesson.title = readText(*title, "title", kMaxStepTitleBytes, false);
        const Json* steps = member(root, "steps");
        if (!steps || !steps->is_array() || steps->empty())
            fail("steps",
                 "must be an array of at least one step, got " + (steps ? describe(*steps) : "nothing"));
        if (steps->size() > kMaxLessonSteps)
            fail("steps", "must hold at most " + std::to_string(kMaxLessonSteps) + " steps, got " +
                              std::to_string(steps->size()));
        Json scene = Json::object(); // a first step without a scene starts from the defaults (DESIGN §4)
        for (std::size_t i = 0; i < steps->size(); ++i)
            lesson.steps.push_back(readStep((*steps)[i], indexPath("steps", i), readScene, scene));
        return lesson;
    } catch (const InputError& e) {
        throw InputError(std::string(source) + ": " + e.what());
    }
}

// A lesson file's tree, its scene files read beside it.
Lesson lessonBeside(const Json& root, const std::filesystem::path& path) {
    const std::filesystem::path folder = path.parent_path();
    return lessonFromTree(root, path.string(),
                          [&folder](const std::string& file) { return readSceneFile(folder / file); });
}

} // namespace

Lesson parseLesson(std::string_view jsonText, std::string_view source, const SceneTextReader& readScene) {
    return lessonFromTree(parseJsonFrom(jsonText, source), source, readScene);
}

Lesson loadLesson(const std::filesystem::path& path) {
    return lessonBeside(parseJsonFrom(readSceneFile(path), path.string()), path);
}

std::variant<Scene, Lesson> loadSceneOrLesson(const std::filesystem::path& path) {
    const Json tree = parseJsonFrom(readSceneFile(path), path.string()); // parsed once, whichever it is
    if (!isLessonTree(tree)) return sceneFromTree(tree, path.string());
    return lessonBeside(tree, path);
}

std::string slideFileName(std::size_t index, std::size_t count, std::string_view title) {
    const std::size_t digits = std::max<std::size_t>(2, std::to_string(count).size());
    std::string number = std::to_string(index + 1);
    number.insert(0, digits - std::min(digits, number.size()), '0');
    std::string safe;
    for (const char c : title) {
        const char lower = (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
        const bool plain = (lower >= 'a' && lower <= 'z') || (lower >= '0' && lower <= '9');
        if (plain)
            safe += lower;
        else if (!safe.empty() && safe.back() != '-')
            safe += '-';
        if (safe.size() >= 48) break;
    }
    while (!safe.empty() && safe.back() == '-') safe.pop_back();
    return number + "-" + (safe.empty() ? "step" : safe) + ".png";
}

} // namespace shadelab
