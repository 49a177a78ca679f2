// Shader sources embedded at build time (cmake/embed_files.cmake generates the definition).
#pragma once

#include <optional>
#include <string_view>

namespace shadelab::gl {

// The text of shaders/<name>, e.g. embeddedShader("surface.vert.glsl"); nullopt if there is no such file.
std::optional<std::string_view> embeddedShader(std::string_view name);

} // namespace shadelab::gl
