// The scenes in scenes/*.json, embedded at build time (cmake/embed_files.cmake): the report, the bench
// and the demo's showcase find them wherever the binary runs.
#pragma once

#include <optional>
#include <string_view>

#include "shadelab/scene/scene.h"

namespace shadelab::app {

// The text of scenes/<fileName>, e.g. bundledSceneText("grid.json").
std::optional<std::string_view> bundledSceneText(std::string_view fileName);
// Parsed; throws RuntimeError if there is no such bundled scene (a build problem, not user input).
Scene bundledScene(std::string_view fileName);

} // namespace shadelab::app
