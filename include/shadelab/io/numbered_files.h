// Files written together under the first free numbered name in a folder (the demo's S: shadelab-NNN.json
// and shadelab-NNN.png), by the output rules of io/atomic_file.h: nothing already in the folder is opened or
// replaced, each content goes to an unpredictable temporary file first (mkstemp: O_CREAT | O_EXCL, so a
// planted link or FIFO is never written through) that SIGINT, SIGTERM and SIGHUP remove, and a failure
// leaves nothing behind.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace shadelab {

struct NumberedFile {
    std::string suffix; // ".json"
    std::string bytes;
};

// Writes `files` to temporaries in `folder`, then gives them the names prefix + NNN + suffix for the first
// NNN after `lastNumber` at which every name is free, claimed in the order given (a reader that sees the
// last one finds the others beside it): a hard link to the temporary (link() never replaces), or, where the
// file system has none, an O_EXCL placeholder renamed over. Returns the stem (folder/prefixNNN) and leaves
// `lastNumber` at its NNN. Throws RuntimeError naming the file and the OS's reason.
std::string writeNumberedFiles(const std::filesystem::path& folder, std::string_view prefix, int& lastNumber,
                               const std::vector<NumberedFile>& files);

} // namespace shadelab
