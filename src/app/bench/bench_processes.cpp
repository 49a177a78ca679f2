// The process costs of `shadelab bench`: `shadelab render` from start to PNG, as a child process, against
// the same binary's --help and against /bin/true (bench/README.md).
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include "app/bench/bench_costs.h"
#include "app/process/child_process.h"
#include "shadelab/errors.h"

namespace shadelab::app {
namespace {

// A temporary folder removed with everything in it when the benchmark ends.
struct TempDir {
    std::filesystem::path path;
    TempDir() {
        std::string pattern = (std::filesystem::temp_directory_path() / "shadelab-bench-XXXXXX").string();
        if (!mkdtemp(pattern.data())) throw RuntimeError("bench: cannot create a temporary folder");
        path = pattern;
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

// Runs `args` with stdout and stderr to `log` and the parent's environment (less `unset`), and returns
// the wall time from spawn to exit. A child that cannot start or exits non-zero throws with its output.
double runProcess(const std::vector<std::string>& args, const char* unset, const std::filesystem::path& log) {
    const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (out < 0) throw RuntimeError("bench: cannot write " + log.string() + ": " + std::strerror(errno));
    const auto start = std::chrono::steady_clock::now();
    pid_t pid = 0;
    try {
        pid = startChild(args, ChildStreams{-1, out, true, unset, false}, "bench");
    } catch (...) {
        ::close(out);
        throw;
    }
    ::close(out);
    const int status = waitForChild(pid, "bench", args[0]);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (const std::string failure = childFailure(status); !failure.empty()) {
        std::string command;
        for (const std::string& a : args) command += " " + a;
        std::ifstream file(log);
        const std::string output((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        throw RuntimeError("bench:" + command + ": failed (" + failure + "); its output:\n" + output);
    }
    return seconds;
}

void registerProcess(const std::string& name,
                     const std::function<std::vector<std::string>(const TempDir&)>& args,
                     const char* unsetVariable = nullptr) {
    benchmark::RegisterBenchmark(name.c_str(),
                                 [args, unsetVariable](benchmark::State& state) {
                                     const TempDir dir;
                                     const std::vector<std::string> command = args(dir);
                                     runProcess(command, unsetVariable, dir.path / "log"); // page cache
                                     std::vector<double> ms;
                                     for (auto _ : state) {
                                         const double s =
                                             runProcess(command, unsetVariable, dir.path / "log");
                                         state.SetIterationTime(s);
                                         ms.push_back(s * 1e3);
                                     }
                                     setSpread(state, ms);
                                 })
        ->UseManualTime()
        ->Iterations(11)
        ->Unit(benchmark::kMillisecond);
}

} // namespace

std::vector<RatioSpec> registerProcessCosts(const BenchOptions& o) {
    const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
    const std::string backend(toString(o.context.backend)), api(toString(o.context.api));
    const auto render = [self, backend, api](const TempDir& dir) {
        return std::vector<std::string>{
            self,    "render", "--size", "512x512", "--backend",
            backend, "--api",  api,      "--out",   (dir.path / "x.png").string()};
    };
    // runBench disables Mesa's shader cache for the whole run; a user's second start finds it warm.
    registerProcess("process/render-512/shader-cache-off", render);
    registerProcess("process/render-512/shader-cache-warm", render, "MESA_SHADER_CACHE_DISABLE");
    registerProcess("process/help", [self](const TempDir&) {
        return std::vector<std::string>{self, "--help"};
    });
    registerProcess("process/true", [](const TempDir&) { return std::vector<std::string>{"/bin/true"}; });
    return {{"render 512 (no shader cache) / shadelab --help", "process/render-512/shader-cache-off",
             "process/help"},
            {"render 512 (warm shader cache) / shadelab --help", "process/render-512/shader-cache-warm",
             "process/help"},
            {"render 512 (warm shader cache) / /bin/true", "process/render-512/shader-cache-warm",
             "process/true"}};
}

} // namespace shadelab::app
