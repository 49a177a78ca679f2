// `shadelab bench`: Google Benchmark runs of what shadelab's design choices buy, each reported as a ratio
// against a baseline measured in the same run (never as an absolute target).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "shadelab/context/context.h"

namespace shadelab::app {

struct BenchOptions {
    ContextRequest context; // --backend, --api, --egl-device
    int width = 800, height = 600;
    int frames = 40;      // timed frames per configuration, after the warm-up
    int warmupFrames = 5; // drawn but not timed: program compile, mesh upload, caches
    std::string filter;   // a regular expression over benchmark names; empty: all
    std::optional<std::filesystem::path> json;
};

int runBench(const BenchOptions& options);

} // namespace shadelab::app
