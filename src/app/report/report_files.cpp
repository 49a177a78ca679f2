// The report's files as text: report.csv and report.json from one table of column names and values, and the
// set of files written together. The gnuplot script and picture are report_plot.cpp's.
#include "app/report/report_files.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <variant>

#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "shadelab/io/atomic_file.h"

namespace shadelab::app {

namespace fs = std::filesystem;

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

// ---- the set ----

namespace {

void writeAll(PendingOutput& output, const std::string& text) {
    if (std::fwrite(text.data(), 1, text.size(), output.stream()) != text.size())
        failWrite("report file", output.target().path, std::strerror(errno));
}

} // namespace

// The files of one report, written as a set: each to a temporary file, all flushed to disk, then renamed
// one after the other with signals held back; any failure before the renames leaves the old set whole.
std::vector<std::string> writeReportSet(const fs::path& dir,
                                        const std::vector<std::pair<std::string, std::string>>& files,
                                        const std::vector<std::string>& stale) {
    std::vector<PendingOutput> outputs;
    for (const auto& [name, text] : files) {
        outputs.emplace_back(resolveFolderEntry(dir, name, "--out"), name);
        writeAll(outputs.back(), text);
    }
    // Only a file or a link (the link itself, never what it points to) is removed: anything else at such a
    // name was never a report's.
    std::vector<std::string> removed;
    sigset_t held, previous;
    sigemptyset(&held);
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&held, sig);
    ::sigprocmask(SIG_BLOCK, &held, &previous); // the renames and the removals as one step for a signal
    try {
        commitAll(outputs);
    } catch (...) {
        ::sigprocmask(SIG_SETMASK, &previous, nullptr);
        throw;
    }
    for (const std::string& name : stale) {
        struct stat st {};
        const fs::path path = dir / name;
        if (::lstat(path.c_str(), &st) == 0 && (S_ISREG(st.st_mode) || S_ISLNK(st.st_mode)) &&
            ::unlink(path.c_str()) == 0)
            removed.push_back(name);
    }
    ::sigprocmask(SIG_SETMASK, &previous, nullptr);
    return removed;
}

} // namespace shadelab::app
