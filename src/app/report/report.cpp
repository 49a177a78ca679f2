// `shadelab report`, the command: its options, the output folder checked before any measuring, the progress
// bar, the table on standard output, and the files written as one set at the end. The rows are measured by
// report_measure.cpp (errors: report_error.cpp) and written by report_files.cpp and report_plot.cpp.
#include "app/report/report.h"

#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>

#include <signal.h>
#include <unistd.h>

#include "app/measure/bundled_scenes.h"
#include "app/measure/memory_budget.h"
#include "app/report/report_files.h"
#include "shadelab/errors.h"
#include "shadelab/gl/loader.h"
#include "shadelab/io/atomic_file.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/scene_file.h"

namespace shadelab::app {

namespace fs = std::filesystem;

// ---- options ----

void parseLevels(std::string_view text, ReportOptions& options) {
    const std::string accepted = "expected N or A..B with 0 <= A <= B <= " + std::to_string(kMaxSubdivisions);
    const std::size_t dots = text.find("..");
    const auto lo = digitsValue(text.substr(0, dots), 2);
    const auto hi = dots == std::string_view::npos ? lo : digitsValue(text.substr(dots + 2), 2);
    if (!lo || !hi || *lo > *hi || *hi > kMaxSubdivisions)
        throw InputError("--levels: " + accepted + ", got " + quotedValue(text));
    options.minLevel = *lo;
    options.maxLevel = *hi;
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

// ---- the command ----

namespace {

using Clock = std::chrono::steady_clock;

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

} // namespace

int runReport(const ReportOptions& options) {
    validateReportOptions(options);
    const Scene scene = options.scene ? loadSceneWithModels(*options.scene) : bundledScene("report.json");
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
    std::vector<std::filesystem::path> inputs;
    if (options.scene) inputs.push_back(*options.scene);
    prepareOutputFolder(options.outDir, "--out", {kReportFiles.begin(), kReportFiles.end()}, inputs);

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
    const std::vector<std::string> removed = writeReportSet(
        options.outDir, files,
        options.plot ? std::vector<std::string>{} : std::vector<std::string>{"report.gp", "report.png"});
    printTable(rows);
    const std::string dir = printable(options.outDir.string());
    std::printf("wrote %s in %s\n",
                options.plot ? "report.csv, report.json, report.gp and report.png"
                             : "report.csv and report.json",
                dir.c_str());
    for (const std::string& name : removed)
        std::printf("removed the earlier run's %s (this run has no plot)\n", name.c_str());
    return kExitOk;
}

} // namespace shadelab::app
