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

#include "io/io_internal.h"

namespace shadelab {

namespace fs = std::filesystem;
using detail::osError;
using detail::quoted;

namespace {

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

} // namespace

namespace detail {

LiveTemporary LiveTemporary::write(const fs::path& folder, std::string_view bytes) {
    std::string path = (folder / ".shadelab-XXXXXX").string();
    int fd = -1, slot = -1;
    {
        const SignalHold hold; // created and registered as one step for the signal handler
        fd = ::mkstemp(path.data());
        if (fd < 0) throw RuntimeError("cannot create a file in " + quoted(folder) + ": " + osError());
        slot = registerTemp(path);
    }
    LiveTemporary temporary(path, slot);
    bool written =
        ::fchmod(fd, newFileMode()) == 0 && writeAll(fd, bytes.data(), bytes.size()) && ::fsync(fd) == 0;
    const int error = errno;
    if (::close(fd) != 0 || !written)
        throw RuntimeError("cannot write " + detail::quoted(fs::path(path)) + ": " +
                           osError(written ? errno : error));
    return temporary;
}

LiveTemporary::LiveTemporary(LiveTemporary&& other) noexcept
    : path_(std::move(other.path_)), slot_(other.slot_), live_(other.live_) {
    other.live_ = false;
    other.slot_ = -1;
}

LiveTemporary::~LiveTemporary() {
    if (live_) ::unlink(path_.c_str());
    unregisterTemp(slot_);
}

void LiveTemporary::release(bool renamed) {
    if (!renamed) ::unlink(path_.c_str());
    live_ = false;
    unregisterTemp(slot_);
    slot_ = -1;
}

} // namespace detail

namespace {

// The descriptor that a path names when it is one of this process's own: /dev/stdout, /dev/stderr,
// /dev/stdin, /dev/fd/N, /proc/self/fd/N, /proc/thread-self/fd/N, /proc/<this pid>/fd/N. Following such a
// path as a link would reach the file behind the descriptor and replace it.

} // namespace

[[noreturn]] void failWrite(std::string_view what, const fs::path& path, const std::string& reason) {
    throw RuntimeError("cannot write " + std::string(what) + " " + quoted(path) + ": " + reason);
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
                         const std::function<void(std::FILE*)>& write, OutputRule rule) {
    OutputTarget target;
    try {
        target = rule == OutputRule::InFolder
                     ? resolveFolderEntry(path.has_parent_path() ? path.parent_path() : fs::path("."),
                                          path.filename().string(), what)
                     : resolveOutput(path, what);
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
