// The teapot-generation cost of `shadelab bench` (CPU): buildTeapot per level, 2 to 8 (DESIGN §1, "The
// teapot"). Registered when the program starts, beside the sphere's build (bench_sphere.cpp); wall time,
// so quote the figures from a quiet machine. Each run is one build into fresh arrays (page faults
// included, as a scene load pays them); the median of the repetitions is the figure to quote.
#include <string>

#include <benchmark/benchmark.h>

#include "shadelab/geometry/teapot.h"

namespace shadelab::app {
namespace {

void buildTeapotLevel(benchmark::State& state) {
    const int level = int(state.range(0));
    for (auto _ : state) benchmark::DoNotOptimize(buildTeapot(level).positions.data());
    state.counters["triangles"] = double(teapotTriangleCount(level));
}

const bool kTeapotBenchmarksRegistered = [] {
    benchmark::RegisterBenchmark("teapot/build", buildTeapotLevel)
        ->DenseRange(2, kMaxTeapotLevel)
        ->ArgName("level")
        ->Repetitions(3)
        ->ReportAggregatesOnly(true)
        ->Unit(benchmark::kMillisecond);
    return true;
}();

} // namespace
} // namespace shadelab::app
