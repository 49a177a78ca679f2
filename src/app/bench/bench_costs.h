// Private to src/app/bench/: the parts of the cost group that registerCostBenchmarks (bench_costs.cpp)
// registers in this order. Each registers its benchmarks and returns the ratios it wants reported.
#pragma once

#include <memory>
#include <vector>

#include "app/bench/bench.h"
#include "app/bench/bench_gpu.h"

namespace shadelab::app {

// The frame benchmarks' limits (bench_frames.cpp): a full-screen fill and the one-colour draw, their
// programs and meshes built at first use and shared by every benchmark of the run.
struct Limits;
std::shared_ptr<Limits> makeLimits();
// Every object of `scene`, with the renderer's depth set-up and clip matrices, in one colour: the raster
// limit of a frame. The renderer culls back faces except where the near plane cuts an object open (its
// inside then shows, as in the reference); drawing them (`cullBackFaces` false) measures what that
// exception costs on a closed sphere.
void drawOneColour(Limits& limits, const Scene& scene, bool cullBackFaces);

std::vector<RatioSpec> registerSphereCosts(); // bench_sphere.cpp, on the CPU
// bench_frames.cpp, each mode against the limits, and the glmark2 scenes
std::vector<RatioSpec> registerFrameCosts(Gpu& gpu, const std::shared_ptr<Limits>& limits);
// bench_objects.cpp, a thousand objects against the one-colour draw of them
std::vector<RatioSpec> registerObjectCosts(Gpu& gpu, const std::shared_ptr<Limits>& limits);
std::vector<RatioSpec> registerProcessCosts(const BenchOptions& o); // bench_processes.cpp

} // namespace shadelab::app
