// Runs the shadelab binary (SHADELAB_EXE, defined by the test target) end to end through fork/execve, never
// a shell, and captures its exit code, stdout and stderr separately. Shared by cli_test.cpp and
// hostile_test.cpp; header-only because each test executable includes it once.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

extern char** environ;

namespace shadelab::cli_test {

// A run that takes longer is hung (e.g. a demo window that opened by mistake); it is killed and fails.
inline constexpr int kTimeoutSeconds = 180;

struct Outcome {
    int exitCode = -1; // -1 when the process did not exit normally
    std::string out, err;
};

inline std::string describe(const Outcome& run) {
    return "exit code " + std::to_string(run.exitCode) + "\n--- stdout:\n" + run.out + "--- stderr:\n" +
           run.err;
}

// Display::None is for the demo's no-display path only; everything else sees the environment unchanged.
enum class Display { Inherit, None };

// The test's environment, less the display variables for Display::None, with each "NAME=value" of
// `overrides` replacing any inherited NAME.
inline std::vector<std::string> childEnvironment(Display display,
                                                 const std::vector<std::string>& overrides = {}) {
    auto nameOf = [](std::string_view entry) { return entry.substr(0, entry.find('=') + 1); };
    auto overridden = [&](std::string_view entry) {
        for (const std::string& o : overrides)
            if (nameOf(o) == nameOf(entry)) return true;
        return false;
    };
    std::vector<std::string> env;
    for (char** entry = environ; *entry != nullptr; ++entry) {
        const std::string_view text(*entry);
        if (display == Display::None &&
            (text.starts_with("DISPLAY=") || text.starts_with("WAYLAND_DISPLAY=")))
            continue;
        if (!overridden(text)) env.emplace_back(text);
    }
    env.insert(env.end(), overrides.begin(), overrides.end());
    return env;
}

inline std::vector<char*> nullTerminated(std::vector<std::string>& strings) {
    std::vector<char*> pointers;
    for (std::string& s : strings) pointers.push_back(s.data());
    pointers.push_back(nullptr);
    return pointers;
}

// Reads both pipes until the child closes them (or the deadline passes), so neither can fill and block it.
inline bool drain(int outFd, int errFd, Outcome& run) {
    pollfd fds[2] = {{outFd, POLLIN, 0}, {errFd, POLLIN, 0}};
    std::string* sinks[2] = {&run.out, &run.err};
    int open = 2;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kTimeoutSeconds);
    while (open > 0) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) return false;
        if (::poll(fds, 2, int(left.count())) < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        for (int i = 0; i < 2; ++i) {
            if (fds[i].fd < 0 || fds[i].revents == 0) continue;
            char buffer[4096];
            const ssize_t n = ::read(fds[i].fd, buffer, sizeof buffer);
            if (n > 0) {
                sinks[i]->append(buffer, std::size_t(n));
            } else if (n == 0 || errno != EINTR) {
                ::close(std::exchange(fds[i].fd, -1));
                --open;
            }
        }
    }
    return true;
}

// Runs shadelab with `args` in the folder `cwd`; stdout and stderr are captured separately. `overrides`
// ("NAME=value") change the child's environment, e.g. to take its GL driver away.
inline Outcome runShadelab(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                           Display display = Display::Inherit,
                           const std::vector<std::string>& overrides = {}) {
    std::vector<std::string> argStrings{SHADELAB_EXE};
    argStrings.insert(argStrings.end(), args.begin(), args.end());
    std::vector<std::string> envStrings = childEnvironment(display, overrides);
    const std::vector<char*> argv = nullTerminated(argStrings), envp = nullTerminated(envStrings);
    const std::string folder = cwd.string();

    Outcome run;
    int outPipe[2], errPipe[2];
    if (::pipe2(outPipe, O_CLOEXEC) != 0 || ::pipe2(errPipe, O_CLOEXEC) != 0) {
        ADD_FAILURE() << "pipe2: " << std::strerror(errno);
        return run;
    }
    const pid_t pid = ::fork();
    if (pid == 0) {
        // Only async-signal-safe calls between fork and exec; dup2 clears O_CLOEXEC on 1 and 2.
        const int devNull = ::open("/dev/null", O_RDONLY);
        if (devNull < 0 || ::dup2(devNull, 0) < 0 || ::dup2(outPipe[1], 1) < 0 || ::dup2(errPipe[1], 2) < 0 ||
            ::chdir(folder.c_str()) != 0)
            ::_exit(126);
        ::execve(argv[0], argv.data(), envp.data());
        ::_exit(127);
    }
    ::close(outPipe[1]);
    ::close(errPipe[1]);
    if (pid < 0) {
        ADD_FAILURE() << "fork: " << std::strerror(errno);
        ::close(outPipe[0]);
        ::close(errPipe[0]);
        return run;
    }
    const bool finished = drain(outPipe[0], errPipe[0], run);
    if (!finished) {
        ::kill(pid, SIGKILL);
        ::close(outPipe[0]);
        ::close(errPipe[0]);
    }
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!finished) ADD_FAILURE() << "shadelab did not finish within " << kTimeoutSeconds << " s; killed";
    if (WIFEXITED(status)) run.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) run.err += "\n[killed by signal " + std::to_string(WTERMSIG(status)) + "]";
    if (run.exitCode == 127 && run.out.empty() && run.err.empty())
        ADD_FAILURE() << "could not execute " << SHADELAB_EXE;
    return run;
}

inline void writeFile(const std::filesystem::path& path, std::string_view bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

inline std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every entry under `folder`, relative, folders with a trailing '/': a leftover temp file shows up here.
inline std::set<std::string> listing(const std::filesystem::path& folder) {
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
        std::string name = std::filesystem::relative(entry.path(), folder).string();
        if (entry.is_directory()) name += '/';
        names.insert(name);
    }
    return names;
}

} // namespace shadelab::cli_test
