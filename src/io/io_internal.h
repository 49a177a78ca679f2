// What src/io/'s files share: a path as messages show it (quoted, control bytes escaped) and an OS error in
// words.
#pragma once

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

#include "shadelab/io/text.h"

namespace shadelab::detail {

// Built by appending: gcc 12 at -O2 reports a memcpy of 2^63 bytes (-Wrestrict, a known false positive of
// its libstdc++'s `"text" + std::string&&`) once this is inlined beside other files in a unity build.
inline std::string quoted(const std::filesystem::path& path) {
    std::string out = "\"";
    out += printable(path.string());
    out += '"';
    return out;
}

inline std::string osError(int error = errno) {
    return std::strerror(error);
}

// A temporary file in a folder holding given bytes, flushed to disk (mkstemp: an unpredictable name made
// with O_CREAT | O_EXCL; the mode a new file gets from umask), removed by SIGINT/SIGTERM/SIGHUP and by its
// destructor until released (atomic_file.cpp).
class LiveTemporary {
public:
    // Throws RuntimeError naming the folder or the file and the OS's reason.
    static LiveTemporary write(const std::filesystem::path& folder, std::string_view bytes);
    LiveTemporary(LiveTemporary&& other) noexcept;
    LiveTemporary& operator=(LiveTemporary&&) = delete;
    LiveTemporary(const LiveTemporary&) = delete;
    LiveTemporary& operator=(const LiveTemporary&) = delete;
    ~LiveTemporary();

    const std::string& path() const { return path_; }
    // Its content has its final name: renamed there (`renamed`), or hard-linked (then the temporary's own
    // name is removed). No longer removed by a signal or the destructor.
    void release(bool renamed);

private:
    LiveTemporary(std::string path, int slot) : path_(std::move(path)), slot_(slot) {}
    std::string path_;
    int slot_ = -1; // in the signal handler's table, or -1
    bool live_ = true;
};

} // namespace shadelab::detail
