// What src/io/'s files share: a path as messages show it (quoted, control bytes escaped) and an OS error in
// words.
#pragma once

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include "shadelab/io/text.h"

namespace shadelab::detail {

inline std::string quoted(const std::filesystem::path& path) {
    return "\"" + printable(path.string()) + "\"";
}

inline std::string osError(int error = errno) {
    return std::strerror(error);
}

} // namespace shadelab::detail
