// `shadelab bench`: what shadelab's work costs against the limits of this machine, each limit
// measured in the same run — sphere generation against memcpy of its output bytes and against the
// lecture's naive recursion; each shading mode's frame against a full-screen fill and against a one-colour
// draw of the same sphere; a thousand small spheres against the bare draw loop; `shadelab render` from
// start to PNG against an empty process start — and the scene bench/compare_glmark2.sh sets beside
// glmark2's `shading` scenes. Each part is a file of its own: bench_sphere.cpp, bench_frames.cpp,
// bench_objects.cpp and bench_processes.cpp.
#include "app/bench/bench_costs.h"

#include <utility>

namespace shadelab::app {

std::vector<RatioSpec> registerCostBenchmarks(Gpu& gpu) {
    std::vector<RatioSpec> ratios = registerSphereCosts();
    const std::shared_ptr<Limits> limits = makeLimits();
    for (RatioSpec& r : registerFrameCosts(gpu, limits)) ratios.push_back(std::move(r));
    for (RatioSpec& r : registerObjectCosts(gpu, limits)) ratios.push_back(std::move(r));
    for (RatioSpec& r : registerProcessCosts(gpu.options)) ratios.push_back(std::move(r));
    return ratios;
}

} // namespace shadelab::app
