// The demo's screenshot files (S, src/app/shells/demo.cpp): nothing already in the screenshot folder is
// ever opened or replaced.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace shadelab::app {

// A new file in `folder` holding `bytes`, flushed to disk: mkstemp's O_CREAT | O_EXCL and unpredictable
// name, so nothing planted in the folder (a link, a FIFO) is opened; the mode a new file gets from umask.
std::string writeTemporary(const std::filesystem::path& folder, std::string_view bytes);

// Links the written temporaries to the first shadelab-NNN whose .json and .png are both free and
// removes the temporaries; returns the stem. Both names are claimed before either is given content (the
// JSON first, the PNG last), so a reader that sees the PNG finds its scene beside it.
// `lastNumber` is the last NNN tried (the next call starts after it).
[[nodiscard]] std::string claimFreeStem(const std::filesystem::path& folder, int& lastNumber,
                                        const std::string& tempJson, const std::string& tempPng);

} // namespace shadelab::app
