// `shadelab bench`. Frame times are GPU-synchronized (glFinish after every frame), timed per frame after a
// warm-up, and summarized as median and 10th/90th percentiles; the figures that matter are ratios of
// configurations measured in the same run on the same machine.
#include "app/bench/bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <regex>

#include <cstdlib>

#include <unistd.h>

#include <benchmark/benchmark.h>
#include <nlohmann/json.hpp>

#include "app/bench/bench_gpu.h"
#include "app/measure/bundled_scenes.h"
#include "shadelab/errors.h"
#include "shadelab/geometry/mesh_layout.h"
#include "shadelab/gl/loader.h"
#include "shadelab/gl/program.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/io/atomic_file.h"
#include "shadelab/io/text.h"

namespace shadelab::app {
namespace {

struct BenchScene {
    const char* name;
    Scene scene;
};

std::vector<BenchScene> issueScenes(const BenchOptions& o) {
    Scene oneLight; // DESIGN §4's default scene: one sphere, one point light
    oneLight.objects[0].subdivisions = kAutoSubdivisions;
    std::vector<BenchScene> scenes = {{"one-light", oneLight},
                                      {"four-mixed-lights", bundledScene("mixed.json")},
                                      {"grid", bundledScene("grid.json")}};
    for (BenchScene& s : scenes) {
        s.scene.width = o.width;
        s.scene.height = o.height;
    }
    return scenes;
}

Scene withLevel(Scene scene, int level) {
    for (SceneObject& o : scene.objects) o.subdivisions = level;
    return scene;
}

} // namespace

// The three specializations as the frame benchmarks name them.
constexpr std::pair<gl::Specialization, const char*> kSpecializations[] = {
    {gl::Specialization::None, "uber"},
    {gl::Specialization::Lights, "specialized"},
    {gl::Specialization::Values, "values"},
};

namespace {

// Each issue scene under each specialization, at level 8 and auto; the ratios between them.
void registerSpecializedFrames(Gpu& gpu, std::vector<RatioSpec>& ratios) {
    for (const BenchScene& s : issueScenes(gpu.options)) {
        for (const auto& [specialization, label] : kSpecializations) {
            for (const int level : {8, kAutoSubdivisions}) {
                const std::string name = std::string("frame/") + s.name + "/" + label + "/" +
                                         (level == kAutoSubdivisions ? "auto" : "level8");
                const Scene scene = withLevel(s.scene, level);
                benchmark::RegisterBenchmark(
                    name.c_str(),
                    [&gpu, scene, specialization = specialization](benchmark::State& state) {
                        gpu.renderer.setSpecialization(specialization);
                        gpu.timeFrames(state, [&] { gpu.renderer.render(scene, scene.width, scene.height); });
                    })
                    ->UseManualTime()
                    ->Iterations(gpu.options.frames)
                    ->Unit(benchmark::kMillisecond);
            }
        }
    }
    for (const BenchScene& s : issueScenes(gpu.options)) {
        const std::string base = std::string("frame/") + s.name + "/";
        ratios.push_back({std::string(s.name) + ": uber / specialized (level 8)", base + "uber/level8",
                          base + "specialized/level8"});
        ratios.push_back({std::string(s.name) + ": uber / specialized (auto)", base + "uber/auto",
                          base + "specialized/auto"});
        ratios.push_back({std::string(s.name) + ": specialized / values (auto)", base + "specialized/auto",
                          base + "values/auto"});
        ratios.push_back({std::string(s.name) + ": level 8 / auto (values)", base + "values/level8",
                          base + "values/auto"});
    }
}

// Flat shading: three vertices per face with face data, or shared vertices and a geometry shader; the
// ratio between them.
void registerFlatLayouts(Gpu& gpu, std::vector<RatioSpec>& ratios) {
    // The geometry stage is desktop only (DESIGN §7): on OpenGL ES the second is left out, and said so.
    const bool geometryStage = gl::capabilities().geometryShaders;
    if (!geometryStage)
        std::printf("bench: %s has no geometry stage: frame/flat-layout/geometry-shader is left out\n",
                    std::string(displayName(gl::capabilities().api)).c_str());
    for (const bool geometryShader : {false, true}) {
        if (geometryShader && !geometryStage) continue;
        for (const int level : {6, 8}) {
            Scene scene = withLevel(issueScenes(gpu.options)[0].scene, level);
            scene.shading = ShadingMode::Flat;
            const std::string name = std::string("frame/flat-layout/") +
                                     (geometryShader ? "geometry-shader" : "duplicated") + "/level" +
                                     std::to_string(level);
            benchmark::RegisterBenchmark(
                name.c_str(),
                [&gpu, scene, geometryShader](benchmark::State& state) {
                    gpu.renderer.setSpecialization(gl::Specialization::Values);
                    gpu.renderer.setFlatGeometryShader(geometryShader);
                    gpu.timeFrames(state, [&] { gpu.renderer.render(scene, scene.width, scene.height); });
                    gpu.renderer.setFlatGeometryShader(false);
                    state.counters["vertex_bytes"] =
                        meshBytes(scene.objects[0].subdivisions,
                                  geometryShader ? MeshLayout::Smooth : MeshLayout::Flat);
                })
                ->UseManualTime()
                ->Iterations(gpu.options.frames)
                ->Unit(benchmark::kMillisecond);
        }
    }
    for (const char* level : {"level6", "level8"})
        if (geometryStage)
            ratios.push_back({std::string("flat ") + level + ": geometry shader / duplicated vertices",
                              std::string("frame/flat-layout/geometry-shader/") + level,
                              std::string("frame/flat-layout/duplicated/") + level});
}

// Compile and link time of each program variant the scenes above use, uber and specialized, up to its
// first draw: Mesa translates to machine code (LLVM) at the first draw, not at glLinkProgram.
void registerCompileTimes(Gpu& gpu) {
    std::map<std::string, gl::ProgramVariant> variants;
    for (const BenchScene& s : issueScenes(gpu.options))
        for (const bool specialized : {false, true}) {
            const gl::ProgramVariant v = gl::ProgramVariant::forScene(s.scene, specialized);
            variants.emplace(v.name(), v);
            if (!specialized) continue;
            const gl::ProgramVariant withValues = v.withValues(s.scene, s.scene.objects.at(0).material);
            variants.emplace(withValues.name(), withValues);
        }
    for (const auto& entry : variants) { // not a structured binding: clang 14 cannot capture one
        const gl::ProgramVariant variant = entry.second;
        benchmark::RegisterBenchmark(
            ("compile/" + entry.first).c_str(),
            [&gpu, variant](benchmark::State& state) {
                const gl::MeshLayout layout =
                    variant.shading == ShadingMode::Flat ? gl::MeshLayout::Flat : gl::MeshLayout::Smooth;
                const gl::GpuMesh tetrahedron(buildSphere(0), layout);
                gpu.target.bind();
                gl::finish();
                for (auto _ : state)
                    state.SetIterationTime(compileAndFirstDrawMs(variant, tetrahedron) / 1e3);
            })
            ->UseManualTime()
            ->Iterations(5)
            ->Unit(benchmark::kMillisecond);
    }
}

} // namespace

// Scene-specialized against uber programs, fixed level 8 against auto, the two flat layouts, and the
// compile time of each program variant.
std::vector<RatioSpec> registerSpecializationBenchmarks(Gpu& gpu) {
    std::vector<RatioSpec> ratios;
    registerSpecializedFrames(gpu, ratios);
    registerFlatLayouts(gpu, ratios);
    registerCompileTimes(gpu);
    return ratios;
}

namespace {

// Collects every run while printing the usual console table.
class Collector : public benchmark::ConsoleReporter {
public:
    explicit Collector(OutputOptions options) : ConsoleReporter(options) {}

protected:
    // The base class's columns, but each counter as a plain number in its column's unit: the base prints
    // 0.000086 in a median_ms column as "86u", which reads as 86 µs.
    void PrintRunData(const Run& run) override {
        if (run.error_occurred) {
            ConsoleReporter::PrintRunData(run);
            return;
        }
        std::ostream& out = GetOutputStream();
        const char* unit = benchmark::GetTimeUnitString(run.time_unit);
        char cell[160];
        std::snprintf(cell, sizeof cell, "%-*s %10.6f %-2s %12.6f %-2s %12lld", int(name_field_width_),
                      run.benchmark_name().c_str(), run.GetAdjustedRealTime(), unit, run.GetAdjustedCPUTime(),
                      unit, static_cast<long long>(run.iterations));
        out << cell;
        for (const auto& [name, counter] : run.counters) {
            const int width = int(std::max<std::size_t>(10, name.size()));
            const bool whole = counter.value == std::floor(counter.value) && std::abs(counter.value) < 1e15;
            std::snprintf(cell, sizeof cell, whole ? " %*.0f" : " %*.6f", width, counter.value);
            out << cell;
        }
        out << "\n";
    }

public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            Result& r = results[run.run_name.function_name]; // the registered name, without suffixes
            r.meanMs = run.GetAdjustedRealTime(); // the unit is milliseconds for every benchmark here
            for (const auto& [key, counter] : run.counters) r.counters[key] = counter.value;
        }
    }
    struct Result {
        double meanMs = 0;
        std::map<std::string, double> counters;
    };
    std::map<std::string, Result> results;
};

double median(const Collector& c, const std::string& name) {
    const auto it = c.results.find(name);
    if (it == c.results.end()) return 0;
    const auto m = it->second.counters.find("median_ms");
    return m == it->second.counters.end() ? it->second.meanMs : m->second;
}

struct Ratio {
    std::string name, numerator, denominator;
    double value = 0;
};

std::vector<Ratio> measuredRatios(const Collector& c, const std::vector<RatioSpec>& specs) {
    std::vector<Ratio> out;
    for (const RatioSpec& spec : specs) {
        const double n = median(c, spec.numerator), d = median(c, spec.denominator);
        if (n > 0 && d > 0) out.push_back({spec.name, spec.numerator, spec.denominator, n / d});
    }
    return out;
}

void writeJson(const Collector& c, const std::vector<Ratio>& rs, const BenchOptions& o,
               const std::string& renderer) {
    nlohmann::json results = nlohmann::json::object();
    for (const auto& [name, r] : c.results) {
        nlohmann::json entry = {{"mean_ms", r.meanMs}};
        for (const auto& [key, value] : r.counters) entry[key] = value;
        results[name] = entry;
    }
    nlohmann::json ratioList = nlohmann::json::array();
    for (const Ratio& r : rs)
        ratioList.push_back({{"name", r.name},
                             {"numerator", r.numerator},
                             {"denominator", r.denominator},
                             {"ratio", r.value}});
    const nlohmann::json root = {{"renderer", renderer}, {"size", {o.width, o.height}},
                                 {"frames", o.frames},   {"warmup_frames", o.warmupFrames},
                                 {"results", results},   {"ratios", ratioList}};
    const std::string text = root.dump(2) + "\n";
    writeFileAtomically(*o.json, "JSON", [&](std::FILE* file) {
        if (std::fwrite(text.data(), 1, text.size(), file) != text.size())
            failWrite("JSON", *o.json, "short write");
    });
}

// Google Benchmark would report a bad expression, run nothing and exit 0. The regex engines compile
// groups by recursion, a frame or more a level (20,000 nested groups overflowed the stack): the nesting and
// length are bounded before any engine sees the expression.
void checkFilter(const std::string& filter) {
    constexpr std::size_t kMaxLength = 1000;
    constexpr int kMaxNesting = 32;
    auto refuse = [&](const std::string& why) {
        throw InputError("--filter: " + why + ", got " + quotedValue(filter));
    };
    if (filter.size() > kMaxLength)
        refuse("at most " + std::to_string(kMaxLength) + " characters (" + std::to_string(filter.size()) +
               ")");
    int depth = 0, deepest = 0;
    for (std::size_t i = 0; i < filter.size(); ++i) {
        if (filter[i] == '\\')
            ++i;
        else if (filter[i] == '(')
            deepest = std::max(deepest, ++depth);
        else if (filter[i] == ')')
            --depth;
    }
    if (deepest > kMaxNesting) refuse("groups nested at most " + std::to_string(kMaxNesting) + " deep");
    try {
        (void)std::regex(filter, std::regex::extended);
    } catch (const std::regex_error& e) {
        refuse(std::string("not a regular expression (") + e.what() + ")");
    }
}

} // namespace

int runBench(const BenchOptions& options) {
    checkFilter(options.filter);
    // Compile times must be compiles: Mesa's on-disk shader cache would turn repeats into look-ups.
    ::setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    Gpu gpu(options);
    const std::string renderer = gl::rendererString();
    std::printf("shadelab bench: %s, %dx%d, %d frames after %d warm-up frames per configuration\n",
                renderer.c_str(), options.width, options.height, options.frames, options.warmupFrames);
    std::vector<RatioSpec> specs = registerSpecializationBenchmarks(gpu);
    for (RatioSpec& spec : registerCostBenchmarks(gpu)) specs.push_back(std::move(spec));

    std::string filterFlag =
        "--benchmark_filter=" + (options.filter.empty() ? std::string(".") : options.filter);
    std::string program = "shadelab-bench";
    char* argv[] = {program.data(), filterFlag.data(), nullptr};
    int argc = 2;
    benchmark::Initialize(&argc, argv);
    std::printf("(Debian's libbenchmark is built without NDEBUG, so Google Benchmark may warn that the "
                "\"Library was built as DEBUG\": that is the library's harness, not the code it times, which "
                "is shadelab's optimized build.)\n");
    std::fflush(stdout);
    // Colour only for a terminal: escape codes in a file or a pipe are noise.
    Collector collector(::isatty(STDOUT_FILENO) ? benchmark::ConsoleReporter::OO_Defaults
                                                : benchmark::ConsoleReporter::OO_Tabular);
    const std::size_t ran = benchmark::RunSpecifiedBenchmarks(&collector);
    benchmark::ClearRegisteredBenchmarks();
    if (ran == 0)
        throw InputError("--filter: \"" + options.filter +
                         "\" matches no benchmark; names look like frame/one-light/specialized/level8 or "
                         "sphere/build/level8 (run without --filter to list them all)");

    const std::vector<Ratio> rs = measuredRatios(collector, specs);
    std::printf("\nratios of medians, measured in this run:\n");
    for (const Ratio& r : rs) std::printf("  %-48s %6.2f\n", r.name.c_str(), r.value);
    if (options.json) {
        writeJson(collector, rs, options, renderer);
        std::printf("figures written to %s\n", options.json->c_str());
    }
    return kExitOk;
}

} // namespace shadelab::app
