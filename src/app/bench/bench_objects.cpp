// The cost of an object in a frame: a thousand level-0 spheres (four triangles each, so the raster work is
// small and the frame is mostly the per-object work), drawn by the renderer in each mesh shading mode and,
// as the limit, by the bare loop a GL program needs for the same draws (one matrix and one draw call per
// object, one colour). Counters: the frame per object (wall, GPU-synchronized) and the CPU time of the
// drawing thread inside render() per object, which is what the renderer itself adds to the driver's work
// (llvmpipe transforms the vertices and bins the triangles in the calling thread; its rasterizer threads
// are not counted).
#include <time.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/bench/bench_costs.h"
#include "shadelab/gl/loader.h"

namespace shadelab::app {
namespace {

constexpr int kColumns = 40, kRows = 25; // 1,000 objects

// The grid of small level-0 spheres across the default camera's view, all of one material.
Scene manyObjects(const BenchOptions& o, ShadingMode mode) {
    Scene scene;
    scene.width = o.width;
    scene.height = o.height;
    scene.shading = mode;
    scene.objects.clear();
    for (int row = 0; row < kRows; ++row)
        for (int column = 0; column < kColumns; ++column) {
            SceneObject object;
            object.center = {-1.3 + 2.6 * column / (kColumns - 1), -0.8 + 1.6 * row / (kRows - 1), 0};
            object.radius = 0.025;
            object.subdivisions = 0;
            scene.objects.push_back(object);
        }
    return scene;
}

double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

// Times `draw` as registerFrame does, and adds the per-object counters: the median frame and the median
// CPU time of the drawing thread in `draw` (before the GPU finishes), each divided by the object count.
void registerObjects(Gpu& gpu, const std::string& name, std::size_t objects,
                     const std::function<void()>& draw) {
    benchmark::RegisterBenchmark(name.c_str(),
                                 [&gpu, objects, draw](benchmark::State& state) {
                                     gpu.renderer.setSpecialization(gl::Specialization::Values);
                                     gpu.renderer.setFlatGeometryShader(false);
                                     auto cpu = std::make_shared<std::vector<double>>();
                                     gpu.timeFrames(state, [cpu, draw] {
                                         const double start = threadCpuSeconds();
                                         draw();
                                         cpu->push_back(threadCpuSeconds() - start);
                                     });
                                     gl::checkGlError("bench: a timed frame of many objects");
                                     state.counters["objects"] = double(objects);
                                     state.counters["cpu_us_per_object"] =
                                         percentile(*cpu, 0.5) * 1e6 / double(objects);
                                     state.counters["frame_us_per_object"] =
                                         state.counters["median_ms"] * 1e3 / double(objects);
                                 })
        ->UseManualTime()
        ->Iterations(gpu.options.frames)
        ->Unit(benchmark::kMillisecond);
}

} // namespace

// The limit: the bare loop any GL program needs to draw these objects one by one (drawOneColour, back
// faces culled as the renderer culls them): per object one clip matrix and one draw of the level-0 mesh.
std::vector<RatioSpec> registerObjectCosts(Gpu& gpu, const std::shared_ptr<Limits>& limits) {
    std::vector<RatioSpec> ratios;
    const Scene bare = manyObjects(gpu.options, ShadingMode::Gouraud);
    const std::string limit = "frame/objects/limits/one-colour-level0";
    registerObjects(gpu, limit, bare.objects.size(), [limits, bare] { drawOneColour(*limits, bare, true); });
    for (const ShadingMode mode : kShadingModes) {
        const Scene scene = manyObjects(gpu.options, mode);
        const std::string name = "frame/objects/" + std::string(toString(mode)) + "-level0";
        registerObjects(gpu, name, scene.objects.size(),
                        [&gpu, scene] { gpu.renderer.render(scene, scene.width, scene.height); });
        ratios.push_back(
            {std::string(toString(mode)) + " 1,000 level-0 spheres: frame / one-colour loop", name, limit});
    }
    return ratios;
}

} // namespace shadelab::app
