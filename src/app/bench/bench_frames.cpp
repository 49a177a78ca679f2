// The frame costs of `shadelab bench` (GPU): each shading mode's frame against a full-screen fill and against
// a one-colour draw of the same sphere, and the scenes bench/compare_glmark2.sh sets beside glmark2's
// `shading` scenes with their own one-colour limits (bench/README.md).
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <glad/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "app/bench/bench_costs.h"
#include "shadelab/gl/handles.h"
#include "shadelab/gl/loader.h"
#include "shadelab/gl/mesh.h"
#include "shadelab/gl/program.h"

namespace shadelab::app {
namespace {

// ---- frame time against the fill and raster limits ----

// The limits' programs: one colour, no lighting. Inline sources: they are part of the measurement, not of
// shadelab's shaders.
gl::Program oneColourProgram(const char* vertexSource, const char* what) {
    static constexpr const char* kFragment = "out vec4 fragColor;\n"
                                             "void main() { fragColor = vec4(1.0); }\n";
    return gl::buildProgramFromBodies(std::string("bench ") + what, vertexSource, kFragment);
}

// One triangle covering the viewport, from gl_VertexID alone.
constexpr const char* kFullScreenVertex = "void main() {\n"
                                          "    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
                                          "    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
                                          "}\n";
constexpr const char* kSphereVertex =
    "layout(location = 0) in vec3 aPositionObject; // gl::kPositionAttribute\n"
    "uniform mat4 uClipFromObject;\n"
    "void main() { gl_Position = uClipFromObject * vec4(aPositionObject, 1.0); }\n";

// What Renderer::render does before its first draw, so that a limit pays the same per-frame clears.
void beginFrame(int width, int height) {
    glViewport(0, 0, width, height);
    glClearColor(0, 0, 0, 0);
    gl::setClipDepthZeroToOne(false, "standard");
    gl::clearDepth(0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

// After the timed frames: the pixels one frame covers (read-back alpha) and the fragments that passed the
// depth test. Their quotient is the overdraw: 1.0 where every covered pixel is shaded once (the renderer
// culls back faces wherever the near plane does not cut the object open); about 1.9 when back faces are
// drawn too (frame/limits/one-colour-sphere against …-culled).
// OpenGL ES has no sample-count query (only "any samples passed"): there the overdraw is left out.
void countFragments(benchmark::State& state, Gpu& gpu, const std::function<void()>& draw) {
    GLuint samples = 0;
    if (gl::capabilities().sampleCounts) {
        const gl::Query query;
        glBeginQuery(GL_SAMPLES_PASSED, query.get());
        draw();
        glEndQuery(GL_SAMPLES_PASSED);
        glGetQueryObjectuiv(query.get(), GL_QUERY_RESULT, &samples);
    }
    const Image image = gpu.target.readRgba8();
    double covered = 0;
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) covered += image.rgba[i] != 0;
    state.counters["covered_px"] = covered;
    if (gl::capabilities().sampleCounts)
        state.counters["fragments_per_px"] = covered > 0 ? samples / covered : 0;
}

void registerFrame(Gpu& gpu, const std::string& name, const std::function<void()>& draw) {
    benchmark::RegisterBenchmark(name.c_str(),
                                 [&gpu, draw](benchmark::State& state) {
                                     gpu.renderer.setSpecialization(gl::Specialization::Values);
                                     gpu.renderer.setFlatGeometryShader(false);
                                     gpu.timeFrames(state, draw);
                                     countFragments(state, gpu, draw);
                                     gl::checkGlError("bench: a timed frame");
                                 })
        ->UseManualTime()
        ->Iterations(gpu.options.frames)
        ->Unit(benchmark::kMillisecond);
}

} // namespace

// The limits are built on the first frame of the benchmark that uses them (a current context is needed)
// and kept for the run: the context outlives every benchmark.
struct Limits {
    gl::Program fill{gl::NoCreate}, sphere{gl::NoCreate};
    int sphereClipFromObject = -1; // uClipFromObject, found once
    gl::VertexArray empty{gl::NoCreate};
    std::map<int, std::unique_ptr<gl::GpuMesh>> meshes;
    void build() {
        if (fill) return;
        fill = oneColourProgram(kFullScreenVertex, "full-screen fill");
        sphere = oneColourProgram(kSphereVertex, "one-colour sphere");
        sphereClipFromObject = glGetUniformLocation(sphere.get(), "uClipFromObject");
        empty = gl::VertexArray();
    }
    const gl::GpuMesh& mesh(int level) {
        auto& slot = meshes[level];
        if (!slot) slot = std::make_unique<gl::GpuMesh>(buildSphere(level), gl::MeshLayout::Smooth);
        return *slot;
    }
};

std::shared_ptr<Limits> makeLimits() {
    return std::make_shared<Limits>();
}

namespace {

void drawFill(Limits& limits, int width, int height) {
    limits.build();
    beginFrame(width, height);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(limits.fill.get());
    glBindVertexArray(limits.empty.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
}

} // namespace

void drawOneColour(Limits& limits, const Scene& scene, bool cullBackFaces) {
    limits.build();
    const SceneView view = sceneView(scene);
    beginFrame(scene.width, scene.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    if (cullBackFaces) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK); // triangles are counter-clockwise seen from outside
    }
    glUseProgram(limits.sphere.get());
    for (const SceneObject& object : scene.objects) {
        const glm::mat4 clipFromObject(view.clipFromView * view.viewFromWorld * worldFromObject(object));
        glUniformMatrix4fv(limits.sphereClipFromObject, 1, GL_FALSE, glm::value_ptr(clipFromObject));
        limits.mesh(object.subdivisions).draw();
    }
    glUseProgram(0);
    glDisable(GL_CULL_FACE);
}

namespace {

Scene sized(Scene scene, const BenchOptions& o, int level) {
    scene.width = o.width;
    scene.height = o.height;
    for (SceneObject& object : scene.objects) object.subdivisions = level;
    return scene;
}

std::vector<RatioSpec> registerModes(Gpu& gpu, const std::shared_ptr<Limits>& limits) {
    const BenchOptions& o = gpu.options;
    const Scene oneLight = sized(Scene{}, o, 6); // DESIGN §4's default scene: one point light, Blinn-Phong
    registerFrame(gpu, "frame/limits/clear", [o] { beginFrame(o.width, o.height); });
    registerFrame(gpu, "frame/limits/fill", [limits, o] { drawFill(*limits, o.width, o.height); });
    registerFrame(gpu, "frame/limits/one-colour-sphere",
                  [limits, oneLight] { drawOneColour(*limits, oneLight, false); });
    registerFrame(gpu, "frame/limits/one-colour-sphere-culled",
                  [limits, oneLight] { drawOneColour(*limits, oneLight, true); });
    std::vector<RatioSpec> ratios;
    for (const ShadingMode mode : kShadingModes) {
        Scene scene = oneLight;
        scene.shading = mode;
        const std::string name = "frame/modes/" + std::string(toString(mode));
        registerFrame(gpu, name, [&gpu, scene] { gpu.renderer.render(scene, scene.width, scene.height); });
        ratios.push_back(
            {std::string(toString(mode)) + " L6: frame / full-screen fill", name, "frame/limits/fill"});
        // The renderer culls back faces (gl/renderer.cpp), so the raster limit is the culled draw.
        ratios.push_back({std::string(toString(mode)) + " L6: frame / one-colour sphere (culled)", name,
                          "frame/limits/one-colour-sphere-culled"});
    }
    // Exact shading against Phong shading, the mesh it replaces, at level 6 and 8: the ray cast
    // per pixel against the triangles' vertex work.
    Scene exact = oneLight;
    exact.shading = ShadingMode::Exact;
    registerFrame(gpu, "frame/modes/exact",
                  [&gpu, exact] { gpu.renderer.render(exact, exact.width, exact.height); });
    Scene phong8 = sized(Scene{}, o, 8);
    registerFrame(gpu, "frame/modes/phong-level8",
                  [&gpu, phong8] { gpu.renderer.render(phong8, phong8.width, phong8.height); });
    // The teapot (DESIGN §1): its patches ray-cast from a proxy mesh against its level-6 mesh, framed as
    // scenes/teapot.json frames it.
    Scene teapotPhong = oneLight;
    teapotPhong.objects[0].shape = Shape::Teapot;
    teapotPhong.eye = {1.0, 2.0, 4.7};
    teapotPhong.target = {0.15, -0.1, 0};
    Scene teapotExact = teapotPhong;
    teapotExact.shading = ShadingMode::Exact;
    registerFrame(gpu, "frame/teapot/phong-level6", [&gpu, teapotPhong] {
        gpu.renderer.render(teapotPhong, teapotPhong.width, teapotPhong.height);
    });
    registerFrame(gpu, "frame/teapot/exact", [&gpu, teapotExact] {
        gpu.renderer.render(teapotExact, teapotExact.width, teapotExact.height);
    });
    ratios.push_back({"teapot: exact / phong L6", "frame/teapot/exact", "frame/teapot/phong-level6"});
    ratios.push_back({"exact / phong L6", "frame/modes/exact", "frame/modes/phong"});
    ratios.push_back({"exact / phong L8", "frame/modes/exact", "frame/modes/phong-level8"});
    ratios.push_back({"full-screen fill / clear", "frame/limits/fill", "frame/limits/clear"});
    ratios.push_back({"one-colour sphere: back faces drawn / culled", "frame/limits/one-colour-sphere",
                      "frame/limits/one-colour-sphere-culled"});
    return ratios;
}

// ---- the scene set beside glmark2's `shading` scenes (bench/compare_glmark2.sh) ----

// glmark2 (src/scene-shading.cpp) frames any model from its bounding box: with r half the box's diagonal,
// the model's centre at distance 2 + r, fovy = 2·atan(r/(2 + r)), near 2, far 2 + 2r. Here: the level-6
// sphere (16,384 faces) framed exactly so, which is what glmark2 draws when compare_glmark2.sh hands it this
// sphere as a model (its box is [−1, 1]³ to within 1e-3, so r = √3: a silhouette of 179.8 px radius of 600,
// ≈ 101,600 px). Lit as glmark2 lights each mode. glmark2 gives lights in eye space; the camera here looks
// down −z from (0, 0, d), so a point moves by d along z into world space and a direction stays.
struct Glmark2Framing {
    double halfDiagonal = std::numbers::sqrt3;
    double distance() const { return 2 + halfDiagonal; }
    double fovyDeg() const { return 2 * std::atan(halfDiagonal / distance()) * 180 / std::numbers::pi; }
};

Scene glmark2Scene(const BenchOptions& o, const char* glmark2Mode) {
    Scene scene = sized(Scene{}, o, 6);
    const Glmark2Framing framing;
    const double d = framing.distance();
    scene.eye = {0, 0, d};
    scene.projection.fovyDeg = framing.fovyDeg();
    scene.projection.near = 2;
    scene.projection.far = 2 + 2 * framing.halfDiagonal;
    Material& m = scene.objects[0].material;
    m.diffuse = {0, 0, 1}; // glmark2's MaterialDiffuse
    m.specular = {1, 1, 1};
    m.shininess = 100;
    Light light;
    light.diffuse = light.specular = glm::dvec3(0.8);
    light.ambient = glm::dvec3(0.1);
    const std::string mode = glmark2Mode;
    if (mode == "gouraud") { // light-basic.vert: diffuse only, light at infinity
        scene.shading = ShadingMode::Gouraud;
        light.type = LightType::Directional;
        light.direction = {-20, -20, -10};
        light.diffuse = glm::dvec3(1);
        light.ambient = light.specular = glm::dvec3(0);
        m.ambient = m.specular = glm::dvec3(0);
    } else if (mode == "blinn-phong-inf") { // light-advanced.frag: per fragment, light at infinity
        scene.shading = ShadingMode::Phong;
        scene.lighting = LightingModel::BlinnPhong;
        light.type = LightType::Directional;
        light.direction = {-20, -20, -10};
        m.ambient = glm::dvec3(1);
    } else if (mode == "phong") { // light-phong.frag, one light: per fragment, point light at (0, 1, 0)
        scene.shading = ShadingMode::Phong;
        scene.lighting = LightingModel::Phong;
        light.type = LightType::Point;
        light.position = {0, 1, d};
        m.ambient = glm::dvec3(0.2);
    } else { // cel, light-cel.frag: point light at (4, 3, 1), diffuse lit or not, thresholded highlight
        scene.shading = ShadingMode::Toon;
        scene.lighting = LightingModel::Phong; // its highlight is pow(max(0, reflect(−L, N)·V), 10)
        scene.toonBands = kMinToonBands;
        light.type = LightType::Point;
        light.position = {4, 3, 1 + d};
        light.ambient = glm::dvec3(0);
        m.diffuse = {0, 0.6, 0};
        m.shininess = 10;
    }
    scene.lights = {light};
    return scene;
}

void registerGlmark2Equivalents(Gpu& gpu, const std::shared_ptr<Limits>& limits) {
    for (const char* mode : {"gouraud", "blinn-phong-inf", "phong", "cel"}) {
        const Scene scene = glmark2Scene(gpu.options, mode);
        registerFrame(gpu, std::string("frame/glmark2-equivalent/") + mode,
                      [&gpu, scene] { gpu.renderer.render(scene, scene.width, scene.height); });
    }
    // The raster limits of this geometry: back faces drawn, and culled as shadelab and glmark2 both do.
    const Scene scene = glmark2Scene(gpu.options, "phong");
    registerFrame(gpu, "frame/glmark2-equivalent/one-colour",
                  [limits, scene] { drawOneColour(*limits, scene, false); });
    registerFrame(gpu, "frame/glmark2-equivalent/one-colour-culled",
                  [limits, scene] { drawOneColour(*limits, scene, true); });
}

} // namespace

std::vector<RatioSpec> registerFrameCosts(Gpu& gpu, const std::shared_ptr<Limits>& limits) {
    std::vector<RatioSpec> ratios = registerModes(gpu, limits);
    registerGlmark2Equivalents(gpu, limits);
    return ratios;
}

} // namespace shadelab::app
