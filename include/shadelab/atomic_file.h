// Output files appear whole or not at all: written to a temporary file beside the target, flushed to disk,
// then renamed over it. Any failure removes the temporary file and leaves the target as it was.
#pragma once

#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace shadelab {

// `write` fills the temporary file (throwing on failure); `what` names the content in messages ("PNG").
// Throws RuntimeError "cannot write <what> "<path>": <reason>".
void writeFileAtomically(const std::filesystem::path& path, std::string_view what,
                         const std::function<void(std::FILE*)>& write);

// Throws RuntimeError "cannot write <what> "<path>": <reason>".
[[noreturn]] void failWrite(std::string_view what, const std::filesystem::path& path,
                            const std::string& reason);

} // namespace shadelab
