// `shadelab bench`, issue 5: what shadelab's work costs against the limits of this machine, each limit
// measured in the same run — sphere generation against memcpy of its output bytes and against the
// lecture's naive recursion; each shading mode's frame against a full-screen fill and against a one-colour
// draw of the same sphere; `shadelab render` from start to PNG against an empty process start — and the
// scene bench/compare_glmark2.sh sets beside glmark2's `shading` scenes.
#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <glad/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include "app/bench/bench_gpu.h"
#include "shadelab/errors.h"
#include "shadelab/gl/handles.h"
#include "shadelab/gl/loader.h"
#include "shadelab/gl/mesh.h"
#include "shadelab/gl/program.h"

extern char** environ;

namespace shadelab::app {
namespace {

// ---- sphere generation (CPU) ----

double wallSeconds() {
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Wall time: generation uses both cores for large levels (sphere.cpp), which the calling thread's CPU time
// would not see; so quote these figures from a quiet machine, as the frame times. One iteration repeats
// `work` for about 2 ms so that the clock's own cost vanishes at level 0; median_ms is the time of one
// call.
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

std::vector<RatioSpec> registerGeneration() {
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

// ---- frame time against the fill and raster limits (GPU) ----

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
        GLuint query = 0;
        glGenQueries(1, &query);
        glBeginQuery(GL_SAMPLES_PASSED, query);
        draw();
        glEndQuery(GL_SAMPLES_PASSED);
        glGetQueryObjectuiv(query, GL_QUERY_RESULT, &samples);
        glDeleteQueries(1, &query);
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
                                     gpu.renderer.setSpecialize(true);
                                     gpu.renderer.setFlatGeometryShader(false);
                                     gpu.timeFrames(state, draw);
                                     countFragments(state, gpu, draw);
                                     gl::checkGlError("bench: a timed frame");
                                 })
        ->UseManualTime()
        ->Iterations(gpu.options.frames)
        ->Unit(benchmark::kMillisecond);
}

// The limits are built on the first frame of the benchmark that uses them (a current context is needed)
// and kept for the run: the context outlives every benchmark.
struct Limits {
    gl::Program fill, sphere;
    gl::VertexArray empty;
    std::map<int, std::unique_ptr<gl::GpuMesh>> meshes;
    void build() {
        if (fill) return;
        fill = oneColourProgram(kFullScreenVertex, "full-screen fill");
        sphere = oneColourProgram(kSphereVertex, "one-colour sphere");
        GLuint id = 0;
        glGenVertexArrays(1, &id);
        empty = gl::VertexArray(id);
    }
    const gl::GpuMesh& mesh(int level) {
        auto& slot = meshes[level];
        if (!slot) slot = std::make_unique<gl::GpuMesh>(buildSphere(level), gl::MeshLayout::Smooth);
        return *slot;
    }
};

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

// The scene's first object, with the renderer's depth set-up and clip matrix, in one colour. The renderer
// draws back faces too (an object cut open by the near plane shows its inside, as in the reference);
// `cullBackFaces` measures what that costs on a closed sphere.
void drawOneColour(Limits& limits, const Scene& scene, bool cullBackFaces) {
    limits.build();
    const SceneView view = sceneView(scene);
    const SceneObject& object = scene.objects[0];
    const glm::mat4 clipFromObject(view.clipFromView * view.viewFromWorld * worldFromObject(object));
    beginFrame(scene.width, scene.height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    if (cullBackFaces) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK); // triangles are counter-clockwise seen from outside
    }
    glUseProgram(limits.sphere.get());
    glUniformMatrix4fv(glGetUniformLocation(limits.sphere.get(), "uClipFromObject"), 1, GL_FALSE,
                       glm::value_ptr(clipFromObject));
    gl::drawWith(limits.sphere, limits.mesh(object.subdivisions));
    glDisable(GL_CULL_FACE);
}

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
    // Exact shading (issue 11) against Phong shading, the mesh it replaces, at level 6 and 8: the ray cast
    // per pixel against the triangles' vertex work.
    Scene exact = oneLight;
    exact.shading = ShadingMode::Exact;
    registerFrame(gpu, "frame/modes/exact",
                  [&gpu, exact] { gpu.renderer.render(exact, exact.width, exact.height); });
    Scene phong8 = sized(Scene{}, o, 8);
    registerFrame(gpu, "frame/modes/phong-level8",
                  [&gpu, phong8] { gpu.renderer.render(phong8, phong8.width, phong8.height); });
    ratios.push_back({"exact / phong L6", "frame/modes/exact", "frame/modes/phong"});
    ratios.push_back({"exact / phong L8", "frame/modes/exact", "frame/modes/phong-level8"});
    ratios.push_back({"full-screen fill / clear", "frame/limits/fill", "frame/limits/clear"});
    ratios.push_back({"one-colour sphere: back faces drawn / culled", "frame/limits/one-colour-sphere",
                      "frame/limits/one-colour-sphere-culled"});
    return ratios;
}

// ---- the scene set beside glmark2's `shading` scenes (bench/compare_glmark2.sh) ----

// glmark2 (src/scene-shading.cpp) draws its cat (≈14,300 faces) covering 15–20 % of 800×600. Here: a
// level-6 sphere (16,384 faces) at the distance where its silhouette's radius is 170 px of a 600 px height
// (≈ 90,800 px), lit as glmark2 lights each mode. glmark2 gives lights in eye space; the camera here looks
// down −z from (0, 0, d), so a point moves by d along z into world space and a direction stays.
inline constexpr double kGlmark2RadiusPx = 170, kGlmark2Height = 600;

double glmark2Distance(const Scene& scene) {
    // A unit sphere at distance d spans the half-angle asin(1/d), which projects to
    // R = (H/2)·tan(asin(1/d))/tan(fovy/2) pixels; solved for d.
    const double radiusPx = kGlmark2RadiusPx * scene.height / kGlmark2Height;
    const double tanHalfAngle =
        radiusPx / (scene.height / 2.0) * std::tan(scene.projection.fovyDeg * std::numbers::pi / 360);
    return 1 / std::sin(std::atan(tanHalfAngle));
}

Scene glmark2Scene(const BenchOptions& o, const char* glmark2Mode) {
    Scene scene = sized(Scene{}, o, 6);
    const double d = glmark2Distance(scene);
    scene.eye = {0, 0, d};
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

// ---- headless start to PNG (processes) ----

// A temporary folder removed with everything in it when the benchmark ends.
struct TempDir {
    std::filesystem::path path;
    TempDir() {
        std::string pattern = (std::filesystem::temp_directory_path() / "shadelab-bench-XXXXXX").string();
        if (!mkdtemp(pattern.data())) throw RuntimeError("bench: cannot create a temporary folder");
        path = pattern;
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

// Runs `args` with stdout and stderr to `log` and the parent's environment (less `unset`), and returns
// the wall time from spawn to exit. A child that cannot start or exits non-zero throws with its output.
double runProcess(const std::vector<std::string>& args, const char* unset, const std::filesystem::path& log) {
    std::vector<char*> argv, envp;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const std::string drop = unset ? std::string(unset) + "=" : std::string();
    for (char** e = environ; *e; ++e)
        if (drop.empty() || std::strncmp(*e, drop.c_str(), drop.size()) != 0) envp.push_back(*e);
    envp.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    const auto start = std::chrono::steady_clock::now();
    pid_t pid = 0;
    const int error = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) throw RuntimeError("bench: cannot start " + args[0] + ": " + std::strerror(error));
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throw RuntimeError("bench: waiting for " + args[0] + ": " + std::strerror(errno));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::string command;
        for (const std::string& a : args) command += " " + a;
        std::ifstream file(log);
        const std::string output((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        throw RuntimeError("bench:" + command + ": failed; its output:\n" + output);
    }
    return seconds;
}

void registerProcess(const std::string& name,
                     const std::function<std::vector<std::string>(const TempDir&)>& args,
                     const char* unsetVariable = nullptr) {
    benchmark::RegisterBenchmark(name.c_str(),
                                 [args, unsetVariable](benchmark::State& state) {
                                     const TempDir dir;
                                     const std::vector<std::string> command = args(dir);
                                     runProcess(command, unsetVariable, dir.path / "log"); // page cache
                                     std::vector<double> ms;
                                     for (auto _ : state) {
                                         const double s =
                                             runProcess(command, unsetVariable, dir.path / "log");
                                         state.SetIterationTime(s);
                                         ms.push_back(s * 1e3);
                                     }
                                     setSpread(state, ms);
                                 })
        ->UseManualTime()
        ->Iterations(11)
        ->Unit(benchmark::kMillisecond);
}

std::vector<RatioSpec> registerStartToPng(const BenchOptions& o) {
    const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
    const std::string backend(toString(o.context.backend)), api(toString(o.context.api));
    const auto render = [self, backend, api](const TempDir& dir) {
        return std::vector<std::string>{
            self,    "render", "--size", "512x512", "--backend",
            backend, "--api",  api,      "--out",   (dir.path / "x.png").string()};
    };
    // runBench disables Mesa's shader cache for the whole run; a user's second start finds it warm.
    registerProcess("process/render-512/shader-cache-off", render);
    registerProcess("process/render-512/shader-cache-warm", render, "MESA_SHADER_CACHE_DISABLE");
    registerProcess("process/help", [self](const TempDir&) {
        return std::vector<std::string>{self, "--help"};
    });
    registerProcess("process/true", [](const TempDir&) { return std::vector<std::string>{"/bin/true"}; });
    return {{"render 512 (no shader cache) / shadelab --help", "process/render-512/shader-cache-off",
             "process/help"},
            {"render 512 (warm shader cache) / shadelab --help", "process/render-512/shader-cache-warm",
             "process/help"},
            {"render 512 (warm shader cache) / /bin/true", "process/render-512/shader-cache-warm",
             "process/true"}};
}

} // namespace

std::vector<RatioSpec> registerCostBenchmarks(Gpu& gpu) {
    auto limits = std::make_shared<Limits>();
    std::vector<RatioSpec> ratios = registerGeneration();
    for (RatioSpec& r : registerModes(gpu, limits)) ratios.push_back(std::move(r));
    registerGlmark2Equivalents(gpu, limits);
    for (RatioSpec& r : registerStartToPng(gpu.options)) ratios.push_back(std::move(r));
    return ratios;
}

} // namespace shadelab::app
