// The mesh-loading cost of `shadelab bench` (CPU): parseModel of an OBJ held in memory, about 1 MB and
// 10 MB, as MB/s of file read (DESIGN §1, "Meshes from files"). The file is the reader's usual case: a
// sphere as a latitude-longitude grid, a normal per vertex ("f a//a b//b c//c"), six decimals per number,
// as exporters write them. Wall time, so quote the figures from a quiet machine; the median of the
// repetitions is the figure to quote. The disk is not read: a cold read is the file system's cost.
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>

#include <benchmark/benchmark.h>

#include "shadelab/scene/model.h"

namespace shadelab::app {
namespace {

// A unit sphere of `rings` × 2·`rings` quads (two triangles each), its normals exact.
std::string sphereObj(int rings) {
    const int segments = 2 * rings;
    std::string text;
    char line[256]; // two face lines of six 10-digit indices at most
    for (const char* kind : {"v", "vn"})
        for (int i = 0; i <= rings; ++i)
            for (int j = 0; j < segments; ++j) {
                const double theta = std::numbers::pi * i / rings, phi = 2 * std::numbers::pi * j / segments;
                std::snprintf(line, sizeof line, "%s %.6f %.6f %.6f\n", kind, std::sin(theta) * std::cos(phi),
                              std::cos(theta), -std::sin(theta) * std::sin(phi));
                text += line;
            }
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const int a = i * segments + j + 1, b = (i + 1) * segments + j + 1,
                      c = (i + 1) * segments + (j + 1) % segments + 1,
                      d = i * segments + (j + 1) % segments + 1;
            // At a pole two corners coincide: finishModel drops that zero-area triangle.
            std::snprintf(line, sizeof line, "f %d//%d %d//%d %d//%d\nf %d//%d %d//%d %d//%d\n", a, a, b, b,
                          c, c, a, a, c, c, d, d);
            text += line;
        }
    return text;
}

// The smallest such sphere of at least `megabytes` MB (10^6 bytes), made once per size.
const std::string& objOfSize(int megabytes) {
    static std::map<int, std::string> made;
    std::string& text = made[megabytes];
    if (text.empty()) {
        // About 130 bytes per grid vertex: a "v", a "vn" and two faces.
        int rings = int(std::sqrt(megabytes * 1e6 / 260.0));
        while ((text = sphereObj(rings)).size() < std::size_t(megabytes) * 1000000) rings += 2;
    }
    return text;
}

void parseObjOfSize(benchmark::State& state) {
    const std::string& text = objOfSize(int(state.range(0)));
    std::size_t triangles = 0;
    for (auto _ : state) {
        const std::shared_ptr<const Model> model = parseModel(text, "bench.obj");
        triangles = model->mesh.triangles.size();
        benchmark::DoNotOptimize(model.get());
    }
    state.SetBytesProcessed(std::int64_t(state.iterations()) * std::int64_t(text.size()));
    state.counters["triangles"] = double(triangles);
    state.counters["file_MB"] = double(text.size()) / 1e6;
}

const bool kModelBenchmarksRegistered = [] {
    benchmark::RegisterBenchmark("model/parse_obj", parseObjOfSize)
        ->Arg(1)
        ->Arg(10)
        ->ArgName("MB")
        ->Repetitions(3)
        ->UseRealTime() // the MB/s too: wall, as the figures beside it
        ->ReportAggregatesOnly(true)
        ->Unit(benchmark::kMillisecond);
    return true;
}();

} // namespace
} // namespace shadelab::app
