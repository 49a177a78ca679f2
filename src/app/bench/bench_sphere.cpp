// The sphere-generation costs of `shadelab bench` (CPU): SphereBuilder and buildSphere against memcpy of
// their output bytes and against the lecture's naive recursion, level 0 to 9 (bench/README.md).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

#include "app/bench/bench_costs.h"
#include "shadelab/geometry/sphere.h"

namespace shadelab::app {
namespace {

double wallSeconds() {
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Wall time, as memcpy's below; so quote these figures from a quiet machine, as the frame times. One
// iteration repeats `work` for about 2 ms so that the clock's own cost vanishes at level 0; median_ms is the
// time of one call.
void timeCpu(benchmark::State& state, const std::function<void()>& work) {
    const double first = wallSeconds();
    work(); // also the warm-up
    const double once = wallSeconds() - first;
    const int repeats = std::clamp(int(std::ceil(2e-3 / std::max(once, 1e-9))), 1, 1 << 16);
    std::vector<double> ms;
    for (auto _ : state) {
        const double start = wallSeconds();
        for (int i = 0; i < repeats; ++i) work();
        const double seconds = (wallSeconds() - start) / repeats;
        state.SetIterationTime(seconds);
        ms.push_back(seconds * 1e3);
    }
    setSpread(state, ms);
}

// The bytes buildSphere leaves behind: its four arrays as the mesh holds them.
std::size_t outputBytes(const SphereMesh& mesh) {
    return (mesh.positions.size() + mesh.faceNormals.size() + mesh.vertexNormals.size()) *
               sizeof(glm::dvec3) +
           mesh.triangles.size() * sizeof(glm::uvec3);
}

// The lecture's generator (lecture notes, "Coding": Sphere → tetrahedron → divideTriangle → triangle),
// kept as the baseline: every leaf triangle pushes three new vertices, none shared, one push at a time,
// each with the face normal.
struct NaiveSphere {
    std::vector<glm::dvec3> positions, normals;
};

void naiveTriangle(NaiveSphere& s, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 normal = glm::normalize(glm::cross(b - a, c - a));
    s.positions.push_back(a);
    s.positions.push_back(b);
    s.positions.push_back(c);
    s.normals.push_back(normal);
    s.normals.push_back(normal);
    s.normals.push_back(normal);
}

void naiveDivide(NaiveSphere& s, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, int n) {
    if (n == 0) return naiveTriangle(s, a, b, c);
    const glm::dvec3 ab = glm::normalize((a + b) * 0.5), ac = glm::normalize((a + c) * 0.5),
                     bc = glm::normalize((b + c) * 0.5);
    naiveDivide(s, a, ab, ac, n - 1);
    naiveDivide(s, ab, b, bc, n - 1);
    naiveDivide(s, bc, c, ac, n - 1);
    naiveDivide(s, ab, bc, ac, n - 1);
}

NaiveSphere naiveSphere(int level, bool reserve) {
    NaiveSphere s;
    if (reserve) {
        s.positions.reserve(3 * sphereTriangleCount(level));
        s.normals.reserve(3 * sphereTriangleCount(level));
    }
    const double s2 = std::sqrt(2.0), s6 = std::sqrt(6.0);
    const glm::dvec3 a{0, 0, 1}, b{0, 2 * s2 / 3, -1.0 / 3}, c{-s6 / 3, -s2 / 3, -1.0 / 3},
        d{s6 / 3, -s2 / 3, -1.0 / 3};
    naiveDivide(s, d, c, b, level);
    naiveDivide(s, a, b, c, level);
    naiveDivide(s, a, d, b, level);
    naiveDivide(s, a, c, d, level);
    return s;
}

void registerCpu(const std::string& name, int iterations, std::function<void(benchmark::State&)> run) {
    benchmark::RegisterBenchmark(name.c_str(), std::move(run))
        ->UseManualTime()
        ->Iterations(iterations)
        ->Unit(benchmark::kMillisecond);
}

} // namespace

std::vector<RatioSpec> registerSphereCosts() {
    std::vector<RatioSpec> ratios;
    for (int level = 0; level <= 9; ++level) {
        const std::string suffix = "/level" + std::to_string(level);
        const int iterations = level >= 8 ? 7 : 15;
        // Into arrays kept from the build before (SphereBuilder): memory already mapped, as memcpy's
        // destination is below, so the ratio compares the generator with the memory's bandwidth and not
        // with the kernel's page faults (about 15 µs each on the sandboxed machines this was measured on).
        registerCpu("sphere/build" + suffix, iterations, [level](benchmark::State& state) {
            SphereBuilder builder;
            timeCpu(state, [&] { benchmark::DoNotOptimize(builder.build(level).positions.data()); });
            state.counters["output_bytes"] = double(outputBytes(builder.build(level)));
        });
        // Fresh arrays every time (buildSphere), against copy-mesh below: allocation and page faults in both.
        registerCpu("sphere/build-fresh" + suffix, iterations, [level](benchmark::State& state) {
            timeCpu(state, [level] { benchmark::DoNotOptimize(buildSphere(level)); });
        });
        // The memory-bandwidth limit: the same bytes copied into a buffer that is already mapped.
        registerCpu("sphere/memcpy" + suffix, iterations, [level](benchmark::State& state) {
            const std::size_t bytes = outputBytes(buildSphere(level));
            std::vector<unsigned char> from(bytes, 1), to(bytes, 0);
            timeCpu(state, [&] {
                std::memcpy(to.data(), from.data(), bytes);
                benchmark::DoNotOptimize(to.data());
                benchmark::ClobberMemory();
            });
            state.counters["output_bytes"] = double(bytes);
        });
        // The limit for any generator returning fresh arrays: allocating them and copying the bytes in.
        registerCpu("sphere/copy-mesh" + suffix, iterations, [level](benchmark::State& state) {
            const SphereMesh mesh = buildSphere(level);
            timeCpu(state, [&] { benchmark::DoNotOptimize(SphereMesh(mesh)); });
        });
        for (const bool reserve : {false, true}) {
            registerCpu(std::string("sphere/naive-unshared") + (reserve ? "-reserved" : "") + suffix,
                        iterations, [level, reserve](benchmark::State& state) {
                            timeCpu(state, [=] { benchmark::DoNotOptimize(naiveSphere(level, reserve)); });
                            const NaiveSphere s = naiveSphere(level, reserve);
                            state.counters["output_bytes"] =
                                double((s.positions.size() + s.normals.size()) * sizeof(glm::dvec3));
                        });
        }
        const std::string l = "sphere L" + std::to_string(level);
        ratios.push_back(
            {l + ": build / memcpy of its output", "sphere/build" + suffix, "sphere/memcpy" + suffix});
        ratios.push_back({l + ": naive (unshared vertices) / build", "sphere/naive-unshared" + suffix,
                          "sphere/build" + suffix});
    }
    ratios.push_back({"sphere L8: fresh build / copy into fresh arrays", "sphere/build-fresh/level8",
                      "sphere/copy-mesh/level8"});
    ratios.push_back({"sphere L8: naive / naive with exact reserve", "sphere/naive-unshared/level8",
                      "sphere/naive-unshared-reserved/level8"});
    return ratios;
}

} // namespace shadelab::app
