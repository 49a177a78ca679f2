// Private to src/app/bench/: the parts of the cost group that registerCostBenchmarks (bench_costs.cpp)
// registers in this order. Each registers its benchmarks and returns the ratios it wants reported.
#pragma once

#include <vector>

#include "app/bench/bench.h"
#include "app/bench/bench_gpu.h"

namespace shadelab::app {

std::vector<RatioSpec> registerSphereCosts();                       // bench_sphere.cpp, on the CPU
std::vector<RatioSpec> registerFrameCosts(Gpu& gpu);                // bench_frames.cpp, limits and glmark2
std::vector<RatioSpec> registerObjectCosts(Gpu& gpu);               // bench_objects.cpp, many objects
std::vector<RatioSpec> registerProcessCosts(const BenchOptions& o); // bench_processes.cpp

} // namespace shadelab::app
