// `shadelab report`: what each shading mode, lighting model and subdivision level of one scene
// buys in accuracy and costs in time. measureReport() is the measuring core: it needs only a headless
// context, so the GL tests call it without the command line; runReport() adds the scene, the files
// (report.csv, report.json, report.png drawn by gnuplot) and the progress bar.
// Defined in report.cpp (the options, runReport), report_measure.cpp (measureReport), report_error.cpp
// (measureError, maxFaceNormalErrorDeg), report_files.cpp (the columns, CSV and JSON) and report_plot.cpp.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shadelab/context/context.h"
#include "shadelab/exact/reference.h"
#include "shadelab/geometry/teapot.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app {

struct ReportOptions {
    std::optional<std::filesystem::path> scene; // none: the bundled scenes/report.json
    std::filesystem::path outDir = "report";
    int minLevel = 0, maxLevel = 8;
    bool includeAuto = true; // one more row per mode: "subdivisions": "auto" at the scene's tolerance_px
    bool plot = true;        // false (--no-plot): report.csv and report.json only, gnuplot not needed
    ContextRequest context;  // --backend, --api, --egl-device
    int frames = 20;         // timed frames per configuration, >= 1
    int warmup = 3;          // untimed frames first, >= 1 (the first frame builds the mesh and the program)
};

// "--levels": "N" or "A..B" with 0 <= A <= B <= kMaxSubdivisions. InputError naming --levels otherwise.
void parseLevels(std::string_view text, ReportOptions& options);
// InputError naming the option (--levels, --frames, --warmup) for values out of range.
void validateReportOptions(const ReportOptions& options);

// One configuration: a shading mode × lighting model × level. The docs/students.md "Error against run time"
// documents each field under its column name (reportColumns()).
struct ReportRow {
    ShadingMode shading = ShadingMode::Phong;
    LightingModel lighting = LightingModel::BlinnPhong;
    bool autoLevel = false; // the scene's objects at "auto"; `level` is then the largest level chosen
    int level = 0;

    // Time, milliseconds. Frames are GPU-synchronized (glFinish after each) into an RGBA8 target.
    double frameMedianMs = 0, frameP10Ms = 0, frameP90Ms = 0;
    // One-off costs, the median of 3 unless said otherwise:
    double meshBuildMs = 0; // buildSphere on the CPU, every distinct level the objects use
    double uploadMs = 0;    // a GpuMesh constructed from the built mesh (float conversion + buffers), synced
    double compileMs = 0;   // buildProgram + first draw of the variant, synced; once per variant

    // Error against renderReference(scene), from the same frame rendered into an RGBA32F target.
    double interiorMeanError = 0, interiorMaxError = 0; // |Δ| per colour channel, in 1/255
    std::size_t interiorPixels = 0;   // 2 px inside the silhouette in both the reference and the render
    double psnrDb = 0;                // whole image, RGB, peak 1; capped at kMaxPsnrDb
    double ssim = 0;                  // whole image, luminance, Gaussian window (see measureError)
    std::size_t coverageMismatch = 0; // pixels covered in exactly one of the render and the reference

    // Geometry: summed over the objects (triangles) or the distinct meshes uploaded (vertex bytes).
    std::size_t triangles = 0;
    std::size_t vertexBytes = 0;   // smooth: vertices + 32-bit indices; flat: 3 vertices per triangle
    double maxRadialDeviation = 0; // δₙ of the unit mesh (relative to the radius)
    double maxNormalErrorDeg = 0;  // max over faces of ∠(face normal, exact normal at the centroid)
};

inline constexpr double kMaxPsnrDb = 100; // identical images would give +infinity

// The column names of report.csv and the keys of report.json's rows, in order. Stable: scripts read them.
const std::vector<std::string_view>& reportColumns();
// "auto" or the level.
std::string levelLabel(const ReportRow& row);

// The error figures of one render against the reference. Interior: pixels whose 2-px neighbourhood shows
// one object in the reference and is covered in the render (alpha > 0.5), as in DESIGN §6. SSIM: Wang et
// al. 2004 on linear luminance Y = 0.2126 R + 0.7152 G + 0.0722 B, Gaussian window σ = 1.5 px truncated
// at 11×11 (renormalized at the image border), C1 = 0.01², C2 = 0.03², averaged over every pixel.
struct ReportError {
    double interiorMean = 0, interiorMax = 0; // 1/255
    std::size_t interiorPixels = 0;
    double psnrDb = 0, ssim = 0;
    std::size_t coverageMismatch = 0;
};
ReportError measureError(const ImageF& rendered, const ReferenceImage& reference);

// Max over faces of the angle, in degrees, between the face normal and the exact sphere normal in the
// direction of the face's centroid.
double maxFaceNormalErrorDeg(const SphereMesh& mesh);
// The same for the teapot: against the patch's analytic normal at the centroid's (patch, u, v).
double maxFaceNormalErrorDeg(const TeapotMesh& mesh);

// Called before each configuration is measured (done = rows finished so far) and once at the end.
using ReportProgress = std::function<void(int done, int total, std::string_view configuration)>;

// The levels measureReport measures `scene` at, in order: options.minLevel..maxLevel within the finest
// level of the scene's shapes (the teapot's kMaxTeapotLevel when no object is a sphere; none beyond a
// model's own mesh, level 0), then kAutoSubdivisions if options.includeAuto and a shape has levels.
std::vector<int> reportLevels(const Scene& scene, const ReportOptions& options);

// Every shading mode × lighting model × level (options.minLevel..maxLevel, then "auto" if
// options.includeAuto) of `scene`, rows ordered by lighting model, shading mode, level (auto last).
// Makes `context` current and leaves it current; every GL object it creates is gone when it returns.
std::vector<ReportRow> measureReport(HeadlessContext& context, const Scene& scene,
                                     const ReportOptions& options, const ReportProgress& progress = {});

// What the files say about the run besides the rows.
struct ReportInfo {
    std::string sceneName; // the scene file, or "scenes/report.json (bundled)"
    std::string renderer;  // gl::rendererString()
    Backend backend = Backend::Egl;
    Api api = Api::Gl;
    int width = 0, height = 0;
    int frames = 0, warmup = 0;
    LightingModel labelledLighting = LightingModel::Phong; // the plot labels this model's points
};

// Each written atomically; RuntimeError naming the path on failure.
void writeReportCsv(const std::vector<ReportRow>& rows, const std::filesystem::path& path);
void writeReportJson(const std::vector<ReportRow>& rows, const ReportInfo& info,
                     const std::filesystem::path& path);
// Writes dir/report.gp (the gnuplot script, data inline) and runs gnuplot on it into dir/report.png.
// RuntimeError naming gnuplot if it is not on PATH or fails.
void plotReport(const std::vector<ReportRow>& rows, const ReportInfo& info, const std::filesystem::path& dir);
// RuntimeError naming gnuplot and its Debian package when it is not on PATH.
void requireGnuplot();

int runReport(const ReportOptions& options);

} // namespace shadelab::app
