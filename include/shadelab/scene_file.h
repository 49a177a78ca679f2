// Scene files on disk, apart from scene.h so that code which only builds, reads or checks scenes does not
// parse <filesystem> (about 2 s of clang-tidy's time for each file that includes it).
#pragma once

#include <filesystem>

#include "shadelab/scene.h"

namespace shadelab {

// Reads and parses a file; a missing or unreadable file is an InputError naming the path.
Scene loadScene(const std::filesystem::path& path);
// sceneToJson written atomically to `path`; throws RuntimeError naming the path.
void saveScene(const Scene& scene, const std::filesystem::path& path);

} // namespace shadelab
