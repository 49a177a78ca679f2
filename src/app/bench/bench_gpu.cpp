#include "app/bench/bench_gpu.h"

#include <algorithm>

#include "shadelab/gl/loader.h"

namespace shadelab::app {

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
    warmUp(options.warmupFrames, draw);
    std::vector<double> ms;
    for (auto _ : state) {
        ms.push_back(timeFrameMs(draw));
        state.SetIterationTime(ms.back() / 1e3);
    }
    setSpread(state, ms);
}

} // namespace shadelab::app
