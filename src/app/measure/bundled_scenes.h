// The scenes the commands read: those in scenes/*.json, embedded at build time (cmake/embed_files.cmake),
// which the report, the bench and the demo's showcase find wherever the binary runs; and scene and lesson
// files, read with the models their mesh objects name (scene/model.h), so that every command draws the same
// scene.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "shadelab/scene/lesson.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_flags.h"

namespace shadelab::app {

// The text of scenes/<fileName>, e.g. bundledSceneText("grid.json").
std::optional<std::string_view> bundledSceneText(std::string_view fileName);
// Parsed, with its models read relative to the current directory (a bundled scene has no folder of its
// own); throws RuntimeError if there is no such bundled scene (a build problem, not user input).
Scene bundledScene(std::string_view fileName);

// The folder a scene file's "mesh" paths are relative to (DESIGN §4): the file's own; the current directory
// for standard input ("-") and for a file named without a folder.
std::filesystem::path sceneFolder(const std::filesystem::path& sceneFile);

// loadScene, then loadSceneModels beside the file. A model that cannot be read is an InputError naming the
// scene file and the object ("scene.json: objects[0].mesh: ...").
Scene loadSceneWithModels(const std::filesystem::path& sceneFile);
// composeScene with the models read before the overrides are applied and the result validated (the limits
// count a mesh's triangles, so they need its model): the DESIGN §4 defaults when `sceneFile` is empty.
Scene composeSceneWithModels(const std::string& sceneFile, const SceneOverrides& overrides);
// The models of every step of `lesson` (read from `lessonFile`): a step's mesh paths are relative to the
// folder of the scene file it starts from (LessonStep::file, itself relative to the lesson's folder), an
// inline step's to the lesson's folder. Errors name the lesson, the step and its scene file
// ("l.json: steps[2] (scene file \"s.json\"): objects[0].mesh: ...").
void loadLessonModels(Lesson& lesson, const std::filesystem::path& lessonFile);
// loadSceneOrLesson, with the models of the scene or of every step.
std::variant<Scene, Lesson> loadSceneOrLessonWithModels(const std::filesystem::path& file);

} // namespace shadelab::app
