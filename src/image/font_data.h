// The font file embedded at build time (cmake/embed_files.cmake generates the definition from Debian's
// fonts-dejavu-core; see CMakeLists.txt).
#pragma once

#include <optional>
#include <string_view>

namespace shadelab {

// The bytes of the font file `name` (e.g. "DejaVuSansMono-Bold.ttf"); nullopt if it was not embedded.
std::optional<std::string_view> embeddedFont(std::string_view name);

} // namespace shadelab
