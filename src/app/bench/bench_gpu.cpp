#include "app/bench/bench_gpu.h"

#include <algorithm>
#include <chrono>

#include "shadelab/gl/loader.h"

namespace shadelab::app {

using Clock = std::chrono::steady_clock;

void setSpread(benchmark::State& state, const std::vector<double>& ms) {
    if (ms.empty()) return;
    state.counters["median_ms"] = percentile(ms, 0.5);
    state.counters["p10_ms"] = percentile(ms, 0.1);
    state.counters["p90_ms"] = percentile(ms, 0.9);
}

Gpu::Gpu(const BenchOptions& o)
    : context(makeHeadlessContext(o.context)), target(o.width, o.height), options(o) {}

void Gpu::timeFrames(benchmark::State& state, const std::function<void()>& draw) {
    target.bind();
    for (int i = 0; i < options.warmupFrames; ++i) draw();
    gl::finish();
    std::vector<double> ms;
    for (auto _ : state) {
        const auto start = Clock::now();
        draw();
        gl::finish();
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        state.SetIterationTime(seconds);
        ms.push_back(seconds * 1e3);
    }
    setSpread(state, ms);
}

} // namespace shadelab::app
