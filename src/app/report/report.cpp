// `shadelab report`. Frame times follow the bench's method (app/frame_timing.h): one context, one renderer
// and one offscreen target for the whole run, glFinish after every frame, median and 10th/90th percentiles
// of the frames after a warm-up. The error of each configuration is taken from the same scene rendered
// once more into an RGBA32F target, so that it is the shading's error and not the 8-bit rounding's.
#include "app/report/report.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <regex>
#include <set>
#include <variant>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "app/measure/bundled_scenes.h"
#include "app/measure/frame_timing.h"
#include "app/measure/memory_budget.h"
#include "shadelab/atomic_file.h"
#include "shadelab/errors.h"
#include "shadelab/gl/loader.h"
#include "shadelab/gl/mesh.h"
#include "shadelab/gl/program.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/image.h"
#include "shadelab/subdivision.h"
#include "shadelab/text.h"

extern char** environ; // POSIX: the environment gnuplot inherits

namespace shadelab::app {

namespace fs = std::filesystem;

// ---- options ----

void parseLevels(std::string_view text, ReportOptions& options) {
    static const std::regex kLevels(R"(([0-9]{1,2})(?:\.\.([0-9]{1,2}))?)");
    const std::string s(text);
    std::smatch m;
    const std::string accepted = "expected N or A..B with 0 <= A <= B <= " + std::to_string(kMaxSubdivisions);
    if (!std::regex_match(s, m, kLevels)) throw InputError("--levels: " + accepted + ", got \"" + s + "\"");
    const int lo = std::stoi(m[1]), hi = m[2].matched ? std::stoi(m[2]) : lo;
    if (lo > hi || hi > kMaxSubdivisions) throw InputError("--levels: " + accepted + ", got \"" + s + "\"");
    options.minLevel = lo;
    options.maxLevel = hi;
}

void validateReportOptions(const ReportOptions& o) {
    if (o.minLevel < 0 || o.minLevel > o.maxLevel || o.maxLevel > kMaxSubdivisions)
        throw InputError("--levels: expected 0 <= A <= B <= " + std::to_string(kMaxSubdivisions) + ", got " +
                         std::to_string(o.minLevel) + ".." + std::to_string(o.maxLevel));
    if (o.frames < 1) throw InputError("--frames: must be >= 1, got " + std::to_string(o.frames));
    if (o.warmup < 1)
        throw InputError("--warmup: must be >= 1 (the first frame of a configuration builds its mesh and "
                         "program), got " +
                         std::to_string(o.warmup));
}

// ---- rows: one table of column names and values, so the CSV, the JSON and the docs cannot drift ----

namespace {

using Cell = std::variant<std::string, double, std::size_t, int>;

std::vector<std::pair<std::string_view, Cell>> cellsOf(const ReportRow& r) {
    return {
        {"shading", std::string(toString(r.shading))},
        {"lighting", std::string(toString(r.lighting))},
        {"level", r.autoLevel ? Cell(std::string("auto")) : Cell(r.level)},
        {"effective_level", r.level},
        {"frame_median_ms", r.frameMedianMs},
        {"frame_p10_ms", r.frameP10Ms},
        {"frame_p90_ms", r.frameP90Ms},
        {"mesh_build_ms", r.meshBuildMs},
        {"upload_ms", r.uploadMs},
        {"compile_ms", r.compileMs},
        {"interior_mean_error", r.interiorMeanError},
        {"interior_max_error", r.interiorMaxError},
        {"interior_pixels", r.interiorPixels},
        {"psnr_db", r.psnrDb},
        {"ssim", r.ssim},
        {"coverage_mismatch_px", r.coverageMismatch},
        {"triangles", r.triangles},
        {"vertex_bytes", r.vertexBytes},
        {"max_radial_deviation", r.maxRadialDeviation},
        {"max_normal_error_deg", r.maxNormalErrorDeg},
    };
}

} // namespace

const std::vector<std::string_view>& reportColumns() {
    static const std::vector<std::string_view> columns = [] {
        std::vector<std::string_view> names;
        for (const auto& [name, cell] : cellsOf(ReportRow{})) names.push_back(name);
        return names;
    }();
    return columns;
}

std::string levelLabel(const ReportRow& row) {
    return row.autoLevel ? "auto" : std::to_string(row.level);
}

// ---- error against the reference ----

namespace {

// Clamped to [0, 1]; NaN → 0.
double unit(float v) {
    return v > 0 ? (v < 1 ? v : 1) : 0;
}

std::vector<double> luminance(const float* rgba, std::size_t pixels) {
    std::vector<double> y(pixels);
    for (std::size_t i = 0; i < pixels; ++i)
        y[i] = 0.2126 * unit(rgba[4 * i]) + 0.7152 * unit(rgba[4 * i + 1]) + 0.0722 * unit(rgba[4 * i + 2]);
    return y;
}

// Separable Gaussian blur, σ = 1.5 px, 11 taps; where the window leaves the image its weights are
// renormalized over the part inside (separable, so the 2-D window is renormalized too).
std::vector<double> gaussianBlur(const std::vector<double>& in, int w, int h) {
    constexpr int kRadius = 5;
    constexpr double kSigma = 1.5;
    std::array<double, 2 * kRadius + 1> weight{};
    for (std::size_t i = 0; i < weight.size(); ++i) {
        const double k = double(i) - kRadius;
        weight[i] = std::exp(-k * k / (2 * kSigma * kSigma));
    }
    auto pass = [&](const std::vector<double>& src, bool horizontal) {
        std::vector<double> dst(src.size());
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                double sum = 0, norm = 0;
                for (std::size_t i = 0; i < weight.size(); ++i) {
                    const int k = int(i) - kRadius;
                    const int sx = horizontal ? x + k : x, sy = horizontal ? y : y + k;
                    if (sx < 0 || sx >= w || sy < 0 || sy >= h) continue;
                    const double wk = weight[i];
                    sum += wk * src[std::size_t(sy) * w + sx];
                    norm += wk;
                }
                dst[std::size_t(y) * w + x] = sum / norm;
            }
        return dst;
    };
    return pass(pass(in, true), false);
}

double meanSsim(const std::vector<double>& a, const std::vector<double>& b, int w, int h) {
    constexpr double kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03; // (K·L)² with L = 1
    std::vector<double> aa(a.size()), bb(a.size()), ab(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        aa[i] = a[i] * a[i];
        bb[i] = b[i] * b[i];
        ab[i] = a[i] * b[i];
    }
    const auto muA = gaussianBlur(a, w, h), muB = gaussianBlur(b, w, h);
    const auto eAA = gaussianBlur(aa, w, h), eBB = gaussianBlur(bb, w, h), eAB = gaussianBlur(ab, w, h);
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double varA = eAA[i] - muA[i] * muA[i], varB = eBB[i] - muB[i] * muB[i];
        const double cov = eAB[i] - muA[i] * muB[i];
        sum += ((2 * muA[i] * muB[i] + kC1) * (2 * cov + kC2)) /
               ((muA[i] * muA[i] + muB[i] * muB[i] + kC1) * (varA + varB + kC2));
    }
    return a.empty() ? 1 : sum / double(a.size());
}

} // namespace

ReportError measureError(const ImageF& rendered, const ReferenceImage& reference) {
    const int w = reference.color.width, h = reference.color.height;
    if (rendered.width != w || rendered.height != h)
        throw RuntimeError("report: the render is " + std::to_string(rendered.width) + "x" +
                           std::to_string(rendered.height) + " but the reference " + std::to_string(w) + "x" +
                           std::to_string(h));
    const std::size_t pixels = std::size_t(w) * std::size_t(h);
    ReportError e;
    // The render's coverage as ids: the object is taken from the reference where both cover.
    std::vector<int> renderedIds(pixels, -1);
    for (std::size_t i = 0; i < pixels; ++i) {
        const bool covered = rendered.rgba[4 * i + 3] > 0.5f;
        if (covered) renderedIds[i] = reference.objectId[i];
        if (covered != (reference.objectId[i] >= 0)) ++e.coverageMismatch;
    }
    const std::vector<bool> inReference = interiorMask(reference.objectId, w, h, 2);
    const std::vector<bool> inRendered = interiorMask(renderedIds, w, h, 2);
    double interiorSum = 0, squaredSum = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        const bool interior = inReference[i] && inRendered[i];
        for (int c = 0; c < 3; ++c) {
            const float got = rendered.rgba[4 * i + c], want = reference.color.rgba[4 * i + c];
            const double d = unit(got) - unit(want);
            squaredSum += d * d;
            if (!interior) continue;
            const double error = 255.0 * std::abs(double(got) - double(want)); // NaN stays visible here
            interiorSum += error;
            e.interiorMax = std::max(e.interiorMax, error);
            if (std::isnan(error)) e.interiorMax = error;
        }
        if (interior) ++e.interiorPixels;
    }
    e.interiorMean = e.interiorPixels ? interiorSum / (3.0 * double(e.interiorPixels)) : 0;
    const double mse = pixels ? squaredSum / (3.0 * double(pixels)) : 0;
    e.psnrDb = mse > 0 ? std::min(kMaxPsnrDb, -10 * std::log10(mse)) : kMaxPsnrDb;
    e.ssim = meanSsim(luminance(rendered.rgba.data(), pixels), luminance(reference.color.rgba.data(), pixels),
                      w, h);
    return e;
}

double maxFaceNormalErrorDeg(const SphereMesh& mesh) {
    double worst = 0;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3& t = mesh.triangles[i];
        const glm::dvec3 centroid = mesh.positions[t.x] + mesh.positions[t.y] + mesh.positions[t.z];
        const glm::dvec3& n = mesh.faceNormals[i];
        // atan2 keeps its precision at tiny angles, where acos(dot) would round to 0.
        worst = std::max(worst, std::atan2(glm::length(glm::cross(n, centroid)), glm::dot(n, centroid)));
    }
    return worst * 180 / std::numbers::pi;
}

// ---- measuring ----

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// One level's mesh, built and timed once per configuration of levels.
struct BuiltLevel {
    SphereMesh mesh;
    double buildMs = 0;
    double radialDeviation = 0, normalErrorDeg = 0;
};

// The GL objects of one run; destroyed (while the context is current) when measureReport returns.
struct GlRun {
    GlRun(int width, int height)
        : frameTarget(width, height, gl::ColorFormat::Rgba8),
          errorTarget(width, height, gl::ColorFormat::Rgba32F),
          tetrahedronSmooth(buildSphere(0), gl::MeshLayout::Smooth),
          tetrahedronFlat(buildSphere(0), gl::MeshLayout::Flat) {}
    gl::Renderer renderer; // specialized programs, as `shadelab render` draws by default
    gl::RenderTarget frameTarget, errorTarget;
    gl::GpuMesh tetrahedronSmooth, tetrahedronFlat; // the first draw after a compile
};

gl::MeshLayout layoutOf(ShadingMode shading) {
    return shading == ShadingMode::Flat ? gl::MeshLayout::Flat : gl::MeshLayout::Smooth;
}

std::string configurationName(ShadingMode shading, LightingModel lighting, int levelConfig) {
    return std::string(toString(shading)) + "/" + std::string(toString(lighting)) + " " +
           (levelConfig == kAutoSubdivisions ? std::string("auto") : "level " + std::to_string(levelConfig));
}

// The median of `repeats` synchronized timings of `run`, each after an untimed `reset` (a one-off cost
// measured once is at the mercy of one page fault or one preemption).
template <typename Reset, typename Run> double medianMs(int repeats, Reset reset, Run run) {
    std::vector<double> ms;
    for (int i = 0; i < repeats; ++i) {
        reset();
        gl::finish();
        const auto start = Clock::now();
        run();
        ms.push_back(msSince(start));
    }
    return percentile(ms, 0.5);
}

constexpr int kOneOffRepeats = 3;

// Compile and link of a program variant up to its first draw, synchronized: Mesa translates to machine code
// at the first draw, not at glLinkProgram. Measured once per variant, before the renderer builds its own
// copy: the first compile of that source in the process (the driver's on-disk shader cache may still
// serve it; see the README).
double compileMs(GlRun& gl, const gl::ProgramVariant& variant, gl::MeshLayout layout) {
    gl.frameTarget.bind();
    gl::finish();
    const auto start = Clock::now();
    const gl::Program program = gl::buildProgram(variant);
    gl::drawWith(program, layout == gl::MeshLayout::Flat ? gl.tetrahedronFlat : gl.tetrahedronSmooth);
    gl::finish();
    return msSince(start);
}

// The upload and frame times of `scene` as configured.
void measureTime(GlRun& gl, const Scene& scene, const std::map<int, BuiltLevel>& built,
                 const ReportOptions& o, ReportRow& row) {
    const gl::MeshLayout layout = layoutOf(scene.shading);
    for (const auto& entry : built) {
        const SphereMesh& sphere = entry.second.mesh; // a structured binding cannot be captured (C++20)
        std::optional<gl::GpuMesh> mesh;
        row.uploadMs += medianMs(
            kOneOffRepeats, [&] { mesh.reset(); },
            [&] {
                mesh.emplace(sphere, layout);
                gl::finish();
            });
    }

    gl.frameTarget.bind();
    const std::vector<double> ms =
        timeFramesMs(o.warmup, o.frames, [&] { gl.renderer.render(scene, scene.width, scene.height); });
    row.frameMedianMs = percentile(ms, 0.5);
    row.frameP10Ms = percentile(ms, 0.1);
    row.frameP90Ms = percentile(ms, 0.9);
}

void setGeometry(const Scene& scene, const std::map<int, BuiltLevel>& built, ReportRow& row) {
    for (const SceneObject& object : scene.objects) {
        const int level = subdivisionLevel(scene, object);
        row.triangles += sphereTriangleCount(level);
        row.level = std::max(row.level, level);
    }
    for (const auto& [level, b] : built) {
        const std::size_t triangles = sphereTriangleCount(level);
        row.vertexBytes +=
            scene.shading == ShadingMode::Flat
                ? 3 * triangles * sizeof(FlatVertex)
                : sphereVertexCount(level) * sizeof(SmoothVertex) + 3 * triangles * sizeof(std::uint32_t);
        row.maxRadialDeviation = std::max(row.maxRadialDeviation, b.radialDeviation);
        row.maxNormalErrorDeg = std::max(row.maxNormalErrorDeg, b.normalErrorDeg);
    }
}

} // namespace

std::vector<ReportRow> measureReport(HeadlessContext& context, const Scene& scene,
                                     const ReportOptions& options, const ReportProgress& progress) {
    validateReportOptions(options);
    validateScene(scene);
    if (scene.objects.empty())
        throw InputError("report: the scene has no objects, so there is nothing to measure");

    std::vector<int> levelConfigs;
    for (int level = options.minLevel; level <= options.maxLevel; ++level) levelConfigs.push_back(level);
    if (options.includeAuto) levelConfigs.push_back(kAutoSubdivisions);
    const std::size_t perMode = levelConfigs.size();
    const int total = int(kLightingModels.size() * kShadingModes.size() * perMode);
    std::vector<ReportRow> rows(static_cast<std::size_t>(total));

    context.makeCurrent();
    GlRun gl(scene.width, scene.height);
    // Per lighting model × toon or not: the exact image depends on nothing else the report varies.
    std::map<std::pair<LightingModel, bool>, ReferenceImage> references;
    std::map<gl::ProgramVariant, double> compileTimes;
    int done = 0;

    for (std::size_t c = 0; c < perMode; ++c) {
        Scene base = scene;
        base.view = View{}; // the report times and measures the shading itself, not a teaching view of it
        for (SceneObject& object : base.objects) object.subdivisions = levelConfigs[c];
        std::map<int, BuiltLevel> built; // the distinct levels the objects use: what gets uploaded
        for (const SceneObject& object : base.objects) {
            const int level = subdivisionLevel(base, object);
            if (built.count(level)) continue;
            BuiltLevel& b = built[level];
            b.buildMs = medianMs(
                kOneOffRepeats, [&] { b.mesh = SphereMesh{}; },
                [&] { b.mesh = buildSphere(level, scene.vertexNormals); });
            b.radialDeviation = maxRadialDeviation(b.mesh);
            b.normalErrorDeg = maxFaceNormalErrorDeg(b.mesh);
        }
        for (std::size_t l = 0; l < kLightingModels.size(); ++l) {
            for (std::size_t s = 0; s < kShadingModes.size(); ++s) {
                Scene configured = base;
                configured.lighting = kLightingModels[l];
                configured.shading = kShadingModes[s];
                if (progress)
                    progress(done, total,
                             configurationName(configured.shading, configured.lighting, levelConfigs[c]));

                ReportRow& row = rows[(l * kShadingModes.size() + s) * perMode + c];
                row.shading = configured.shading;
                row.lighting = configured.lighting;
                row.autoLevel = levelConfigs[c] == kAutoSubdivisions;
                for (const auto& [level, b] : built) row.meshBuildMs += b.buildMs;
                setGeometry(configured, built, row);
                const gl::ProgramVariant variant =
                    gl::ProgramVariant::forScene(configured, gl.renderer.specialize());
                if (!compileTimes.count(variant))
                    compileTimes[variant] = compileMs(gl, variant, layoutOf(configured.shading));
                row.compileMs = compileTimes[variant];
                measureTime(gl, configured, built, options, row);

                const bool toon = configured.shading == ShadingMode::Toon;
                auto reference = references.find({configured.lighting, toon});
                if (reference == references.end())
                    reference =
                        references.emplace(std::pair{configured.lighting, toon}, renderReference(configured))
                            .first;
                gl.errorTarget.bind();
                gl.renderer.render(configured, configured.width, configured.height);
                const ReportError e = measureError(gl.errorTarget.readFloat(), reference->second);
                row.interiorMeanError = e.interiorMean;
                row.interiorMaxError = e.interiorMax;
                row.interiorPixels = e.interiorPixels;
                row.psnrDb = e.psnrDb;
                row.ssim = e.ssim;
                row.coverageMismatch = e.coverageMismatch;
                ++done;
            }
        }
    }
    if (progress) progress(done, total, "done");
    return rows;
}

// ---- files ----

namespace {

std::string formatCell(const Cell& cell) {
    char buffer[64];
    if (const auto* s = std::get_if<std::string>(&cell)) return *s;
    if (const auto* d = std::get_if<double>(&cell)) std::snprintf(buffer, sizeof buffer, "%.6g", *d);
    if (const auto* z = std::get_if<std::size_t>(&cell)) std::snprintf(buffer, sizeof buffer, "%zu", *z);
    if (const auto* i = std::get_if<int>(&cell)) std::snprintf(buffer, sizeof buffer, "%d", *i);
    return buffer;
}

void writeText(const fs::path& path, std::string_view what, const std::string& text) {
    writeFileAtomically(path, what, [&](std::FILE* file) {
        if (std::fwrite(text.data(), 1, text.size(), file) != text.size())
            failWrite(what, path, "short write");
    });
}

} // namespace

std::string reportCsv(const std::vector<ReportRow>& rows) {
    std::string text;
    for (std::string_view name : reportColumns()) text.append(name).append(",");
    text.back() = '\n';
    for (const ReportRow& row : rows) {
        for (const auto& [name, cell] : cellsOf(row)) text.append(formatCell(cell)).append(",");
        text.back() = '\n';
    }
    return text;
}

void writeReportCsv(const std::vector<ReportRow>& rows, const fs::path& path) {
    writeText(path, "CSV", reportCsv(rows));
}

std::string reportJson(const std::vector<ReportRow>& rows, const ReportInfo& info) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const ReportRow& row : rows) {
        nlohmann::ordered_json entry = nlohmann::ordered_json::object();
        for (const auto& [name, cell] : cellsOf(row))
            std::visit([&, key = std::string(name)](const auto& value) { entry[key] = value; }, cell);
        list.push_back(std::move(entry));
    }
    const nlohmann::ordered_json root = {{"scene", info.sceneName},
                                         {"renderer", info.renderer},
                                         {"backend", std::string(toString(info.backend))},
                                         {"api", std::string(toString(info.api))},
                                         {"width", info.width},
                                         {"height", info.height},
                                         {"frames", info.frames},
                                         {"warmup_frames", info.warmup},
                                         {"columns", reportColumns()},
                                         {"rows", list}};
    // Scene names and renderer strings are input: invalid UTF-8 in them must not make dump() throw.
    return root.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

void writeReportJson(const std::vector<ReportRow>& rows, const ReportInfo& info, const fs::path& path) {
    writeText(path, "JSON", reportJson(rows, info));
}

// ---- the plot ----

namespace {

// A gnuplot string literal holding `text` as data. In single quotes gnuplot expands nothing (no backquote
// command, no @macro, no backslash escape); only ' ends the string (doubled as '') and a line break ends the
// command, so a newline in a file name would start a new gnuplot command (`system(...)` included).
// printable() writes every control byte and invalid UTF-8 as \xNN text, so no line break gets through.
std::string gnuplotString(std::string_view text) {
    std::string out = "'";
    for (char ch : printable(text)) out += ch == '\'' ? std::string("''") : std::string(1, ch);
    return out + "'";
}

std::string blockName(ShadingMode shading, LightingModel lighting, bool autoLevel) {
    std::string name = "$" + std::string(toString(shading)) + "_" + std::string(toString(lighting));
    std::replace(name.begin(), name.end(), '-', '_');
    return autoLevel ? name + "_auto" : name;
}

constexpr const char* modeColor(ShadingMode shading) {
    switch (shading) {
    case ShadingMode::Flat:
        return "#1f77b4";
    case ShadingMode::Gouraud:
        return "#2ca02c";
    case ShadingMode::Phong:
        return "#d62728";
    case ShadingMode::Toon:
        return "#9467bd";
    case ShadingMode::Exact:
        return "#000000";
    }
    return "#000000";
}

std::string gnuplotScript(const std::vector<ReportRow>& rows, const ReportInfo& info) {
    std::string s;
    std::set<std::string> blocks; // the data blocks written, by name
    bool hasAuto = false;
    s += "# report.png of `shadelab report`: interior mean error against median frame time, one curve per\n"
         "# shading mode and lighting model, points labelled by subdivision level. Written by shadelab;\n"
         "# re-draw with: gnuplot report.gp > report.png\n";
    s += "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {\n"
         "    set terminal pngcairo size 1280,860 font 'sans,11' noenhanced\n"
         "} else {\n"
         "    set terminal png size 1280,860 noenhanced\n"
         "}\n";
    s +=
        "set title " +
        gnuplotString(info.sceneName + ", " + std::to_string(info.width) + "x" + std::to_string(info.height) +
                      ", " + info.renderer + " (" + std::string(toString(info.backend)) + ")") +
        "\n";
    s += "set logscale xy\nset autoscale xfix\nset offsets graph 0.04, graph 0.08, 0, 0\n"
         "set format x '%g'\nset format y '%g'\nset xtics add (0.2, 0.5, 2, 5, 20, 50, 200, 500)\n"
         "set xlabel 'median frame time, ms (glFinish after each frame)'\n"
         "set ylabel 'interior mean |error| per channel, 1/255'\n"
         "set grid xtics ytics mxtics mytics lc rgb '#dddddd'\n"
         "set key inside left bottom box opaque\n"
         "set arrow from graph 0, first 1 to graph 1, first 1 nohead dt 2 lc rgb '#777777'\n"
         "set label '1/255' at graph 0.01, first 1 offset 0,0.7 tc rgb '#555555'\n";
    // The y axis is logarithmic: an error of exactly zero (an unlit scene, a flat colour) has no place on
    // it. Such points are drawn on a floor below the smallest non-zero error, marked "0 (exact)".
    double smallest = 0;
    bool anyZero = false;
    for (const ReportRow& row : rows) {
        if (row.interiorMeanError > 0)
            smallest = smallest > 0 ? std::min(smallest, row.interiorMeanError) : row.interiorMeanError;
        else
            anyZero = true;
    }
    const double zeroLevel = smallest > 0 ? smallest / 4 : 0.01;
    if (anyZero) {
        char text[400];
        std::snprintf(
            text, sizeof text,
            "set arrow from graph 0, first %.6g to graph 1, first %.6g nohead dt 3 lc rgb '#999999'\n"
            "set label '0 (exact): an error of zero is drawn on this line' at graph 0.99, first %.6g "
            "right offset 0,0.7 tc rgb '#555555'\nset yrange [%.6g:%s]\n"
            "set key inside right center box opaque\nset ytics add ('0' %.6g)\n",
            zeroLevel, zeroLevel, zeroLevel, zeroLevel / 3, smallest > 0 ? "*" : "3", zeroLevel);
        s += text;
    }
    char line[128];
    for (LightingModel lighting : kLightingModels)
        for (ShadingMode shading : kShadingModes)
            for (bool autoLevel : {false, true}) {
                std::string block;
                for (const ReportRow& row : rows) {
                    if (row.lighting != lighting || row.shading != shading || row.autoLevel != autoLevel)
                        continue;
                    std::snprintf(line, sizeof line, "%.6g %.6g \"%s\"\n", row.frameMedianMs,
                                  row.interiorMeanError > 0 ? row.interiorMeanError : zeroLevel,
                                  levelLabel(row).c_str());
                    block += line;
                }
                if (block.empty()) continue;
                const std::string name = blockName(shading, lighting, autoLevel);
                s.append(name).append(" << EOD\n").append(block).append("EOD\n");
                blocks.insert(name);
                hasAuto = hasAuto || autoLevel;
            }

    std::vector<std::string> plots;
    auto plot = [&](const std::string& block, std::string_view style, std::string_view title) {
        std::string line = block;
        line.append(" using ").append(style).append(title.empty() ? " notitle" : " title ");
        if (!title.empty()) line += gnuplotString(title);
        plots.push_back(std::move(line));
    };
    for (bool labelled : {true, false})
        for (LightingModel lighting : kLightingModels) {
            if ((lighting == info.labelledLighting) != labelled) continue;
            for (ShadingMode shading : kShadingModes) {
                const std::string name = blockName(shading, lighting, false);
                if (!blocks.count(name)) continue;
                std::string color = "lc rgb '";
                color.append(modeColor(shading)).append("'");
                std::string title(toString(shading));
                title.append(" (").append(toString(lighting)).append(" lighting)");
                plot(name,
                     std::string(labelled ? "1:2 with linespoints lw 2 pt 7 ps 1.1 dt 1 "
                                          : "1:2 with linespoints lw 1 pt 6 ps 0.8 dt 2 ") +
                         color,
                     title);
                if (!labelled) continue;
                std::string labels = "1:2:3 with labels offset char 0.9,0.55 font ',9' tc rgb '";
                labels.append(modeColor(shading)).append("'");
                plot(name, labels, {});
                const std::string autoName = blockName(shading, lighting, true);
                if (blocks.count(autoName)) plot(autoName, "1:2 with points pt 6 ps 2.6 lw 2 " + color, {});
            }
        }
    if (hasAuto) {
        std::string title = "auto subdivision (";
        title.append(toString(info.labelledLighting)).append(" lighting)");
        plots.push_back("NaN with points pt 6 ps 2.6 lw 2 lc rgb 'black' title " + gnuplotString(title));
    }
    s += "plot ";
    for (std::size_t i = 0; i < plots.size(); ++i) s.append(i ? ", \\\n     " : "").append(plots[i]);
    return s + "\n";
}

bool onPath(const char* program) {
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        const std::size_t end = std::min(dirs.find(':', start), dirs.size());
        const std::string dir = end > start ? dirs.substr(start, end - start) : ".";
        if (::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
        start = end + 1;
    }
    return false;
}

// Runs gnuplot on `script`, fed through standard input from an anonymous file, and returns what it wrote to
// standard output: no path reaches gnuplot's command line (so a folder named "-p" is not an option), and the
// PNG never touches the disk until it has been checked. --default-settings: no ~/.gnuplot runs first.
std::string runGnuplot(const std::string& script) {
    const int in = ::memfd_create("shadelab-report.gp", MFD_CLOEXEC);
    if (in < 0)
        throw RuntimeError("report: cannot hold the gnuplot script: " + std::string(std::strerror(errno)));
    std::size_t done = 0;
    while (done < script.size()) {
        const ssize_t n = ::write(in, script.data() + done, script.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            ::close(in);
            throw RuntimeError("report: cannot hold the gnuplot script: " +
                               std::string(std::strerror(errno)));
        }
        done += std::size_t(n);
    }
    ::lseek(in, 0, SEEK_SET);
    int out[2];
    if (::pipe2(out, O_CLOEXEC) != 0) {
        ::close(in);
        throw RuntimeError("report: pipe for gnuplot: " + std::string(std::strerror(errno)));
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in, STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    std::string program = "gnuplot", defaults = "--default-settings";
    char* argv[] = {program.data(), defaults.data(), nullptr};
    pid_t pid = 0;
    const int spawnError = ::posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(in);
    ::close(out[1]);
    std::string png;
    if (spawnError == 0) {
        char buffer[65536];
        for (;;) {
            const ssize_t n = ::read(out[0], buffer, sizeof buffer);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) break;
            png.append(buffer, std::size_t(n));
        }
    }
    ::close(out[0]);
    if (spawnError != 0)
        throw RuntimeError("report: cannot run gnuplot (" + std::string(std::strerror(spawnError)) +
                           "); report.png is drawn with gnuplot, Debian package gnuplot-nox");
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            throw RuntimeError("report: waiting for gnuplot: " + std::string(std::strerror(errno)));
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw RuntimeError("report: gnuplot failed (" +
                           (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                              : "signal " + std::to_string(WTERMSIG(status))) +
                           ") on report.gp; its messages are above");
    // gnuplot exits 0 after a write error of its own: check that what it wrote is a whole PNG.
    (void)decodePng(png, "report: gnuplot's report.png");
    return png;
}

void writeAll(PendingOutput& output, const std::string& text) {
    if (std::fwrite(text.data(), 1, text.size(), output.stream()) != text.size())
        failWrite("report file", output.target().path, std::strerror(errno));
}

// The files of one report, written as a set: each to a temporary file, all flushed to disk, then renamed
// one after the other with signals held back; any failure before the renames leaves the old set whole.
void writeReportSet(const fs::path& dir, const std::vector<std::pair<std::string, std::string>>& files) {
    std::vector<PendingOutput> outputs;
    for (const auto& [name, text] : files) {
        outputs.emplace_back(resolveOutput(dir / name, "--out"), name);
        writeAll(outputs.back(), text);
    }
    commitAll(outputs);
}

} // namespace

void requireGnuplot() {
    if (!onPath("gnuplot"))
        throw RuntimeError("report: gnuplot not found on PATH; report.png is drawn with gnuplot (Debian "
                           "package gnuplot-nox: apt-get install gnuplot-nox)");
}

void plotReport(const std::vector<ReportRow>& rows, const ReportInfo& info, const fs::path& dir) {
    requireGnuplot();
    const std::string script = gnuplotScript(rows, info);
    writeReportSet(dir, {{"report.gp", script}, {"report.png", runGnuplot(script)}});
}

// ---- the command ----

namespace {

// A bar redrawn in place when stderr is a terminal; otherwise one plain line per configuration.
class ProgressBar {
public:
    void operator()(int done, int total, std::string_view what) {
        if (!tty_) {
            std::fprintf(stderr, "report: %d/%d %.*s\n", done, total, int(what.size()), what.data());
            return;
        }
        constexpr int kWidth = 32;
        const int filled = total > 0 ? done * kWidth / total : kWidth;
        const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
        std::string eta;
        if (done > 0 && done < total)
            eta = ", ~" + std::to_string(std::lround(elapsed / done * (total - done))) + " s left";
        std::fprintf(stderr, "\r\033[K[%s%s] %d/%d %.*s (%.0f s%s)",
                     std::string(std::size_t(filled), '#').c_str(),
                     std::string(std::size_t(kWidth - filled), '.').c_str(), done, total, int(what.size()),
                     what.data(), elapsed, eta.c_str());
        if (done == total) std::fputc('\n', stderr);
        std::fflush(stderr);
    }

private:
    bool tty_ = ::isatty(STDERR_FILENO) == 1;
    Clock::time_point start_ = Clock::now();
};

void printTable(const std::vector<ReportRow>& rows) {
    std::printf("%-11s %-8s %5s %10s %10s %10s %11s %11s %8s %7s %9s\n", "lighting", "shading", "level",
                "triangles", "median_ms", "p90_ms", "mean/255", "max/255", "psnr_db", "ssim", "cov_px");
    for (const ReportRow& r : rows)
        std::printf("%-11s %-8s %5s %10zu %10.3f %10.3f %11.4f %11.3f %8.2f %7.5f %9zu\n",
                    toString(r.lighting).data(), toString(r.shading).data(), levelLabel(r).c_str(),
                    r.triangles, r.frameMedianMs, r.frameP90Ms, r.interiorMeanError, r.interiorMaxError,
                    r.psnrDb, r.ssim, r.coverageMismatch);
}

constexpr std::array<const char*, 4> kReportFiles{"report.csv", "report.json", "report.gp", "report.png"};

// Before any measuring: the folder exists (created if need be) and takes a new file, no report file in it is
// something that cannot be replaced (a folder, a socket) or the scene itself.
void prepareOutDir(const fs::path& dir, const std::optional<fs::path>& scene) {
    if (dir.empty()) throw InputError("--out: the folder name is empty; give a folder such as report");
    const std::string shown = "\"" + printable(dir.string()) + "\"";
    std::error_code error;
    if (fs::exists(dir, error) && !fs::is_directory(dir, error))
        throw InputError("--out: " + shown +
                         " exists and is not a folder; give a folder for the report files");
    fs::create_directories(dir, error);
    if (error)
        throw InputError("--out: cannot create the folder " + shown + ": " + error.message() +
                         "; choose a folder you can write");
    for (const char* name : kReportFiles) {
        (void)resolveOutput(dir / name, "--out");
        if (scene) refuseOverwritingInput(dir / name, "--out", *scene);
    }
    // The probe file lives only between mkstemp and unlink: SIGINT/TERM/HUP are held back meanwhile, so an
    // interrupt cannot leave it behind (it is delivered at once after the unlink).
    sigset_t held, previous;
    sigemptyset(&held);
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&held, sig);
    ::sigprocmask(SIG_BLOCK, &held, &previous);
    std::string probe = (dir / ".shadelab-XXXXXX").string();
    const int fd = ::mkstemp(probe.data());
    const int code = errno;
    if (fd >= 0) {
        ::close(fd);
        ::unlink(probe.c_str());
    }
    ::sigprocmask(SIG_SETMASK, &previous, nullptr);
    if (fd < 0) {
        const std::string reason = std::strerror(code);
        if (code == EACCES || code == EPERM || code == EROFS)
            throw InputError("--out: cannot write in the folder " + shown + ": " + reason +
                             "; choose a folder you can write");
        throw RuntimeError("report: cannot write in the folder " + shown + ": " + reason);
    }
}

} // namespace

int runReport(const ReportOptions& options) {
    validateReportOptions(options);
    const Scene scene = options.scene ? loadScene(*options.scene) : bundledScene("report.json");
    ReportInfo info;
    info.sceneName = options.scene ? printable(options.scene->string()) : "scenes/report.json (bundled)";
    // Measured: about 220 bytes per pixel (float targets, the reference and its normals, error and SSIM
    // maps): `/usr/bin/time -f %M shadelab report` at 2048x2048 less at 24x24 gives 216.
    Scene largest = scene;
    for (SceneObject& object : largest.objects) object.subdivisions = options.maxLevel;
    checkMemoryBudget("report at " + std::to_string(scene.width) + "x" + std::to_string(scene.height),
                      kGlBaselineBytes + 220.0 * scene.width * scene.height + renderBytes(largest),
                      "the scene's image size");
    if (options.plot) requireGnuplot(); // before minutes of measuring, not after
    prepareOutDir(options.outDir, options.scene);

    const std::unique_ptr<HeadlessContext> context = makeHeadlessContext(options.context);
    info.renderer = gl::rendererString();
    info.backend = options.context.backend;
    info.api = options.context.api;
    info.width = scene.width;
    info.height = scene.height;
    info.frames = options.frames;
    info.warmup = options.warmup;
    info.labelledLighting = scene.lighting;
    std::printf("shadelab report: %s, %s, %dx%d, %d frames after %d warm-up frames per configuration\n",
                info.sceneName.c_str(), info.renderer.c_str(), info.width, info.height, info.frames,
                info.warmup);
    std::fflush(stdout);

    const std::vector<ReportRow> rows = measureReport(*context, scene, options, ProgressBar());
    std::vector<std::pair<std::string, std::string>> files = {{"report.csv", reportCsv(rows)},
                                                              {"report.json", reportJson(rows, info)}};
    if (options.plot) {
        const std::string script = gnuplotScript(rows, info);
        files.emplace_back("report.gp", script);
        files.emplace_back("report.png", runGnuplot(script));
    }
    writeReportSet(options.outDir, files);
    printTable(rows);
    const std::string dir = printable(options.outDir.string());
    std::printf("wrote %s in %s\n",
                options.plot ? "report.csv, report.json, report.gp and report.png"
                             : "report.csv and report.json",
                dir.c_str());
    return kExitOk;
}

} // namespace shadelab::app
