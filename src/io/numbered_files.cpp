#include "shadelab/io/numbered_files.h"

#include <cstdio>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/io_internal.h"
#include "shadelab/errors.h"

namespace shadelab {

namespace fs = std::filesystem;
using detail::osError;
using detail::quoted;

namespace {

// How a final name was claimed for its temporary file.
enum class Claim {
    Taken,   // something has the name already: try the next number
    Linked,  // a hard link to the temporary now has the name (link() never replaces)
    Reserved // no hard links on this file system: an empty file made with O_CREAT | O_EXCL holds the name,
             // and the temporary is renamed over it
};

Claim claimName(const std::string& temp, const std::string& name) {
    if (::link(temp.c_str(), name.c_str()) == 0) return Claim::Linked;
    if (errno == EEXIST) return Claim::Taken;
    if (errno != EPERM && errno != EOPNOTSUPP && errno != EXDEV && errno != EMLINK && errno != ENOSYS)
        throw RuntimeError("cannot write " + quoted(fs::path(name)) + ": " + osError());
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0) {
        if (errno == EEXIST) return Claim::Taken;
        throw RuntimeError("cannot write " + quoted(fs::path(name)) + ": " + osError());
    }
    ::close(fd);
    return Claim::Reserved;
}

} // namespace

std::string writeNumberedFiles(const fs::path& folder, std::string_view prefix, int& lastNumber,
                               const std::vector<NumberedFile>& files) {
    std::vector<detail::LiveTemporary> temps;
    temps.reserve(files.size());
    for (const NumberedFile& file : files) temps.push_back(detail::LiveTemporary::write(folder, file.bytes));
    for (int tries = 0; tries < 100000; ++tries) {
        char number[16];
        std::snprintf(number, sizeof number, "%03d", ++lastNumber);
        std::string stem = (folder / (std::string(prefix) + number)).string();
        std::vector<std::pair<Claim, std::string>> claimed;
        const auto unclaim = [&] {
            for (const auto& [claim, name] : claimed) ::unlink(name.c_str()); // our own links or placeholders
        };
        bool free = true;
        try {
            for (std::size_t i = 0; i < files.size() && free; ++i) {
                const std::string name = stem + files[i].suffix;
                const Claim claim = claimName(temps[i].path(), name);
                free = claim != Claim::Taken;
                if (free) claimed.emplace_back(claim, name);
            }
            if (!free) {
                unclaim();
                continue;
            }
            for (std::size_t i = 0; i < files.size(); ++i) {
                const auto& [claim, name] = claimed[i];
                if (claim == Claim::Reserved && ::rename(temps[i].path().c_str(), name.c_str()) != 0)
                    throw RuntimeError("cannot write " + quoted(fs::path(name)) + ": " + osError());
                temps[i].release(/*renamed=*/claim == Claim::Reserved);
            }
        } catch (...) {
            unclaim();
            throw;
        }
        return stem;
    }
    throw RuntimeError("no free " + std::string(prefix) + "NNN name in " + quoted(folder));
}

} // namespace shadelab
