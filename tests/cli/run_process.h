// Runs the shadelab binary (SHADELAB_EXE, defined by the test target, or SHADELAB_TEST_EXE from the
// environment) end to end through fork/execve, never a shell, and captures its exit code, stdout and stderr
// separately. Shared by the tests of tests/cli/; header-only because each test executable includes it once.
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
#include <cstdlib>
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
    bool started = false; // false: the child failed before exec (run.err says where); the test has failed
};

// The binary under test: SHADELAB_TEST_EXE when set (scripts/test.sh points it at a copy in a folder only
// root can enter, as a clone in /root is), otherwise the one this build made.
inline std::string shadelabExe() {
    const char* chosen = std::getenv("SHADELAB_TEST_EXE");
    return chosen != nullptr && *chosen != '\0' ? std::string(chosen) : std::string(SHADELAB_EXE);
}

// A copy of the binary that every user can execute, whatever the modes of the checkout's parents (a clone
// in /root, mode 0700, cannot be entered by nobody): a folder of its own under /tmp, mode 0755, removed
// when the test process exits. The binary embeds its shaders, fonts and scenes, so it needs nothing else.
inline const std::string& shadelabExeForAnyUser() {
    struct Copy {
        std::filesystem::path folder, exe;
        std::string error;
        Copy() {
            char pattern[] = "/tmp/shadelab-exe-XXXXXX";
            if (::mkdtemp(pattern) == nullptr) {
                error = std::string("mkdtemp /tmp/shadelab-exe-XXXXXX: ") + std::strerror(errno);
                return;
            }
            folder = pattern;
            exe = folder / "shadelab";
            std::error_code failed;
            std::filesystem::copy_file(shadelabExe(), exe, failed);
            if (!failed) {
                using std::filesystem::perms;
                std::filesystem::permissions(folder,
                                             perms::owner_all | perms::group_read | perms::group_exec |
                                                 perms::others_read | perms::others_exec,
                                             failed);
            }
            if (failed) error = "copying " + shadelabExe() + " to " + exe.string() + ": " + failed.message();
        }
        ~Copy() {
            std::error_code ignored;
            if (!folder.empty()) std::filesystem::remove_all(folder, ignored);
        }
    };
    static const Copy copy;
    if (!copy.error.empty()) ADD_FAILURE() << copy.error;
    static const std::string path = copy.exe.string();
    return path;
}

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

// Reads `fd` (a pipe, or a FIFO opened O_RDONLY | O_NONBLOCK before its writer starts) until every writer
// has closed it, appending to `bytes`. False when `limit` passes first: the caller fails naming what it
// waited for, rather than waiting forever on a writer that never came or never closed.
inline bool readToEndWithin(int fd, std::chrono::seconds limit, std::string& bytes) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        pollfd poller{fd, POLLIN, 0};
        if (::poll(&poller, 1, 100) < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        if (poller.revents & POLLIN) {
            char buffer[65536];
            const ssize_t n = ::read(fd, buffer, sizeof buffer);
            if (n > 0) bytes.append(buffer, std::size_t(n));
            if (n == 0) return true;
            if (n < 0 && errno != EINTR && errno != EAGAIN) return false;
            continue;
        }
        // Linux reports POLLHUP on a FIFO's read end only once a writer has opened it and all have closed.
        if (poller.revents & (POLLHUP | POLLERR)) return true;
    }
    return false;
}

// How runWith starts the child and watches it.
struct RunOptions {
    std::vector<std::string> environment; // "NAME=value" each; empty: the test's own environment
    std::optional<uid_t> user;            // run as this user (and `group`), from root
    gid_t group = 65534;                  // nogroup
    std::optional<std::string> stdinText; // written to its standard input (small); otherwise /dev/null
    std::optional<std::filesystem::path> stdoutPath; // its standard output goes there; otherwise captured
    bool stdoutAppends = false;                      // stdoutPath opened O_APPEND, as `>>` does
    std::function<bool()> signalWhen; // polled every 2 ms; when it is first true, `signal` is sent
    int signal = 0;
    std::chrono::seconds timeout{kTimeoutSeconds}; // then it is killed and the test fails
    rlim_t addressSpace = RLIM_INFINITY;           // RLIMIT_AS for the child, as `ulimit -v` sets it
    std::optional<std::string> program;            // run this instead of shadelab (args follow it)
};

// What a child that failed between fork and exec tells its parent, through a close-on-exec pipe that stays
// empty when exec succeeds.
struct StartFailure {
    enum Step : int { Redirect, User, Folder, Limit, Exec } step;
    int error; // errno
};

inline std::string describe(const StartFailure& failure, const std::string& program) {
    static constexpr const char* kSteps[] = {"redirecting its standard streams", "dropping to the test user",
                                             "entering its working folder", "setting its memory limit",
                                             "executing"};
    return "could not start " + program + ": " + kSteps[failure.step] +
           " failed: " + std::strerror(failure.error);
}

// Runs shadelab with `args` in the folder `cwd` through fork/execve (never a shell); stdout and stderr are
// read as they come, so neither pipe can fill and block it.
inline Outcome runWith(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                       const RunOptions& options = {}) {
    std::vector<std::string> argStrings{options.program ? *options.program
                                        : options.user  ? shadelabExeForAnyUser()
                                                        : shadelabExe()};
    argStrings.insert(argStrings.end(), args.begin(), args.end());
    std::vector<std::string> envStrings =
        options.environment.empty() ? childEnvironment(Display::Inherit) : options.environment;
    const std::vector<char*> argv = nullTerminated(argStrings), envp = nullTerminated(envStrings);
    const std::string folder = cwd.string();
    const std::string stdoutPath = options.stdoutPath ? options.stdoutPath->string() : std::string();

    Outcome run;
    int outPipe[2], errPipe[2], inPipe[2], startPipe[2];
    if (::pipe2(outPipe, O_CLOEXEC) != 0 || ::pipe2(errPipe, O_CLOEXEC) != 0 ||
        ::pipe2(inPipe, O_CLOEXEC) != 0 || ::pipe2(startPipe, O_CLOEXEC) != 0) {
        ADD_FAILURE() << "pipe2: " << std::strerror(errno);
        return run;
    }
    const pid_t pid = ::fork();
    if (pid == 0) {
        // Only async-signal-safe calls between fork and exec; dup2 clears O_CLOEXEC on 0, 1 and 2.
        auto fail = [&](StartFailure::Step step) {
            const StartFailure failure{step, errno};
            [[maybe_unused]] const ssize_t ignored = ::write(startPipe[1], &failure, sizeof failure);
            ::_exit(127);
        };
        const int in = options.stdinText ? inPipe[0] : ::open("/dev/null", O_RDONLY);
        const int out = options.stdoutPath
                            ? ::open(stdoutPath.c_str(), O_WRONLY | (options.stdoutAppends ? O_APPEND : 0))
                            : outPipe[1];
        if (in < 0 || out < 0 || ::dup2(in, 0) < 0 || ::dup2(out, 1) < 0 || ::dup2(errPipe[1], 2) < 0)
            fail(StartFailure::Redirect);
        if (options.user &&
            (::setgroups(0, nullptr) != 0 || ::setresgid(options.group, options.group, options.group) != 0 ||
             ::setresuid(*options.user, *options.user, *options.user) != 0))
            fail(StartFailure::User);
        if (::chdir(folder.c_str()) != 0) fail(StartFailure::Folder);
        // The signal the test sends acts as it would from a terminal, whatever the test runner inherited:
        // a shell's background job (`cmd &`) starts with SIGINT ignored, and shadelab keeps an ignored
        // signal ignored (as nohup asks).
        if (options.signal != 0) ::signal(options.signal, SIG_DFL);
        const rlimit limit{options.addressSpace, options.addressSpace};
        if (options.addressSpace != RLIM_INFINITY && ::setrlimit(RLIMIT_AS, &limit) != 0)
            fail(StartFailure::Limit);
        ::execve(argv[0], argv.data(), envp.data());
        fail(StartFailure::Exec);
    }
    ::close(outPipe[1]);
    ::close(errPipe[1]);
    ::close(inPipe[0]);
    ::close(startPipe[1]);
    auto closeAll = [&] {
        for (int fd : {outPipe[0], errPipe[0], inPipe[1], startPipe[0]}) ::close(fd);
    };
    if (pid < 0) {
        ADD_FAILURE() << "fork: " << std::strerror(errno);
        closeAll();
        return run;
    }
    // Empty at exec (close-on-exec), or the step that failed: a child that never started fails the test
    // now, before anything waits on what it would have done.
    StartFailure failure{};
    ssize_t got = 0;
    while ((got = ::read(startPipe[0], &failure, sizeof failure)) < 0 && errno == EINTR) {
    }
    ::close(std::exchange(startPipe[0], -1));
    if (got == ssize_t(sizeof failure)) {
        closeAll();
        int status = 0;
        while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        run.err = describe(failure, argStrings[0]);
        ADD_FAILURE() << run.err;
        return run;
    }
    run.started = true;
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
    // Both pipes are closed: the child has exited, or closed them and runs on; the same deadline holds.
    int status = 0;
    pid_t waited = 0;
    while ((waited = ::waitpid(pid, &status, WNOHANG)) == 0 && std::chrono::steady_clock::now() < deadline)
        ::usleep(2000);
    if (waited == 0) {
        ::kill(pid, SIGKILL);
        ADD_FAILURE() << argStrings[0] << " closed its output but did not exit within "
                      << options.timeout.count() << " s; killed";
    }
    while (waited <= 0 && (waited = ::waitpid(pid, &status, 0)) < 0 && errno == EINTR) {
    }
    if (WIFEXITED(status)) run.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) {
        run.signal = WTERMSIG(status);
        run.err += "\n[killed by signal " + std::to_string(run.signal) + "]";
    }
    if (options.signalWhen && !signalled) ADD_FAILURE() << "the condition for sending the signal never came";
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
