// measureReport: every shading mode × lighting model × level of one scene, each row timed and measured.
// Frame times follow the bench's method (app/measure/frame_timing.h): one context, one renderer and one
// offscreen target for the whole run, glFinish after every frame, median and 10th/90th percentiles of the
// frames after a warm-up. The error of each configuration is taken from the same scene rendered once more
// into an RGBA32F target, so that it is the shading's error and not the 8-bit rounding's.
#include "app/report/report.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <tuple>
#include <utility>

#include "app/measure/frame_timing.h"
#include "app/measure/shape_levels.h"
#include "shadelab/errors.h"
#include "shadelab/geometry/mesh_layout.h"
#include "shadelab/geometry/subdivision.h"
#include "shadelab/geometry/teapot.h"
#include "shadelab/gl/loader.h"
#include "shadelab/gl/mesh.h"
#include "shadelab/gl/program.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/scene/auto_level.h"
#include "shadelab/scene/model.h"

namespace shadelab::app {

namespace {

// One distinct mesh of a configuration: a shape at a level, built and timed once per configuration of
// levels, or a model (read with the scene, so nothing to build).
struct BuiltLevel {
    TriangleMesh mesh;
    double buildMs = 0;
    double radialDeviation = 0, normalErrorDeg = 0;
};
struct MeshKey {
    Shape shape = Shape::Sphere;
    int level = 0;
    const Model* model = nullptr;
    // Spelled out: clang-tidy 14 reads a defaulted operator<=> as a literal 0 (modernize-use-nullptr).
    bool operator<(const MeshKey& other) const {
        return std::tie(shape, level, model) < std::tie(other.shape, other.level, other.model);
    }
};
using BuiltMeshes = std::map<MeshKey, BuiltLevel>;

MeshKey meshKey(const Scene& scene, const SceneObject& object) {
    if (object.shape == Shape::Mesh) return {Shape::Mesh, 0, object.model.get()};
    return {object.shape, subdivisionLevel(scene, object), nullptr};
}

// The GL objects of one run; destroyed (while the context is current) when measureReport returns.
struct GlRun {
    GlRun(int width, int height)
        : frameTarget(width, height, gl::ColorFormat::Rgba8),
          errorTarget(width, height, gl::ColorFormat::Rgba32F),
          tetrahedronSmooth(buildSphere(0), gl::MeshLayout::Smooth),
          tetrahedronFlat(buildSphere(0), gl::MeshLayout::Flat) {}
    gl::Renderer renderer; // programs with each object's values compiled in, as `shadelab render` draws
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

constexpr int kOneOffRepeats = 3;

// Compile and link of a program variant up to its first draw, synchronized: Mesa translates to machine code
// at the first draw, not at glLinkProgram. Measured once per variant, before the renderer builds its own
// copy: the first compile of that source in the process (the driver's on-disk shader cache may still
// serve it; see the README).
double compileMs(GlRun& gl, const gl::ProgramVariant& variant, gl::MeshLayout layout) {
    gl.frameTarget.bind();
    gl::finish();
    return compileAndFirstDrawMs(variant,
                                 layout == gl::MeshLayout::Flat ? gl.tetrahedronFlat : gl.tetrahedronSmooth);
}

// The upload and frame times of `scene` as configured.
void measureTime(GlRun& gl, const Scene& scene, const BuiltMeshes& built, const ReportOptions& o,
                 ReportRow& row) {
    const gl::MeshLayout layout = layoutOf(scene.shading);
    for (const auto& entry : built) {
        const TriangleMesh& built = entry.second.mesh; // a structured binding cannot be captured (C++20)
        std::optional<gl::GpuMesh> mesh;
        row.uploadMs += medianOneOffMs(
            kOneOffRepeats, [&] { mesh.reset(); },
            [&] {
                mesh.emplace(built, layout);
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

void setGeometry(const Scene& scene, const BuiltMeshes& built, ReportRow& row) {
    for (const SceneObject& object : scene.objects) {
        const int level = subdivisionLevel(scene, object);
        row.triangles += triangleCount(object, level);
        row.level = std::max(row.level, level);
    }
    for (const auto& [key, b] : built) {
        const double vertices = double(b.mesh.positions.size()), triangles = double(b.mesh.triangles.size());
        row.vertexBytes += std::size_t(scene.shading == ShadingMode::Flat
                                           ? triangles * 3 * double(sizeof(FlatVertex))
                                           : vertices * double(sizeof(SmoothVertex)) +
                                                 triangles * 3 * double(sizeof(std::uint32_t)));
        row.maxRadialDeviation = std::max(row.maxRadialDeviation, b.radialDeviation);
        row.maxNormalErrorDeg = std::max(row.maxNormalErrorDeg, b.normalErrorDeg);
    }
}

// The distinct meshes the objects of `base` use (what gets uploaded), each built and measured. The
// teapot's distance from its patches is teapotMeshError's bound (DESIGN §1), relative to its bounding
// radius as the sphere's δₙ is to its radius; a model's is none (its mesh is its surface).
BuiltMeshes buildLevels(const Scene& base) {
    BuiltMeshes built;
    for (const SceneObject& object : base.objects) {
        const MeshKey key = meshKey(base, object);
        if (built.count(key)) continue;
        BuiltLevel& b = built[key];
        if (key.shape == Shape::Sphere) {
            SphereMesh sphere;
            b.buildMs = medianOneOffMs(
                kOneOffRepeats, [&] { sphere = SphereMesh{}; },
                [&] { sphere = buildSphere(key.level, base.vertexNormals); });
            b.radialDeviation = maxRadialDeviation(sphere);
            b.normalErrorDeg = maxFaceNormalErrorDeg(sphere);
            b.mesh = std::move(sphere);
        } else if (key.shape == Shape::Teapot) {
            TeapotMesh teapot;
            b.buildMs = medianOneOffMs(
                kOneOffRepeats, [&] { teapot = TeapotMesh{}; }, [&] { teapot = buildTeapot(key.level); });
            b.radialDeviation = teapotMeshError(key.level) / teapotBoundingRadius();
            b.normalErrorDeg = maxFaceNormalErrorDeg(teapot);
            b.mesh = std::move(teapot);
        } else if (key.model) {
            b.mesh = key.model->mesh;
        }
    }
    return built;
}

// What the configurations of one report share: the exact images (per lighting model × toon or not: the
// exact image depends on nothing else the report varies) and the compile times per program variant.
struct ReportCaches {
    std::map<std::pair<LightingModel, bool>, ReferenceImage> references;
    std::map<gl::ProgramVariant, double> compileTimes;
};

// One configuration's row: its geometry, compile and frame times, and its error against the reference.
void measureRow(GlRun& gl, const Scene& configured, const BuiltMeshes& built, const ReportOptions& options,
                ReportCaches& caches, ReportRow& row) {
    for (const auto& [key, b] : built) row.meshBuildMs += b.buildMs;
    setGeometry(configured, built, row);
    // The first object's program (with values compiled in: one per distinct material).
    gl::ProgramVariant variant =
        gl::ProgramVariant::forScene(configured, gl.renderer.specialization() != gl::Specialization::None);
    if (gl.renderer.specialization() == gl::Specialization::Values && !configured.objects.empty())
        variant = variant.withValues(configured, configured.objects[0].material);
    if (!caches.compileTimes.count(variant))
        caches.compileTimes[variant] = compileMs(gl, variant, layoutOf(configured.shading));
    row.compileMs = caches.compileTimes[variant];
    measureTime(gl, configured, built, options, row);

    const bool toon = configured.shading == ShadingMode::Toon;
    auto reference = caches.references.find({configured.lighting, toon});
    if (reference == caches.references.end())
        reference =
            caches.references
                .emplace(std::pair{configured.lighting, toon}, renderReference(withTrueNormals(configured)))
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
}

} // namespace

std::vector<int> reportLevels(const Scene& scene, const ReportOptions& options) {
    // A level above the finest of every object's shape would measure the finest again; a scene of models
    // only has one configuration, their own meshes, and no "auto".
    int finest = 0;
    for (const SceneObject& object : scene.objects) finest = std::max(finest, finestLevel(object.shape));
    std::vector<int> levels;
    for (int level = std::min(options.minLevel, finest); level <= std::min(options.maxLevel, finest); ++level)
        levels.push_back(level);
    if (options.includeAuto && finest > 0) levels.push_back(kAutoSubdivisions);
    return levels;
}

std::vector<ReportRow> measureReport(HeadlessContext& context, const Scene& scene,
                                     const ReportOptions& options, const ReportProgress& progress) {
    validateReportOptions(options);
    validateScene(scene);
    if (scene.objects.empty())
        throw InputError("report: the scene has no objects, so there is nothing to measure");

    const std::vector<int> levelConfigs = reportLevels(scene, options);
    const std::size_t perMode = levelConfigs.size();
    const int total = int(kLightingModels.size() * kShadingModes.size() * perMode);
    std::vector<ReportRow> rows(static_cast<std::size_t>(total));

    context.makeCurrent();
    GlRun gl(scene.width, scene.height);
    ReportCaches caches;
    int done = 0;
    for (std::size_t c = 0; c < perMode; ++c) {
        Scene base = scene;
        base.view = View{}; // the report times and measures the shading itself, not a teaching view of it
        for (SceneObject& object : base.objects)
            object.subdivisions = levelConfigs[c] == kAutoSubdivisions
                                      ? kAutoSubdivisions
                                      : std::min(levelConfigs[c], finestLevel(object.shape));
        const BuiltMeshes built = buildLevels(base);
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
                measureRow(gl, configured, built, options, caches, row);
                ++done;
            }
        }
    }
    if (progress) progress(done, total, "done");
    return rows;
}

} // namespace shadelab::app
