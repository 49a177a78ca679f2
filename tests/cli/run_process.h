// Runs the shadelab binary (SHADELAB_EXE, defined by the test target) end to end through fork/execve, never
// a shell, and captures its exit code, stdout and stderr separately. Shared by cli_test.cpp and
// hostile_test.cpp; header-only because each test executable includes it once.
#pragma once

#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
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
    int signal = 0;    // the signal that ended it, if one did
    std::string out, err;
};

inline std::string describe(const Outcome& run) {
    const bool binary = run.out.find('\0') != std::string::npos || run.out.starts_with("\x89PNG");
    return "exit code " + std::to_string(run.exitCode) + "\n--- stdout:\n" +
           (binary ? "(" + std::to_string(run.out.size()) + " bytes of binary)\n" : run.out) +
           "--- stderr:\n" + run.err;
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

// How runWith starts the child and watches it.
struct RunOptions {
    std::vector<std::string> environment; // "NAME=value" each; empty: the test's own environment
    std::optional<uid_t> user;            // run as this user (and `group`), from root
    gid_t group = 65534;                  // nogroup
    std::optional<std::string> stdinText; // written to its standard input (small); otherwise /dev/null
    std::optional<std::filesystem::path> stdoutPath; // its standard output goes there; otherwise captured
    std::function<bool()> signalWhen; // polled every 2 ms; when it is first true, `signal` is sent
    int signal = 0;
    std::chrono::seconds timeout{kTimeoutSeconds}; // then it is killed and the test fails
    rlim_t addressSpace = RLIM_INFINITY;           // RLIMIT_AS for the child, as `ulimit -v` sets it
    std::optional<std::string> program;            // run this instead of shadelab (args follow it)
};

// Runs shadelab with `args` in the folder `cwd` through fork/execve (never a shell); stdout and stderr are
// read as they come, so neither pipe can fill and block it.
inline Outcome runWith(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                       const RunOptions& options = {}) {
    std::vector<std::string> argStrings{options.program ? *options.program : std::string(SHADELAB_EXE)};
    argStrings.insert(argStrings.end(), args.begin(), args.end());
    std::vector<std::string> envStrings =
        options.environment.empty() ? childEnvironment(Display::Inherit) : options.environment;
    const std::vector<char*> argv = nullTerminated(argStrings), envp = nullTerminated(envStrings);
    const std::string folder = cwd.string();
    const std::string stdoutPath = options.stdoutPath ? options.stdoutPath->string() : std::string();

    Outcome run;
    int outPipe[2], errPipe[2], inPipe[2];
    if (::pipe2(outPipe, O_CLOEXEC) != 0 || ::pipe2(errPipe, O_CLOEXEC) != 0 ||
        ::pipe2(inPipe, O_CLOEXEC) != 0) {
        ADD_FAILURE() << "pipe2: " << std::strerror(errno);
        return run;
    }
    const pid_t pid = ::fork();
    if (pid == 0) {
        // Only async-signal-safe calls between fork and exec; dup2 clears O_CLOEXEC on 0, 1 and 2.
        const int in = options.stdinText ? inPipe[0] : ::open("/dev/null", O_RDONLY);
        const int out = options.stdoutPath ? ::open(stdoutPath.c_str(), O_WRONLY) : outPipe[1];
        if (in < 0 || out < 0 || ::dup2(in, 0) < 0 || ::dup2(out, 1) < 0 || ::dup2(errPipe[1], 2) < 0)
            ::_exit(126);
        if (options.user &&
            (::setgroups(0, nullptr) != 0 || ::setresgid(options.group, options.group, options.group) != 0 ||
             ::setresuid(*options.user, *options.user, *options.user) != 0))
            ::_exit(125);
        if (::chdir(folder.c_str()) != 0) ::_exit(124);
        const rlimit limit{options.addressSpace, options.addressSpace};
        if (options.addressSpace != RLIM_INFINITY && ::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(123);
        ::execve(argv[0], argv.data(), envp.data());
        ::_exit(127);
    }
    ::close(outPipe[1]);
    ::close(errPipe[1]);
    ::close(inPipe[0]);
    if (pid < 0) {
        ADD_FAILURE() << "fork: " << std::strerror(errno);
        ::close(outPipe[0]);
        ::close(errPipe[0]);
        ::close(inPipe[1]);
        return run;
    }
    if (options.stdinText && ::write(inPipe[1], options.stdinText->data(), options.stdinText->size()) < 0)
        ADD_FAILURE() << "write to stdin: " << std::strerror(errno);
    ::close(inPipe[1]);

    pollfd fds[2] = {{outPipe[0], POLLIN, 0}, {errPipe[0], POLLIN, 0}};
    std::string* sinks[2] = {&run.out, &run.err};
    int open = 2;
    bool signalled = false;
    const auto deadline = std::chrono::steady_clock::now() + options.timeout;
    while (open > 0 && std::chrono::steady_clock::now() < deadline) {
        if (options.signalWhen && !signalled && options.signalWhen()) {
            ::kill(pid, options.signal);
            signalled = true;
        }
        if (::poll(fds, 2, options.signalWhen ? 2 : 100) < 0 && errno != EINTR) break;
        for (int i = 0; i < 2; ++i) {
            if (fds[i].fd < 0 || fds[i].revents == 0) continue;
            char buffer[65536];
            const ssize_t n = ::read(fds[i].fd, buffer, sizeof buffer);
            if (n > 0) {
                sinks[i]->append(buffer, std::size_t(n));
            } else if (n == 0 || errno != EINTR) {
                ::close(std::exchange(fds[i].fd, -1));
                --open;
            }
        }
    }
    if (open > 0) {
        ::kill(pid, SIGKILL);
        ADD_FAILURE() << argStrings[0] << " did not finish within " << options.timeout.count()
                      << " s; killed";
    }
    for (pollfd& fd : fds)
        if (fd.fd >= 0) ::close(fd.fd);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFEXITED(status)) run.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) {
        run.signal = WTERMSIG(status);
        run.err += "\n[killed by signal " + std::to_string(run.signal) + "]";
    }
    if (options.signalWhen && !signalled) ADD_FAILURE() << "the condition for sending the signal never came";
    if (run.exitCode == 127 && run.out.empty() && run.err.empty())
        ADD_FAILURE() << "could not execute " << argStrings[0];
    return run;
}

// Runs shadelab with `args` in the folder `cwd`; stdout and stderr are captured separately. `overrides`
// ("NAME=value") change the child's environment, e.g. to take its GL driver away.
inline Outcome runShadelab(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                           Display display = Display::Inherit,
                           const std::vector<std::string>& overrides = {}) {
    RunOptions options;
    options.environment = childEnvironment(display, overrides);
    return runWith(args, cwd, options);
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
