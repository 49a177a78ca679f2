// Scene files on disk, apart from scene.h so that code which only builds, reads or checks scenes does not
// parse <filesystem> (about 2 s of clang-tidy's time for each file that includes it).
#pragma once

#include <filesystem>
#include <variant>

#include "shadelab/scene/lesson.h"
#include "shadelab/scene/scene.h"

namespace shadelab {

// Reads and parses a file; a missing or unreadable file is an InputError naming the path.
Scene loadScene(const std::filesystem::path& path);
// sceneToJson written atomically to `path`; throws RuntimeError naming the path.
void saveScene(const Scene& scene, const std::filesystem::path& path);
// Reads and parses a lesson file; the scene files its steps name are read beside it, with loadScene's
// rules (a regular file of at most 16 MiB). A path that is not a lesson, or unreadable, is an InputError.
Lesson loadLesson(const std::filesystem::path& path);
// The file read once (so "-", standard input, works too) as a lesson when isLessonText says it is one,
// otherwise as a scene, each with its loader's rules and messages.
std::variant<Scene, Lesson> loadSceneOrLesson(const std::filesystem::path& path);

} // namespace shadelab
