// `shadelab report` on a small configuration: the bundled report scene at 128×128, levels 3..5 and
// auto, a few frames. The measuring core is called directly; the last tests run the whole command.
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/measure/bundled_scenes.h"
#include "app/report/report.h"
#include "gl/gl_test_support.h"
#include "shadelab/errors.h"
#include "shadelab/geometry/mesh_layout.h"
#include "shadelab/geometry/subdivision.h"
#include "shadelab/image/image_file.h"
#include "shadelab/scene/auto_level.h"
#include "shadelab/scene/scene_file.h"

namespace shadelab::test {
namespace {

namespace fs = std::filesystem;
using app::ReportOptions;
using app::ReportRow;

// The columns the README documents, spelled out here so that renaming one fails a test.
const std::vector<std::string> kDocumentedColumns = {"shading",
                                                     "lighting",
                                                     "level",
                                                     "effective_level",
                                                     "frame_median_ms",
                                                     "frame_p10_ms",
                                                     "frame_p90_ms",
                                                     "mesh_build_ms",
                                                     "upload_ms",
                                                     "compile_ms",
                                                     "interior_mean_error",
                                                     "interior_max_error",
                                                     "interior_pixels",
                                                     "psnr_db",
                                                     "ssim",
                                                     "coverage_mismatch_px",
                                                     "triangles",
                                                     "vertex_bytes",
                                                     "max_radial_deviation",
                                                     "max_normal_error_deg"};
const std::size_t kTextColumns = 3; // shading, lighting, level; the rest are numbers

// The report makes its context itself (as `shadelab report` does), apart from the support's renderer.
HeadlessContext* reportContext(std::string& why) {
    static std::unique_ptr<HeadlessContext> context;
    static std::string failure;
    if (!context && failure.empty()) {
        try {
            context = makeHeadlessContext(contextUnderTest());
        } catch (const std::exception& e) {
            failure = e.what();
        }
    }
    why = failure;
    return context.get();
}

#define REQUIRE_REPORT_CONTEXT(context)                                                                      \
    std::string context##Why;                                                                                \
    HeadlessContext* context = reportContext(context##Why);                                                  \
    if (!context) {                                                                                          \
        if (std::getenv("CI")) FAIL() << "no GL context in CI: " << context##Why;                            \
        GTEST_SKIP() << "no GL context: " << context##Why;                                                   \
    }

Scene smallScene() {
    Scene scene = app::bundledScene("report.json");
    scene.width = scene.height = 128; // the sphere's radius ≈ 62 px
    return scene;
}

ReportOptions smallOptions() {
    ReportOptions o;
    o.minLevel = 3;
    o.maxLevel = 5;
    o.frames = 3;
    o.warmup = 1;
    o.context = contextUnderTest();
    return o;
}

// Measured once per process: every test below reads the same rows.
const std::vector<ReportRow>& smallReport(HeadlessContext& context) {
    static const std::vector<ReportRow> rows = app::measureReport(context, smallScene(), smallOptions());
    return rows;
}

const ReportRow& rowOf(const std::vector<ReportRow>& rows, LightingModel lighting, ShadingMode shading,
                       std::string_view level) {
    for (const ReportRow& row : rows)
        if (row.lighting == lighting && row.shading == shading && app::levelLabel(row) == level) return row;
    throw std::logic_error("no row " + std::string(toString(shading)) + "/" +
                           std::string(toString(lighting)) + " " + std::string(level));
}

class TempDir {
public:
    explicit TempDir(const std::string& name)
        : path_(fs::temp_directory_path() /
                ("shadelab-report-test-" + std::to_string(::getpid()) + "-" + name)) {
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

std::vector<std::string> readLines(const fs::path& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::vector<std::string> splitCsv(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
    return cells;
}

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ",") + n;
    return out;
}

TEST(Report, ColumnsAreTheDocumentedOnes) {
    const std::vector<std::string> columns(app::reportColumns().begin(), app::reportColumns().end());
    EXPECT_EQ(columns, kDocumentedColumns);
}

TEST(Report, OneRowPerShadingLightingAndLevelInOrder) {
    REQUIRE_REPORT_CONTEXT(context);
    const std::vector<ReportRow>& rows = smallReport(*context);
    ASSERT_EQ(rows.size(), kLightingModels.size() * kShadingModes.size() * 4); // levels 3, 4, 5 and auto
    std::size_t i = 0;
    for (LightingModel lighting : kLightingModels)
        for (ShadingMode shading : kShadingModes)
            for (std::string_view level : {"3", "4", "5", "auto"}) {
                EXPECT_EQ(rows[i].lighting, lighting) << i;
                EXPECT_EQ(rows[i].shading, shading) << i;
                EXPECT_EQ(app::levelLabel(rows[i]), level) << i;
                ++i;
            }
}

// Through the CSV file itself: the header line is the documented one and every number is finite.
TEST(Report, CsvHasTheDocumentedColumnsAndOnlyFiniteValues) {
    REQUIRE_REPORT_CONTEXT(context);
    const std::vector<ReportRow>& rows = smallReport(*context);
    const TempDir dir("csv");
    app::writeReportCsv(rows, dir.path() / "report.csv");
    const std::vector<std::string> lines = readLines(dir.path() / "report.csv");
    ASSERT_EQ(lines.size(), rows.size() + 1);
    EXPECT_EQ(lines[0], joined(kDocumentedColumns));
    for (std::size_t r = 1; r < lines.size(); ++r) {
        const std::vector<std::string> cells = splitCsv(lines[r]);
        ASSERT_EQ(cells.size(), kDocumentedColumns.size()) << lines[r];
        EXPECT_TRUE(parseShadingMode(cells[0])) << lines[r];
        EXPECT_TRUE(parseLightingModel(cells[1])) << lines[r];
        for (std::size_t c = kTextColumns; c < cells.size(); ++c) {
            char* end = nullptr;
            const double value = std::strtod(cells[c].c_str(), &end);
            EXPECT_TRUE(!cells[c].empty() && *end == '\0' && std::isfinite(value))
                << kDocumentedColumns[c] << " = \"" << cells[c] << "\" in " << lines[r];
        }
    }
}

TEST(Report, JsonHasTheRunAndOneObjectPerRow) {
    REQUIRE_REPORT_CONTEXT(context);
    const std::vector<ReportRow>& rows = smallReport(*context);
    const TempDir dir("json");
    app::ReportInfo info;
    info.sceneName = "small";
    info.renderer = "test";
    info.width = info.height = 128;
    app::writeReportJson(rows, info, dir.path() / "report.json");
    std::ifstream in(dir.path() / "report.json");
    const nlohmann::json root = nlohmann::json::parse(in);
    EXPECT_EQ(root.at("columns").get<std::vector<std::string>>(), kDocumentedColumns);
    ASSERT_EQ(root.at("rows").size(), rows.size());
    for (const auto& row : root.at("rows")) {
        ASSERT_EQ(row.size(), kDocumentedColumns.size());
        for (std::size_t c = kTextColumns; c < kDocumentedColumns.size(); ++c)
            EXPECT_TRUE(row.at(kDocumentedColumns[c]).is_number())
                << kDocumentedColumns[c] << " in " << row.dump();
        // Level is a number where it is one ("auto" only for the automatic level).
        if (row.at("level") != "auto") {
            EXPECT_TRUE(row.at("level").is_number_integer()) << "level in " << row.dump();
        }
    }
}

// Smooth modes interpolate over triangles of edge h ~ 2⁻ⁿ with O(h²) error, flat is O(h). At 128×128 (radius
// ≈ 62 px) the Gouraud and Phong means fall 2.6–3.5× per level from level 3 to 5 (llvmpipe, both lighting
// models); 1.5× per level is required, so that a mode whose error does not converge (a constant error) fails
// and pixel-grid noise at this small size cannot.
TEST(Report, InteriorErrorFallsWithLevelForGouraudAndPhong) {
    REQUIRE_REPORT_CONTEXT(context);
    const std::vector<ReportRow>& rows = smallReport(*context);
    for (LightingModel lighting : kLightingModels)
        for (ShadingMode shading : {ShadingMode::Gouraud, ShadingMode::Phong}) {
            const double e3 = rowOf(rows, lighting, shading, "3").interiorMeanError;
            const double e4 = rowOf(rows, lighting, shading, "4").interiorMeanError;
            const double e5 = rowOf(rows, lighting, shading, "5").interiorMeanError;
            SCOPED_TRACE(std::string(toString(shading)) + "/" + std::string(toString(lighting)));
            std::printf("%s/%s interior mean error (1/255): n=3 %.3f, n=4 %.3f, n=5 %.3f\n",
                        toString(shading).data(), toString(lighting).data(), e3, e4, e5);
            EXPECT_GT(e3, 1.5 * e4);
            EXPECT_GT(e4, 1.5 * e5);
            EXPECT_GT(e5, 0) << "an exact match at level 5 means the render and the "
                                "reference are the same code";
        }
}

TEST(Report, GeometryMatchesTheSphere) {
    REQUIRE_REPORT_CONTEXT(context);
    const std::vector<ReportRow>& rows = smallReport(*context);
    const Scene scene = smallScene();
    for (const ReportRow& row : rows) {
        SCOPED_TRACE(std::string(toString(row.shading)) + " " + app::levelLabel(row));
        const std::size_t n = std::size_t(row.level);
        const std::size_t triangles = std::size_t(1) << (2 * (n + 1)); // 4^(n+1)
        EXPECT_EQ(row.triangles, triangles);
        const std::size_t vertices = 2 * (std::size_t(1) << (2 * n)) + 2; // 2·4ⁿ + 2
        EXPECT_EQ(row.vertexBytes,
                  row.shading == ShadingMode::Flat
                      ? 3 * triangles * sizeof(FlatVertex)
                      : vertices * sizeof(SmoothVertex) + 3 * triangles * sizeof(std::uint32_t));
        EXPECT_GT(row.maxRadialDeviation, 0);
        EXPECT_LT(row.maxRadialDeviation, std::pow(4.0, 1.0 - double(n))); // DESIGN §1
        EXPECT_GT(row.maxNormalErrorDeg, 0);
        EXPECT_LT(row.maxNormalErrorDeg, 90);
        if (row.autoLevel) {
            EXPECT_EQ(row.level, autoSubdivisionLevel(scene, scene.objects[0]));
        }
        EXPECT_GT(row.interiorPixels, 5000u) << "radius ≈ 62 px: about 11,000 pixels inside the silhouette";
        EXPECT_LE(row.frameP10Ms, row.frameMedianMs);
        EXPECT_LE(row.frameMedianMs, row.frameP90Ms);
        EXPECT_GT(row.compileMs, 0);
        EXPECT_GT(row.uploadMs, 0);
    }
    // Finer meshes deviate less, and their faces point closer to the exact normal.
    const ReportRow& n3 = rowOf(rows, LightingModel::Phong, ShadingMode::Phong, "3");
    const ReportRow& n5 = rowOf(rows, LightingModel::Phong, ShadingMode::Phong, "5");
    EXPECT_GT(n3.maxRadialDeviation, 10 * n5.maxRadialDeviation);
    EXPECT_GT(n3.maxNormalErrorDeg, n5.maxNormalErrorDeg);
}

// The report's interior error is the one the analytic tests use (gl_test_support's interiorError), and the
// whole-image scores are perfect for the reference against itself.
TEST(Report, ErrorMeasuresAgreeWithTheAnalyticTests) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = smallScene();
    scene.shading = ShadingMode::Phong;
    scene.objects[0].subdivisions = 4;
    const ReferenceImage reference = renderReference(scene);
    const ImageF rendered = renderer->renderFloat(scene);
    const app::ReportError e = app::measureError(rendered, reference);
    const InteriorError expected = interiorError(rendered, reference);
    EXPECT_NEAR(e.interiorMean, expected.mean, 1e-9);
    EXPECT_NEAR(e.interiorMax, expected.max, 1e-9);
    EXPECT_EQ(e.interiorPixels, expected.pixels);
    EXPECT_GT(e.ssim, 0.9);
    EXPECT_LT(e.ssim, 1);
    EXPECT_GT(e.psnrDb, 20);
    EXPECT_LT(e.psnrDb, app::kMaxPsnrDb);

    const app::ReportError same = app::measureError(reference.color, reference);
    EXPECT_EQ(same.interiorMean, 0);
    EXPECT_EQ(same.coverageMismatch, 0u);
    EXPECT_EQ(same.psnrDb, app::kMaxPsnrDb);
    EXPECT_NEAR(same.ssim, 1, 1e-12);
}

// A scene saved from the demo in a teaching view (E, V, I) is reported as the plain scene: the view is how
// the picture is shown, not what the report times and measures.
TEST(Report, ASavedViewDoesNotChangeTheRows) {
    REQUIRE_REPORT_CONTEXT(context);
    ReportOptions o = smallOptions();
    o.minLevel = o.maxLevel = 3;
    o.includeAuto = false;
    Scene scene = smallScene();
    const std::vector<ReportRow> plain = app::measureReport(*context, scene, o);
    scene.view.kind = ViewKind::Error;
    const std::vector<ReportRow> viewed = app::measureReport(*context, scene, o);
    ASSERT_EQ(plain.size(), viewed.size());
    for (std::size_t i = 0; i < plain.size(); ++i) {
        EXPECT_EQ(viewed[i].interiorMeanError, plain[i].interiorMeanError);
        EXPECT_EQ(viewed[i].interiorPixels, plain[i].interiorPixels);
    }
}

TEST(Report, LevelsOption) {
    ReportOptions o;
    app::parseLevels("2..6", o);
    EXPECT_EQ(o.minLevel, 2);
    EXPECT_EQ(o.maxLevel, 6);
    app::parseLevels("7", o);
    EXPECT_EQ(o.minLevel, 7);
    EXPECT_EQ(o.maxLevel, 7);
    for (const char* bad : {"6..2", "0..11", "-1..3", "a", "3..", ""}) {
        try {
            app::parseLevels(bad, o);
            ADD_FAILURE() << "accepted --levels \"" << bad << "\"";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("--levels"), std::string::npos) << e.what();
        }
    }
    o = ReportOptions{};
    o.frames = 0;
    EXPECT_THROW(app::validateReportOptions(o), InputError);
    o = ReportOptions{};
    o.warmup = 0;
    EXPECT_THROW(app::validateReportOptions(o), InputError);
}

bool haveGnuplot() {
    try {
        app::requireGnuplot();
        return true;
    } catch (const RuntimeError&) {
        return false;
    }
}

// The command end to end into a folder it creates: the three files, the CSV header, a PNG gnuplot drew.
TEST(Report, RunWritesCsvJsonAndPlot) {
    REQUIRE_REPORT_CONTEXT(context);
    if (!haveGnuplot()) {
        if (std::getenv("CI")) FAIL() << "gnuplot missing in CI (scripts/setup.sh installs gnuplot-nox)";
        GTEST_SKIP() << "gnuplot not on PATH (Debian package gnuplot-nox)";
    }
    const TempDir dir("run");
    saveScene(smallScene(), dir.path() / "small.json");
    ReportOptions o = smallOptions();
    o.scene = dir.path() / "small.json";
    o.outDir = dir.path() / "out" / "nested";
    o.minLevel = 3;
    o.maxLevel = 4;
    ASSERT_EQ(app::runReport(o), kExitOk);
    const std::vector<std::string> lines = readLines(o.outDir / "report.csv");
    ASSERT_EQ(lines.size(), 1 + kLightingModels.size() * kShadingModes.size() * 3); // levels 3, 4 and auto
    EXPECT_EQ(lines[0], joined(kDocumentedColumns));
    EXPECT_TRUE(fs::exists(o.outDir / "report.json"));
    EXPECT_TRUE(fs::exists(o.outDir / "report.gp"));
    const Image png = readPng(o.outDir / "report.png");
    EXPECT_EQ(png.width, 1280);
    EXPECT_EQ(png.height, 860);
    for (const auto& entry : fs::directory_iterator(o.outDir))
        EXPECT_NE(entry.path().filename().string().front(), '.') << "temporary file left: " << entry.path();
}

// Without gnuplot the command fails at once, before measuring, naming gnuplot and its package.
TEST(Report, MissingGnuplotIsARuntimeErrorNamingIt) {
    const TempDir dir("nognuplot");
    const char* path = std::getenv("PATH");
    const std::string savedPath = path ? path : "";
    ::setenv("PATH", dir.path().c_str(), 1);
    ReportOptions o;
    o.outDir = dir.path() / "out";
    try {
        app::runReport(o);
        ADD_FAILURE() << "ran without gnuplot";
    } catch (const RuntimeError& e) {
        EXPECT_NE(std::string(e.what()).find("gnuplot-nox"), std::string::npos) << e.what();
    }
    ::setenv("PATH", savedPath.c_str(), 1);
    EXPECT_FALSE(fs::exists(o.outDir)) << "nothing is created before the check";
}

} // namespace
} // namespace shadelab::test
