// The three GL flavours one renderer and one set of GLSL sources run on (DESIGN §7). Native contexts are
// desktop OpenGL 3.3 core or OpenGL ES 3.0; the browser build is WebGL 2, which is OpenGL ES 3.0 to the
// renderer. The shaders keep to what all of them share; what a smaller API lacks is refused by name.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace shadelab {

enum class Api { Gl, Gles };
inline constexpr std::array kApis = {Api::Gl, Api::Gles}; // the vocabulary of --api (vocabulary.h)

std::string_view toString(Api api);    // "gl" | "gles": the spelling of --api
std::string_view displayName(Api api); // "OpenGL 3.3 core" | "OpenGL ES 3.0"
std::optional<Api> parseApi(std::string_view text);

} // namespace shadelab
