#include "app/measure/bundled_scenes.h"

#include <string>

#include "shadelab/errors.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/model.h"
#include "shadelab/scene/scene_file.h"

namespace shadelab::app {

namespace fs = std::filesystem;

namespace {

// loadSceneModels with its message prefixed by where the scene came from, as parseScene prefixes its own.
void loadModelsOf(Scene& scene, const fs::path& folder, const std::string& where, ModelCache& cache) {
    try {
        loadSceneModels(scene, folder, cache);
    } catch (const InputError& e) {
        throw InputError(where + ": " + e.what());
    }
}

} // namespace

Scene bundledScene(std::string_view fileName) {
    const auto text = bundledSceneText(fileName);
    if (!text) throw RuntimeError("scene " + std::string(fileName) + " is not bundled in this binary");
    Scene scene = parseScene(*text, fileName);
    ModelCache cache;
    loadModelsOf(scene, ".", std::string(fileName), cache);
    return scene;
}

fs::path sceneFolder(const fs::path& sceneFile) {
    if (sceneFile == "-" || sceneFile.parent_path().empty()) return ".";
    return sceneFile.parent_path();
}

Scene loadSceneWithModels(const fs::path& sceneFile) {
    Scene scene = loadScene(sceneFile);
    ModelCache cache;
    loadModelsOf(scene, sceneFolder(sceneFile), sceneFile.string(), cache);
    return scene;
}

Scene composeSceneWithModels(const std::string& sceneFile, const SceneOverrides& overrides) {
    return applyOverrides(sceneFile.empty() ? Scene{} : loadSceneWithModels(sceneFile), overrides, sceneFile);
}

void loadLessonModels(Lesson& lesson, const fs::path& lessonFile) {
    const fs::path lessonFolder = sceneFolder(lessonFile);
    ModelCache cache; // a file named by many steps is read once
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        LessonStep& step = lesson.steps[i];
        const fs::path folder = step.file.empty() ? lessonFolder : sceneFolder(lessonFolder / step.file);
        const std::string file = step.file.empty() ? "" : " (scene file " + quotedValue(step.file) + ")";
        loadModelsOf(step.scene, folder, lessonFile.string() + ": steps[" + std::to_string(i) + "]" + file,
                     cache);
    }
}

std::variant<Scene, Lesson> loadSceneOrLessonWithModels(const fs::path& file) {
    std::variant<Scene, Lesson> read = loadSceneOrLesson(file);
    ModelCache cache;
    if (Scene* scene = std::get_if<Scene>(&read))
        loadModelsOf(*scene, sceneFolder(file), file.string(), cache);
    else
        loadLessonModels(std::get<Lesson>(read), file);
    return read;
}

} // namespace shadelab::app
