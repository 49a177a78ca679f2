// The demo's screenshot files (S): written to temporaries nobody can predict, then given the first free
// shadelab-NNN names without opening or replacing anything already in the folder.
#include "app/shells/screenshot_files.h"

#include <cerrno>
#include <cstdio>
#include <stdexcept>
#include <system_error>
#include <tuple>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace shadelab::app {
namespace {

// How a screenshot's final name was claimed for its temporary file.
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
        throw std::runtime_error(name + ": " + std::generic_category().message(errno));
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0) {
        if (errno == EEXIST) return Claim::Taken;
        throw std::runtime_error(name + ": " + std::generic_category().message(errno));
    }
    ::close(fd);
    return Claim::Reserved;
}

} // namespace

std::string writeTemporary(const std::filesystem::path& folder, std::string_view bytes) {
    std::string path = (folder / ".shadelab-XXXXXX").string();
    const int fd = ::mkstemp(path.data());
    if (fd < 0)
        throw std::runtime_error("cannot create a file in " + folder.string() + ": " +
                                 std::generic_category().message(errno));
    const mode_t mask = ::umask(0);
    ::umask(mask);
    bool written = ::fchmod(fd, 0666 & ~mask) == 0;
    for (std::size_t done = 0; written && done < bytes.size();) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        written = n > 0;
        if (written) done += std::size_t(n);
    }
    written = written && ::fsync(fd) == 0;
    const int error = errno;
    if (::close(fd) != 0 || !written) {
        ::unlink(path.c_str());
        throw std::runtime_error(path + ": " + std::generic_category().message(written ? errno : error));
    }
    return path;
}

std::string claimFreeStem(const std::filesystem::path& folder, int& lastNumber, const std::string& tempJson,
                          const std::string& tempPng) {
    for (int tries = 0; tries < 100000; ++tries) {
        char name[32];
        std::snprintf(name, sizeof name, "shadelab-%03d", ++lastNumber);
        std::string stem = (folder / name).string();
        const std::string json = stem + ".json", png = stem + ".png";
        const Claim jsonClaim = claimName(tempJson, json);
        if (jsonClaim == Claim::Taken) continue;
        const Claim pngClaim = claimName(tempPng, png);
        if (pngClaim == Claim::Taken) {
            ::unlink(json.c_str()); // our own link or placeholder
            continue;
        }
        for (const auto& [claim, temp, target] :
             {std::tuple{jsonClaim, &tempJson, &json}, std::tuple{pngClaim, &tempPng, &png}}) {
            if (claim == Claim::Linked)
                ::unlink(temp->c_str());
            else if (::rename(temp->c_str(), target->c_str()) != 0)
                throw std::runtime_error(*target + ": " + std::generic_category().message(errno));
        }
        return stem;
    }
    throw std::runtime_error("no free shadelab-NNN name in " + folder.string());
}

} // namespace shadelab::app
