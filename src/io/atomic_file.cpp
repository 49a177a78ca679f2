#include "shadelab/io/atomic_file.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "shadelab/errors.h"
#include "shadelab/io/text.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& path) {
    return "\"" + printable(path.string()) + "\"";
}

std::string osError(int error = errno) {
    return std::strerror(error);
}

// ---- the temporary files a signal must remove: a fixed table the handler can read without allocating ----

constexpr std::size_t kMaxLiveTemps = 16;
struct TempSlot {
    std::array<char, PATH_MAX> path{};
    std::atomic<bool> used{false};
};
std::array<TempSlot, kMaxLiveTemps> gTemps;
constexpr std::array kCleanupSignals{SIGINT, SIGTERM, SIGHUP};

int registerTemp(const std::string& path) {
    if (path.size() >= PATH_MAX) return -1;
    for (std::size_t i = 0; i < gTemps.size(); ++i) {
        TempSlot& slot = gTemps[i];
        if (slot.used.load()) continue;
        std::memcpy(slot.path.data(), path.c_str(), path.size() + 1);
        slot.used.store(true);
        return int(i);
    }
    return -1;
}

void unregisterTemp(int slot) {
    if (slot >= 0) gTemps[std::size_t(slot)].used.store(false);
}

extern "C" void removeTempsAndReraise(int signal) {
    for (TempSlot& slot : gTemps)
        if (slot.used.load()) ::unlink(slot.path.data());
    // SA_RESETHAND restored the default action; SA_NODEFER lets it act now.
    ::raise(signal);
}

// Holds SIGINT/SIGTERM/SIGHUP back for its lifetime: a signal that comes meanwhile is handled when it ends,
// so creating a temporary file and registering it for removal happen as one step for the handler.
class SignalHold {
public:
    SignalHold() {
        sigset_t held;
        sigemptyset(&held);
        for (int signal : kCleanupSignals) sigaddset(&held, signal);
        ::sigprocmask(SIG_BLOCK, &held, &previous_);
    }
    SignalHold(const SignalHold&) = delete;
    SignalHold& operator=(const SignalHold&) = delete;
    ~SignalHold() { ::sigprocmask(SIG_SETMASK, &previous_, nullptr); }

private:
    sigset_t previous_{};
};

// mkstemp creates files 0600; a new output should get the permissions fopen would have given it.
// umask can only be read by setting it, so this runs once.
mode_t newFileMode() {
    static const mode_t mode = [] {
        const mode_t mask = ::umask(0);
        ::umask(mask);
        return mode_t(0666) & ~mask;
    }();
    return mode;
}

const char* kindName(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a file";
}

// write(2) until done; false with errno set on failure.
bool writeAll(int fd, const char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        data += n;
        size -= std::size_t(n);
    }
    return true;
}

// The descriptor that a path names when it is one of this process's own: /dev/stdout, /dev/stderr,
// /dev/stdin, /dev/fd/N, /proc/self/fd/N, /proc/thread-self/fd/N, /proc/<this pid>/fd/N. Following such a
// path as a link would reach the file behind the descriptor and replace it.
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

[[noreturn]] void failWrite(std::string_view what, const fs::path& path, const std::string& reason) {
    throw RuntimeError("cannot write " + std::string(what) + " " + quoted(path) + ": " + reason);
}

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
        (void)resolveOutput(dir / file, field);
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
    if (output.empty() || output == "-" || input.empty() || input == "-") return;
    if (isSameFile(output, input))
        throw InputError(std::string(field) + ": " + quoted(output) + " is the input file " + quoted(input) +
                         "; writing it would destroy the input: choose another output path");
}

// ---- PendingOutput ----

struct PendingOutput::State {
    OutputTarget target;
    std::string what;
    std::FILE* file = nullptr;
    fs::path tempPath; // Regular: the temporary file until commit
    int slot = -1;
    char* buffer = nullptr; // WriteThrough and Stdout: the content, held in memory until commit
    std::size_t size = 0;
    bool finished = false, committed = false;

    [[noreturn]] void fail(const std::string& reason) const { failWrite(what, displayPath(), reason); }
    fs::path displayPath() const {
        return target.kind == OutputTarget::Kind::Stdout ? fs::path("standard output") : target.path;
    }

    void openTemp() {
        const fs::path dir = target.path.has_parent_path() ? target.path.parent_path() : fs::path(".");
        // A short name, so that a legal 255-byte output name still has a legal temporary beside it.
        std::string pattern = (dir / ".shadelab-XXXXXX").string();
        int fd = -1;
        {
            const SignalHold hold;
            fd = ::mkstemp(pattern.data());
            if (fd >= 0) slot = registerTemp(pattern);
        }
        if (fd < 0) fail("cannot create a temporary file in " + quoted(dir) + ": " + osError());
        tempPath = pattern;
        // An existing file keeps its mode and (where we may set it) its owner and group.
        struct stat old {};
        mode_t mode = newFileMode();
        if (::stat(target.path.c_str(), &old) == 0) {
            mode = old.st_mode & 07777;
            if (::fchown(fd, old.st_uid, old.st_gid) != 0 && ::geteuid() == 0) {
                const std::string reason = osError();
                ::close(fd);
                fail("cannot keep the owner of the existing file: " + reason);
            }
        }
        if (::fchmod(fd, mode) != 0 || !(file = ::fdopen(fd, "wb"))) {
            const std::string reason = osError();
            ::close(fd);
            fail("cannot open the temporary file: " + reason);
        }
    }

    void cleanUp() noexcept {
        if (file) std::fclose(std::exchange(file, nullptr));
        if (!tempPath.empty()) ::unlink(tempPath.c_str());
        unregisterTemp(std::exchange(slot, -1));
        tempPath.clear();
        std::free(std::exchange(buffer, nullptr));
    }
};

PendingOutput::PendingOutput(OutputTarget target, std::string_view what) : state_(std::make_unique<State>()) {
    state_->target = std::move(target);
    state_->what = what;
    if (state_->target.kind == OutputTarget::Kind::Regular) {
        try {
            state_->openTemp();
        } catch (...) {
            state_->cleanUp();
            throw;
        }
    } else {
        state_->file = ::open_memstream(&state_->buffer, &state_->size);
        if (!state_->file) state_->fail("cannot hold the output in memory: " + osError());
    }
}

PendingOutput::PendingOutput(PendingOutput&&) noexcept = default;
PendingOutput& PendingOutput::operator=(PendingOutput&&) noexcept = default;

PendingOutput::~PendingOutput() {
    if (state_) state_->cleanUp();
}

std::FILE* PendingOutput::stream() const {
    return state_->file;
}

const OutputTarget& PendingOutput::target() const {
    return state_->target;
}

void PendingOutput::finish() {
    State& s = *state_;
    if (s.finished) return;
    if (std::ferror(s.file) || std::fflush(s.file) != 0) s.fail("write error: " + osError());
    if (s.target.kind == OutputTarget::Kind::Regular && ::fsync(::fileno(s.file)) != 0)
        s.fail("fsync " + quoted(s.tempPath) + ": " + osError());
    std::FILE* file = std::exchange(s.file, nullptr);
    if (std::fclose(file) != 0) s.fail("close: " + osError());
    s.finished = true;
}

void PendingOutput::commit() {
    State& s = *state_;
    finish();
    if (s.committed) return;
    switch (s.target.kind) {
    case OutputTarget::Kind::Regular: {
        const SignalHold hold; // renamed and unregistered as one step
        if (::rename(s.tempPath.c_str(), s.target.path.c_str()) != 0)
            s.fail("cannot rename " + quoted(s.tempPath) + " over it: " + osError());
        unregisterTemp(std::exchange(s.slot, -1));
        s.tempPath.clear();
        break;
    }
    case OutputTarget::Kind::Stdout:
        if (!writeAll(STDOUT_FILENO, s.buffer, s.size)) s.fail(osError());
        break;
    case OutputTarget::Kind::Descriptor:
        if (!writeAll(s.target.descriptor, s.buffer, s.size)) s.fail(osError());
        break;
    case OutputTarget::Kind::WriteThrough: {
        // No O_CREAT, no O_TRUNC: the device or FIFO is used as it is. A FIFO waits here for its reader.
        const int fd = ::open(s.target.path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
        if (fd < 0) s.fail(osError());
        struct stat st {};
        if (::fstat(fd, &st) != 0 || !(S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode))) {
            ::close(fd);
            s.fail("it is no longer a device or FIFO; not writing through it");
        }
        const bool written = writeAll(fd, s.buffer, s.size);
        const int error = errno;
        if (::close(fd) != 0 && written) s.fail("close: " + osError());
        if (!written) s.fail(osError(error));
        break;
    }
    }
    std::free(std::exchange(s.buffer, nullptr));
    s.committed = true;
}

void commitAll(std::vector<PendingOutput>& outputs) {
    for (PendingOutput& output : outputs) output.finish();
    const SignalHold hold;
    for (PendingOutput& output : outputs) output.commit();
}

void writeFileAtomically(const fs::path& path, std::string_view what,
                         const std::function<void(std::FILE*)>& write) {
    OutputTarget target;
    try {
        target = resolveOutput(path, what);
    } catch (const InputError& e) { // the command line was checked before the work: now it is a failure
        std::string_view reason = e.what();
        if (reason.starts_with(what) && reason.substr(what.size()).starts_with(": "))
            reason.remove_prefix(what.size() + 2);
        failWrite(what, path, std::string(reason));
    }
    PendingOutput output(std::move(target), what);
    write(output.stream());
    output.commit();
}

void installOutputSignalHandlers() {
    for (int signal : kCleanupSignals) {
        struct sigaction current {};
        if (::sigaction(signal, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue; // nohup
        struct sigaction action {};
        action.sa_handler = removeTempsAndReraise;
        sigemptyset(&action.sa_mask);
        action.sa_flags = SA_RESETHAND | SA_NODEFER;
        ::sigaction(signal, &action, nullptr);
    }
}

} // namespace shadelab
