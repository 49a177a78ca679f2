// What every GPU benchmark of `shadelab bench` shares: one headless context, one renderer, one offscreen
// target, and GPU-synchronized per-frame timing summarized as median and 10th/90th percentiles.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "app/bench/bench.h"
#include "app/measure/frame_timing.h"
#include "shadelab/context/context.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/gl/renderer.h"

namespace shadelab::app {

// Sets the median_ms, p10_ms and p90_ms counters from per-frame times.
void setSpread(benchmark::State& state, const std::vector<double>& ms);

// A ratio of two benchmarks' medians, reported at the end of the run: numerator / denominator.
struct RatioSpec {
    std::string name, numerator, denominator; // benchmark names as registered
};

struct Gpu {
    explicit Gpu(const BenchOptions& options);
    std::unique_ptr<HeadlessContext> context;
    gl::RenderTarget target;
    gl::Renderer renderer;
    BenchOptions options;

    // Draws the warm-up frames, then one GPU-synchronized frame of `draw` per benchmark iteration.
    void timeFrames(benchmark::State& state, const std::function<void()>& draw);
};

// Each group registers its benchmarks and returns the ratios it wants reported.
std::vector<RatioSpec> registerSpecializationBenchmarks(Gpu& gpu); // bench.cpp
std::vector<RatioSpec> registerCostBenchmarks(Gpu& gpu);           // bench_costs.cpp: costs against limits

} // namespace shadelab::app
