#include "window/process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace shadelab::window_test {
namespace {

using Clock = std::chrono::steady_clock;

std::vector<char*> nullTerminated(std::vector<std::string>& strings) {
    std::vector<char*> pointers;
    for (std::string& s : strings) pointers.push_back(s.data());
    pointers.push_back(nullptr);
    return pointers;
}

ExitStatus decode(int status) {
    ExitStatus s;
    if (WIFEXITED(status)) s.code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) s.signal = WTERMSIG(status);
    return s;
}

int openOutput(const fs::path& path) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw std::runtime_error("cannot create " + path.string() + ": " + std::strerror(errno));
    return fd;
}

} // namespace

std::optional<fs::path> findOnPath(std::string_view name) {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/local/bin:/usr/bin:/bin");
    for (std::string dir; std::getline(dirs, dir, ':');) {
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
        if (::access(candidate.c_str(), X_OK) == 0) return fs::absolute(candidate);
    }
    return std::nullopt;
}

std::vector<std::string> childEnvironment(const std::string& display) {
    std::vector<std::string> env;
    for (char** entry = environ; *entry != nullptr; ++entry) {
        const std::string_view text(*entry);
        if (!text.starts_with("DISPLAY=") && !text.starts_with("WAYLAND_DISPLAY=")) env.emplace_back(text);
    }
    if (!display.empty()) env.push_back("DISPLAY=" + display);
    return env;
}

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string ExitStatus::describe() const {
    if (signal != 0) return "killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
    if (code >= 0) return "exit code " + std::to_string(code);
    return "unknown status";
}

Child::Child(SpawnOptions options) : options_(std::move(options)) {
    if (options_.argv.empty()) throw std::runtime_error("Child: empty argv");
    name_ = fs::path(options_.argv[0]).filename().string();
    const int outFd = openOutput(options_.stdoutPath);
    int errFd = -1;
    try {
        errFd = openOutput(options_.stderrPath);
    } catch (...) {
        ::close(outFd);
        throw;
    }
    std::vector<std::string> argStrings = options_.argv, envStrings = options_.env;
    const std::vector<char*> argv = nullTerminated(argStrings), envp = nullTerminated(envStrings);
    const pid_t parent = ::getpid();
    const int fd3 = options_.fd3;

    pid_ = ::fork();
    if (pid_ == 0) {
        // Only async-signal-safe calls between fork and execve. dup2 clears O_CLOEXEC on its target; a
        // source that already is the target keeps it, so clear it by hand.
        if (::prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || ::getppid() != parent) ::_exit(125);
        const int devNull = ::open("/dev/null", O_RDONLY);
        if (devNull < 0 || ::dup2(devNull, 0) < 0 || ::dup2(outFd, 1) < 0 || ::dup2(errFd, 2) < 0)
            ::_exit(126);
        if (fd3 >= 0 && (fd3 == 3 ? ::fcntl(3, F_SETFD, 0) : ::dup2(fd3, 3)) < 0) ::_exit(126);
        ::execve(argv[0], argv.data(), envp.data());
        ::_exit(127);
    }
    const int forkErrno = errno;
    ::close(outFd);
    ::close(errFd);
    if (pid_ < 0) throw std::runtime_error("fork for " + name_ + ": " + std::strerror(forkErrno));
}

Child::~Child() {
    if (!running()) return;
    ::kill(pid_, SIGTERM);
    if (waitExit(Seconds(2))) return;
    ::kill(pid_, SIGKILL);
    waitExit(Seconds(5));
}

bool Child::running() {
    return pid_ > 0 && !waitExit(Seconds(0));
}

std::optional<ExitStatus> Child::waitExit(Seconds timeout) {
    if (status_) return status_;
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(timeout);
    for (;;) {
        int status = 0;
        const pid_t done = ::waitpid(pid_, &status, WNOHANG);
        if (done == pid_) return status_ = decode(status);
        if (done < 0 && errno != EINTR) return status_ = ExitStatus{}; // not our child any more
        if (Clock::now() >= deadline) return std::nullopt;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

std::string Child::logs() const {
    return "--- " + name_ + " stdout (" + options_.stdoutPath.string() + "):\n" + out() + "--- " + name_ +
           " stderr (" + options_.stderrPath.string() + "):\n" + err();
}

std::string ToolRun::describe(const std::vector<std::string>& argv) const {
    std::string command;
    for (const std::string& a : argv) command += (command.empty() ? "" : " ") + a;
    return "`" + command + "`: " + (timedOut ? std::string("timed out, killed") : status.describe()) +
           "\n--- stdout:\n" + out + "--- stderr:\n" + err;
}

ToolRun runTool(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                const fs::path& scratch, Seconds timeout) {
    static std::atomic<int> counter = 0;
    const std::string stem = "tool-" + std::to_string(++counter);
    ToolRun run;
    {
        Child child({argv, env, scratch / (stem + ".out"), scratch / (stem + ".err")});
        const std::optional<ExitStatus> status = child.waitExit(timeout);
        run.timedOut = !status;
        if (status) run.status = *status;
    } // a timed-out child is killed and reaped here, before its output is read
    run.out = readText(scratch / (stem + ".out"));
    run.err = readText(scratch / (stem + ".err"));
    return run;
}

} // namespace shadelab::window_test
