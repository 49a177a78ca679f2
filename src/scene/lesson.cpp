// Lessons (shadelab/scene/lesson.h): the file read one way in, as scenes are. Each step's scene is a JSON
// tree (inline, read from the file it names, or the previous step's), the step's changes are merged into it,
// and the result goes through the scene parser, so every value is refused in the scene's own words.
#include "shadelab/scene/lesson.h"

#include <algorithm>
#include <array>
#include <map>
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
constexpr std::array<std::string_view, 4> kStepKeys = {"title", "caption", "notes", "scene"};

std::vector<std::string_view> allowedStepKeys() {
    std::vector<std::string_view> keys(kStepKeys.begin(), kStepKeys.end());
    keys.insert(keys.end(), kSceneKeys.begin(), kSceneKeys.end());
    keys.emplace_back("subdivisions");
    keys.emplace_back("all_objects");
    return keys;
}

// Text a person wrote to be drawn on a slide: printable (valid UTF-8 with no control or format character
// but the caption's line breaks, so that nothing hidden reorders a terminal's line), within its size.
std::string readText(const Json& value, const std::string& path, std::size_t maxBytes, bool multiline,
                     int maxLines = kMaxCaptionLines) {
    const std::string& text = readString(value, path);
    if (text.size() > maxBytes)
        fail(path,
             "must be at most " + std::to_string(maxBytes) + " bytes, got " + std::to_string(text.size()));
    std::string unprintable = unprintableCharacter(text, multiline);
    if (const std::size_t tab = text.find('\t'); unprintable.empty() && tab != std::string::npos)
        unprintable = "U+0009 (a tab) at byte " + std::to_string(tab);
    if (!unprintable.empty())
        fail(path, std::string("must be printable text") + (multiline ? " (lines broken by \\n)" : "") +
                       ", got " + quotedValue(text) + ": " + unprintable + "; remove it");
    const auto lines = std::count(text.begin(), text.end(), '\n') + 1;
    if (multiline && lines > maxLines)
        fail(path, "must be at most " + std::to_string(maxLines) + " lines, got " + std::to_string(lines));
    return text;
}

// The scene files a lesson's steps name, each read, parsed and checked once however many steps name it, and
// the scene text the steps parse bounded (kMaxLessonSceneBytes), each step counting its whole scene. Every
// file read is some step's base, so the files read together are bounded by it too.
class StepFiles {
public:
    explicit StepFiles(const SceneTextReader& read) : read_(read) {}

    // The tree of the scene file `file` (a step's "scene", as written); throws InputError saying why not.
    const Json& tree(const std::string& file, const std::string& path) {
        checkStepPath(file, path);
        if (const auto it = trees_.find(file); it != trees_.end()) return it->second.tree;
        try {
            const std::string text = read_(file);
            Json tree = parseJson(text);
            sceneFromJson(tree);
            files_.push_back(file);
            return trees_.emplace(file, File{std::move(tree), text.size()}).first->second.tree;
        } catch (const InputError& e) {
            fail(path + " (" + quotedValue(file) + ")", e.what());
        }
    }
    // The bytes a step's base counts: its file's size, or the inline scene's written size.
    std::size_t bytesOf(const std::string& file) const { return trees_.at(file).bytes; }

    // Counts one step's scene text against the lesson's bound.
    void countStep(std::size_t sceneBytes, const std::string& path) {
        stepBytes_ += sceneBytes;
        if (stepBytes_ > kMaxLessonSceneBytes)
            fail(path, "the steps so far parse " + std::to_string(stepBytes_ >> 20) +
                           " MiB of scene text in all (each step its whole scene); a lesson parses at most " +
                           std::to_string(kMaxLessonSceneBytes >> 20) +
                           " MiB (four of the largest scene files): use fewer steps or smaller scenes");
    }

    std::vector<std::string> files() const { return files_; }

private:
    // A step's file is named relative to the lesson's folder; "-" (standard input on the command line) and
    // a NUL byte (which would cut the path short) are no such names.
    static void checkStepPath(const std::string& file, const std::string& path) {
        if (file.empty()) fail(path, "must name a scene file, got an empty string");
        if (file.find('\0') != std::string::npos)
            fail(path, "must be a path without a NUL byte, got " + quotedValue(file) +
                           "; name the scene file relative to the lesson's folder");
        if (file == "-")
            fail(path, "must name a scene file relative to the lesson's folder, got \"-\" (standard input "
                       "is no step's scene); write \"./-\" for a file named -");
        if (file.front() == '/')
            fail(path, "must be a path relative to the lesson's folder, got " + quotedValue(file));
    }

    struct File {
        Json tree;
        std::size_t bytes;
    };
    const SceneTextReader& read_;
    std::map<std::string, File> trees_;
    std::vector<std::string> files_;
    std::size_t stepBytes_ = 0;
};

// The scene a step starts from, as a tree: written inline, or read from the file it names. `bytes` is set
// to its size (the file's, or the inline scene's as written), `file` to the file's name ("" inline).
Json stepBase(const Json& scene, const std::string& path, StepFiles& files, std::size_t& bytes,
              std::string& file) {
    file.clear();
    if (scene.is_object()) {
        try {
            sceneFromJson(scene); // refused with the inline scene's own path, before any change is merged
        } catch (const InputError& e) {
            fail(path, e.what());
        }
        bytes = scene.dump().size();
        return scene;
    }
    if (!scene.is_string())
        fail(path,
             "must be a scene (an object) or the path of a scene file (a string), got " + describe(scene));
    const std::string& named = scene.get_ref<const std::string&>();
    Json tree = files.tree(named, path);
    bytes = files.bytesOf(named);
    file = named;
    return tree;
}

// The scene's objects array, made the one default sphere when the scene has none (DESIGN §4).
Json& objectsOf(Json& scene) {
    if (!scene.contains("objects")) scene["objects"] = Json::array({Json::object()});
    return scene["objects"];
}

// "objects" written as an object, {"1": {...}}: each named object (by its index in the scene's list)
// merged with its changes, the list kept; "all_objects": {...} merged into every object. `changed` gets
// the objects' indices.
void patchObjects(const Json& patch, const std::string& path, Json& scene,
                  std::vector<std::size_t>& changed) {
    Json& objects = objectsOf(scene);
    if (!objects.is_array()) return; // the scene parser names it
    for (auto it = patch.begin(); it != patch.end(); ++it) {
        const std::string& key = it.key();
        const bool digits =
            !key.empty() && key.size() <= 9 && key.find_first_not_of("0123456789") == std::string::npos;
        if (!digits || std::stoul(key) >= objects.size())
            fail(keyPath(path, key),
                 (objects.empty()
                      ? std::string("the scene has no objects to change")
                      : "must be the index of one of the scene's " + std::to_string(objects.size()) +
                            " objects (0.." + std::to_string(objects.size() - 1) + ")") +
                     ", got " + quotedValue(key) +
                     "; \"all_objects\" changes every object, an array replaces the list");
        if (!it->is_object())
            fail(keyPath(path, key), "must be an object's changes (an object), got " + describe(*it));
        const std::size_t index = std::stoul(key);
        objects[index].merge_patch(*it);
        changed.push_back(index);
    }
}

// The step's changes merged into its base: objects merge key by key (RFC 7386), anything else replaces.
// "subdivisions" sets every object's level, as --subdivisions does; "objects" written as an object and
// "all_objects" change objects of the list without replacing it (patchObjects).
void applyChanges(const Json& step, const std::string& path, Json& scene, LessonStep& out) {
    for (auto it = step.begin(); it != step.end(); ++it) {
        const std::string& key = it.key();
        if (std::find(kStepKeys.begin(), kStepKeys.end(), key) != kStepKeys.end()) continue;
        if (it->is_null()) fail(keyPath(path, key), "must be a value, got null");
        if (key == "subdivisions") continue;
        if (key == "objects" && it->is_object()) {
            patchObjects(*it, keyPath(path, key), scene, out.changedObjects);
            continue;
        }
        if (key == "all_objects") {
            if (!it->is_object())
                fail(keyPath(path, key),
                     "must be the changes every object takes (an object), got " + describe(*it));
            Json& objects = objectsOf(scene);
            if (!objects.is_array()) continue; // the scene parser names it
            for (std::size_t i = 0; i < objects.size(); ++i) {
                objects[i].merge_patch(*it);
                out.changedObjects.push_back(i);
            }
            continue;
        }
        Json patch = Json::object();
        patch[key] = *it;
        scene.merge_patch(patch);
    }
    if (const Json* level = member(step, "subdivisions")) {
        if (!level->is_number() && !level->is_string())
            fail(keyPath(path, "subdivisions"),
                 "must be a level (a number) or \"auto\", got " + describe(*level));
        Json& objects = objectsOf(scene);
        if (!objects.is_array()) return; // the scene parser names it
        for (Json& object : objects)     // a mesh object's triangles are its file's: it has no level
            if (object.is_object() && !object.contains("mesh")) object["subdivisions"] = *level;
    }
}

// `base` carries the previous step's scene (its tree, size and file) in and this step's out.
struct StepBase {
    Json scene = Json::object(); // a first step without a scene starts from the defaults (DESIGN §4)
    std::size_t bytes = 2;
    std::string file;
};

LessonStep readStep(const Json& step, const std::string& path, StepFiles& files, StepBase& base) {
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
    if (const Json* notes = member(step, "notes"))
        out.notes = readText(*notes, keyPath(path, "notes"), kMaxNotesBytes, true, kMaxNotesLines);
    if (const Json* scene = member(step, "scene"))
        base.scene = stepBase(*scene, keyPath(path, "scene"), files, base.bytes, base.file);
    files.countStep(base.bytes + step.dump().size(), path);
    out.file = base.file;
    applyChanges(step, path, base.scene, out);
    std::sort(out.changedObjects.begin(), out.changedObjects.end());
    out.changedObjects.erase(std::unique(out.changedObjects.begin(), out.changedObjects.end()),
                             out.changedObjects.end());
    try {
        out.scene = sceneFromJson(base.scene);
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
        StepBase base;
        StepFiles files(readScene);
        for (std::size_t i = 0; i < steps->size(); ++i)
            lesson.steps.push_back(readStep((*steps)[i], indexPath("steps", i), files, base));
        lesson.sceneFiles = files.files();
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

} // namespace shadelab
