// Child processes for the window tests: fork/execve (never a shell), stdout and stderr to files, every
// wait bounded, and an owner that kills and reaps what it started, whatever happens to the test.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shadelab::window_test {

namespace fs = std::filesystem;
using Seconds = std::chrono::duration<double>;

// The absolute path of `name` on PATH, or nullopt.
std::optional<fs::path> findOnPath(std::string_view name);

// This process's environment without DISPLAY and WAYLAND_DISPLAY, plus DISPLAY=`display` when it is not
// empty: only the children see the test's X server, and GLFW cannot pick a Wayland compositor instead.
std::vector<std::string> childEnvironment(const std::string& display);

std::string readText(const fs::path& path);

// How a child ended.
struct ExitStatus {
    int code = -1;  // the exit code when it exited
    int signal = 0; // the signal that killed it, else 0
    std::string describe() const;
};

struct SpawnOptions {
    std::vector<std::string> argv; // argv[0] is an absolute path
    std::vector<std::string> env;
    fs::path stdoutPath, stderrPath;
    int fd3 = -1; // when >= 0, becomes the child's fd 3 (Xvfb -displayfd 3)
};

// A running child. The destructor sends SIGTERM, then SIGKILL if it is still there after a moment, and
// reaps it. The child also gets SIGKILL if the test process dies first (PR_SET_PDEATHSIG), so a test
// killed by the CTest timeout leaves no Xvfb behind.
class Child {
public:
    explicit Child(SpawnOptions options); // throws std::runtime_error when it cannot start
    ~Child();
    Child(const Child&) = delete;
    Child& operator=(const Child&) = delete;

    pid_t pid() const { return pid_; }
    const std::string& name() const { return name_; }
    bool running();
    // Waits up to `timeout` for the child to exit; nullopt if it is still running.
    std::optional<ExitStatus> waitExit(Seconds timeout);
    std::string out() const { return readText(options_.stdoutPath); }
    std::string err() const { return readText(options_.stderrPath); }
    std::string logs() const; // stdout and stderr, labelled, for failure messages

private:
    SpawnOptions options_;
    std::string name_;
    pid_t pid_ = -1;
    std::optional<ExitStatus> status_;
};

// A command run to completion within `timeout` (killed after it); stdout and stderr go to files in
// `scratch`. Never throws for a failing command: the caller judges the exit code.
struct ToolRun {
    ExitStatus status;
    bool timedOut = false;
    std::string out, err;
    bool ok() const { return !timedOut && status.code == 0; }
    std::string describe(const std::vector<std::string>& argv) const;
};
ToolRun runTool(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                const fs::path& scratch, Seconds timeout);

} // namespace shadelab::window_test
