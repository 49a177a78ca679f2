// What an output path names and whether it may be written (shadelab/io/atomic_file.h): resolveOutput's
// rules for regular files, links, descriptors, devices and folders, and the same-file checks. Writing is
// atomic_file.cpp's.
#include "shadelab/io/atomic_file.h"

#include <array>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include "io/io_internal.h"
#include "shadelab/errors.h"

namespace shadelab {

namespace fs = std::filesystem;
using detail::osError;
using detail::quoted;

namespace {

const char* kindName(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a file";
}

// write(2) until done; false with errno set on failure.

std::optional<int> descriptorNamedBy(const fs::path& path) {
    const std::string text = path.lexically_normal().string();
    if (text == "/dev/stdin") return 0;
    if (text == "/dev/stdout") return 1;
    if (text == "/dev/stderr") return 2;
    const std::string prefixes[] = {"/dev/fd/", "/proc/self/fd/", "/proc/thread-self/fd/",
                                    "/proc/" + std::to_string(::getpid()) + "/fd/"};
    for (const std::string& prefix : prefixes) {
        if (!text.starts_with(prefix)) continue;
        const std::string number = text.substr(prefix.size());
        if (number.empty() || number.size() > 9 ||
            number.find_first_not_of("0123456789") != std::string::npos)
            return std::nullopt;
        return std::stoi(number);
    }
    return std::nullopt;
}

OutputTarget descriptorTarget(const fs::path& userPath, int fd, const std::string& name) {
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags < 0)
        throw InputError(name + ": " + quoted(userPath) + " names descriptor " + std::to_string(fd) +
                         ", which is not open; give a file name, or - for standard output");
    if ((flags & O_ACCMODE) == O_RDONLY)
        throw InputError(name + ": " + quoted(userPath) + " names descriptor " + std::to_string(fd) +
                         ", which is open for reading only; give a file name, or - for standard output");
    struct stat st {};
    if (::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode))
        throw InputError(name + ": " + quoted(userPath) + " names descriptor " + std::to_string(fd) +
                         ", which is a directory; give a file name, or - for standard output");
    return {OutputTarget::Kind::Descriptor, userPath, name, fd};
}

// fs.protected_symlinks: in a sticky world-writable folder (/tmp), the kernel follows a link only for its
// owner or the folder's owner, so that nobody can plant a link there for another user to write through.
void refuseUnprotectedLink(const fs::path& link, const struct stat& linkStat, const std::string& name) {
    const fs::path folder = link.has_parent_path() ? link.parent_path() : fs::path(".");
    struct stat st {};
    if (::stat(folder.c_str(), &st) != 0) return;
    const bool stickyWorldWritable = (st.st_mode & S_ISVTX) && (st.st_mode & S_IWOTH);
    if (!stickyWorldWritable || linkStat.st_uid == ::geteuid() || linkStat.st_uid == st.st_uid) return;
    throw InputError(name + ": " + quoted(link) + " is a symbolic link of uid " +
                     std::to_string(linkStat.st_uid) + " in the sticky world-writable folder " +
                     quoted(folder) +
                     ", which the kernel (fs.protected_symlinks) would not follow for you; remove the link "
                     "or choose another path");
}

// The caller must be able to replace an existing file and to create the temporary file beside it.
void refuseUnwritable(const fs::path& path, const fs::path& folder, const std::string& name) {
    if (::faccessat(AT_FDCWD, path.c_str(), W_OK, AT_EACCESS) != 0 && errno != ENOENT) {
        const std::string reason = osError();
        struct stat st {};
        std::array<char, 8> mode{'?'};
        if (::stat(path.c_str(), &st) == 0)
            std::snprintf(mode.data(), mode.size(), "%04o", st.st_mode & 07777u);
        throw InputError(name + ": " + quoted(path) + " exists and you may not write it (mode " +
                         mode.data() + ": " + reason + "); make it writable or choose another path");
    }
    if (::faccessat(AT_FDCWD, folder.c_str(), W_OK | X_OK, AT_EACCESS) != 0)
        throw InputError(name + ": cannot create files in the folder " + quoted(folder) + " (" + osError() +
                         "): the output is written beside its name and renamed; choose another folder");
}

} // namespace

OutputTarget resolveOutput(const fs::path& userPath, std::string_view field) {
    const std::string name(field);
    if (userPath.empty())
        throw InputError(name + ": the output path is empty; give a file name such as out.png, or - for "
                                "standard output");
    if (userPath == "-") return {OutputTarget::Kind::Stdout, {}, name};
    fs::path path = userPath;
    for (int hops = 0;; ++hops) {
        if (hops > 40)
            throw InputError(name + ": " + quoted(userPath) +
                             " is a loop of symbolic links; give a path that ends at a file");
        if (path.is_absolute())
            if (const std::optional<int> fd = descriptorNamedBy(path))
                return descriptorTarget(userPath, *fd, name);
        struct stat st {};
        if (::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
            refuseUnprotectedLink(path, st, name);
            std::array<char, PATH_MAX> buffer{};
            const ssize_t n = ::readlink(path.c_str(), buffer.data(), buffer.size() - 1);
            if (n < 0) throw InputError(name + ": cannot read the link " + quoted(path) + ": " + osError());
            const fs::path next(std::string(buffer.data(), std::size_t(n)));
            path = next.is_absolute() ? next : path.parent_path() / next;
            continue;
        }
        if (::stat(path.c_str(), &st) == 0) {
            if (S_ISREG(st.st_mode)) {
                refuseUnwritable(path, path.has_parent_path() ? path.parent_path() : fs::path("."), name);
                return {OutputTarget::Kind::Regular, path, name};
            }
            if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode))
                return {OutputTarget::Kind::WriteThrough, path, name};
            throw InputError(name + ": " + quoted(userPath) + " is " + kindName(st.st_mode) +
                             "; give a file name such as out.png, a character device or FIFO, or - for "
                             "standard output");
        }
        if (errno != ENOENT && errno != ENOTDIR)
            throw InputError(name + ": cannot use " + quoted(userPath) + ": " + osError());
        break; // a new file
    }
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    struct stat st {};
    if (::stat(folder.c_str(), &st) != 0) {
        if (errno == ENOTDIR)
            throw InputError(name + ": a part of " + quoted(folder) +
                             " is a file, not a folder; choose a path inside a folder");
        throw InputError(name + ": the folder " + quoted(folder) +
                         " does not exist; create it first or choose another path");
    }
    if (!S_ISDIR(st.st_mode))
        throw InputError(name + ": " + quoted(folder) +
                         " is a file, not a folder; choose a path inside a folder");
    refuseUnwritable(path, folder, name);
    return {OutputTarget::Kind::Regular, path, name};
}

OutputTarget resolveFolderEntry(const fs::path& dir, const std::string& name, std::string_view field) {
    const std::string label(field);
    const fs::path path = dir / name;
    struct stat st {};
    if (::lstat(path.c_str(), &st) != 0) {
        if (errno != ENOENT) throw InputError(label + ": cannot use " + quoted(path) + ": " + osError());
        refuseUnwritable(path, dir, label);
        return {OutputTarget::Kind::Regular, path, label};
    }
    if (S_ISREG(st.st_mode)) {
        refuseUnwritable(path, dir, label);
        return {OutputTarget::Kind::Regular, path, label};
    }
    const std::string kind = S_ISLNK(st.st_mode)    ? "a symbolic link"
                             : S_ISFIFO(st.st_mode) ? "a FIFO"
                             : S_ISCHR(st.st_mode)  ? "a character device"
                             : S_ISDIR(st.st_mode)  ? "a folder"
                                                    : std::string(kindName(st.st_mode));
    throw InputError(label + ": " + quoted(path) + " is " + kind + "; the files written into " + label +
                     " are created inside it and replace only a regular file, never through a link: remove " +
                     quoted(path) + " or give another folder");
}

void refuseStandardOutputAlias(const fs::path& out, std::string_view field, std::string_view carries,
                               std::string_view example) {
    const OutputTarget target = resolveOutput(out, field);
    struct stat stdoutStat {};
    const bool stdoutOpen = ::fstat(STDOUT_FILENO, &stdoutStat) == 0;
    bool alias = target.kind == OutputTarget::Kind::Stdout ||
                 (target.kind == OutputTarget::Kind::Descriptor && target.descriptor == STDOUT_FILENO);
    struct stat st {};
    const bool opened =
        target.kind == OutputTarget::Kind::Descriptor
            ? ::fstat(target.descriptor, &st) == 0
            : target.kind != OutputTarget::Kind::Stdout && ::stat(target.path.c_str(), &st) == 0;
    // Another name for what descriptor 1 is open on: /dev/fd/3 after 3>&1, the file of `> out.png`, the
    // FIFO standard output feeds. The null device takes both streams and loses nothing by it.
    const bool nullDevice = S_ISCHR(st.st_mode) && st.st_rdev == makedev(1, 3);
    if (opened && stdoutOpen && !nullDevice && st.st_dev == stdoutStat.st_dev &&
        st.st_ino == stdoutStat.st_ino)
        alias = true;
    if (!alias) return;
    const std::string shown = out == "-" ? std::string("-") : quoted(out);
    throw InputError(std::string(field) + ": " + shown + " is standard output, which carries " +
                     std::string(carries) + "; the two would mix: write to a file (" + std::string(field) +
                     " " + std::string(example) + ")");
}

bool isSameFile(const fs::path& a, const fs::path& b) {
    struct stat sa {
    }, sb{};
    if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

void prepareOutputFolder(const fs::path& dir, std::string_view field, const std::vector<std::string>& names,
                         const std::vector<fs::path>& inputs) {
    const std::string name(field);
    if (dir.empty()) throw InputError(name + ": the folder name is empty; give a folder such as slides");
    const std::string shown = "\"" + printable(dir.string()) + "\"";
    std::error_code error;
    if (fs::exists(dir, error) && !fs::is_directory(dir, error))
        throw InputError(name + ": " + shown + " exists and is not a folder; give a folder for the files");
    fs::create_directories(dir, error);
    if (error)
        throw InputError(name + ": cannot create the folder " + shown + ": " + error.message() +
                         "; choose a folder you can write");
    for (const std::string& file : names) {
        (void)resolveFolderEntry(dir, file, field);
        for (const fs::path& input : inputs) refuseOverwritingInput(dir / file, field, input);
    }
    // The probe file lives only between mkstemp and unlink: SIGINT/TERM/HUP are held back meanwhile, so an
    // interrupt cannot leave it behind (it is delivered at once after the unlink).
    sigset_t held, previous;
    sigemptyset(&held);
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&held, sig);
    ::sigprocmask(SIG_BLOCK, &held, &previous);
    std::string probe = (dir / ".shadelab-XXXXXX").string();
    const int fd = ::mkstemp(probe.data());
    const int code = errno;
    if (fd >= 0) {
        ::close(fd);
        ::unlink(probe.c_str());
    }
    ::sigprocmask(SIG_SETMASK, &previous, nullptr);
    if (fd < 0) {
        const std::string reason = std::strerror(code);
        if (code == EACCES || code == EPERM || code == EROFS)
            throw InputError(name + ": cannot write in the folder " + shown + ": " + reason +
                             "; choose a folder you can write");
        throw RuntimeError("cannot write in the folder " + shown + ": " + reason);
    }
}

void refuseOverwritingInput(const fs::path& output, std::string_view field, const fs::path& input) {
    if (output.empty() || input.empty() || input == "-") return;
    if (output == "-") { // standard output redirected onto the input: `--out - >> scene.json`
        struct stat out {
        }, in{};
        if (::fstat(STDOUT_FILENO, &out) == 0 && ::stat(input.c_str(), &in) == 0 && S_ISREG(out.st_mode) &&
            out.st_dev == in.st_dev && out.st_ino == in.st_ino)
            throw InputError(std::string(field) + ": - (standard output) is the input file " + quoted(input) +
                             "; writing it would destroy the input: choose another output path");
        return;
    }
    if (isSameFile(output, input))
        throw InputError(std::string(field) + ": " + quoted(output) + " is the input file " + quoted(input) +
                         "; writing it would destroy the input: choose another output path");
}

} // namespace shadelab
