// The one draw of a Scene (DESIGN §7's one renderer: render, report, bench, the window and the page all draw
// through it): the scene's objects, shaded as its mode says, into whatever framebuffer is bound, with the
// overlay over them. Everything a draw depends on is an argument — the scene, the viewport and the options
// that pick the programs' variant — so that the views (gl/views.h) compose draws without switching anything
// between them; what a SceneDraw keeps is caches of what it built (programs, meshes, plans, lines).
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <tuple>
#include <vector>

#include "shadelab/gl/mesh.h"
#include "shadelab/gl/program.h"
#include "shadelab/scene/model.h"
#include "shadelab/scene/scene.h"

namespace shadelab::gl {

// Where a draw goes: the rectangle (x, 0, width, height) of the bound framebuffer.
struct Viewport {
    int x = 0, width = 0, height = 0;
};

// How a draw writes its pixels, chosen with the programs it draws with (as ProgramVariant's defines are).
struct DrawOptions {
    // How far programs are specialized (gl/program_variant.h), and flat shading from shared vertices and a
    // geometry shader instead of duplicated vertices with face data (the same picture; `shadelab bench`).
    Specialization specialization = Specialization::Values;
    bool flatGeometryShader = false;
    // Exact shading writes each object's index + 1 as alpha instead of 1 (the error view's compare pass).
    bool exactObjectIds = false;
    // Exact shading quantizes the lighting as toon shading does (the error view's exact answer for toon).
    bool exactToon = false;
    // The NDC view: the meshes (and their overlay) drawn through the camera's M_proj·M_cam into its NDC
    // space and on through this matrix, every fragment outside the camera's clip volume discarded; the
    // camera's standard-depth matrices are used whatever its depth mode, so NDC is the cube [−1, 1]³. Exact
    // shading has no mesh to transform (the scene check refuses it).
    std::optional<glm::dmat4> observerClipFromNdc;
};

// The level of the teapot's mesh that exact shading refines its rays from (DESIGN §3 "Open surfaces"):
// finer costs vertices, coarser a wider push along the normals and starts farther from the hit. Measured
// 2026-11-28, llvmpipe on a shared 2-core machine (tests/gl/teapot_draw_test.cpp's three views at 256²,
// interior pixels over 2/255 of the CPU reference; a level-6 teapot's frame at 512², exact against Phong,
// medians of 5 × 10 frames, the machine's load 5–6): level 4: 31–70 pixels, ×2.0; level 5: 0–3, ×2.1–3.3;
// level 6: 0–2, ×5.3.
inline constexpr int kExactProxyLevel = 5;

// The teapot's exact-shading proxy at `level` (scene_draw_exact.cpp) and its bounding radius in object units.
TeapotMesh exactTeapotProxy(int level);
double teapotBoundRadius();

class SceneDraw {
public:
    SceneDraw();
    ~SceneDraw();
    SceneDraw(const SceneDraw&) = delete;
    SceneDraw& operator=(const SceneDraw&) = delete;

    // `scene` itself, whatever its view says, over the viewport (whose size may differ from the scene's
    // image size; the aspect comes from the viewport). The clear covers the whole target; a 0×0 viewport
    // draws nothing. With scene.overlay, the objects' edges (normals, lights) are drawn over them.
    void draw(const Scene& scene, const Viewport& viewport, const DrawOptions& options);
    // Lines given in view space over what draw() drew into the same viewport, never hidden (the probe's).
    void drawLinesOver(const Scene& scene, std::span<const LineVertex> linesView, const Viewport& viewport);
    // World-space triangles and lines (GL_LINES pairs), depth-tested against what scene's draw left in the
    // depth buffer (lines behind an object are hidden): the triangles first, blended with `faceAlpha` and
    // without writing depth, then the lines opaque over them.
    void drawWorld(const Scene& scene, std::span<const LineVertex> linesWorld,
                   std::span<const LineVertex> trianglesWorld, float faceAlpha, const Viewport& viewport);
    // Programs compiled so far: switching back to a variant already built never recompiles.
    int programsBuilt() const { return programsBuilt_; }

private:
    // A mesh on the GPU and what the draw needs to know of it, kept by what it was built from.
    struct CachedMesh {
        std::shared_ptr<const Model> model; // a model's: held, so its address is not reused under the key
        std::unique_ptr<GpuMesh> mesh;
        double boundRadiusObject = 1; // the largest |p| of the surface, in object units (cullBackFaces)
    };
    // The object's mesh in `layout`: the sphere's and the teapot's at the object's level (the teapot's
    // exact proxy at kExactProxyLevel), a model's own.
    const CachedMesh& mesh(const Scene& sized, const SceneObject& object, MeshLayout layout);
    const SurfaceProgram& program(const ProgramVariant& variant);
    struct LineProgram {
        Program program;
        int clipFromSpace = -1; // uClipFromSpace, looked up once
        int translucency = -1;  // uTranslucency
    };
    const LineProgram& lineProgram();
    void drawOverlay(const Scene& sized, const SceneView& view, const DrawOptions& options);
    // The lights' markers of the "lights" overlay, made again only when what they depend on changes.
    std::span<const LineVertex> lightMarkers(const Scene& sized);
    // The matrices of `scene` at the viewport's size, with the viewport and the clip range of its depth mode
    // set, for lines drawn over what draw() drew there.
    SceneView viewportOver(const Scene& scene, const Viewport& viewport);
    // How an object is drawn: as a mesh (every shading mode but exact; in exact shading a model, whose
    // reference is Phong of its own normals), or ray cast — the sphere through a rectangle, the teapot's
    // patches refined from a proxy mesh.
    enum class ObjectKind { Mesh, ExactSphere, ExactPatches };
    struct ObjectPlan {
        ObjectKind kind = ObjectKind::Mesh;
        const SurfaceProgram* program = nullptr;
        const CachedMesh* mesh = nullptr; // none for the exact sphere
        bool closed = true;               // isClosed: back faces culled, else lit two-sided
    };
    // What each object of a scene is drawn with, resolved once for the scene and kept while neither it nor
    // an option changes: a frame then builds no variant's #define text and finds no program or mesh in a
    // map (programs_ and meshes_ never drop an entry, so the pointers stay valid).
    struct DrawPlan {
        Scene scene;                     // the scene as draw() draws it (atSize, the term)
        ProgramVariant variant;          // the frame's variant, before an object's values
        Specialization specialization{}; // the options' when it was made
        std::vector<ObjectPlan> objects; // one per object
    };
    const DrawPlan& drawPlan(const Scene& sized, const ProgramVariant& variant,
                             Specialization specialization);
    ObjectPlan objectPlan(const Scene& sized, const SceneObject& object, const ProgramVariant& variant,
                          Specialization specialization);
    // Binds, for a frame, the program that draws each object (scene_draw.cpp).
    class ObjectBinder;
    void drawMesh(const Scene& sized, const SceneView& view, const ProgramVariant& variant,
                  const ObjectPlan& plan, std::size_t index, ObjectBinder& bind, const DrawOptions& options);
    // Exact shading (scene_draw_exact.cpp), with the object's program bound.
    void drawExactSphere(const Scene& sized, const SceneView& view, std::size_t index,
                         const SurfaceLocations& at, int x, const DrawOptions& options);
    void drawExactPatches(const Scene& sized, const SceneView& view, const ObjectPlan& plan,
                          std::size_t index, const SurfaceLocations& at, int x, const DrawOptions& options);

    int programsBuilt_ = 0;
    std::map<ProgramVariant, std::unique_ptr<SurfaceProgram>> programs_;
    // By shape, model (null but for a model), level (0 for a model), the sphere's normals and the layout.
    std::map<std::tuple<Shape, const Model*, int, VertexNormals, MeshLayout>, CachedMesh> meshes_;
    Buffer teapotPatches_{NoCreate}; // the control points' uniform block (made at first use)
    std::unique_ptr<LineProgram> lineProgram_;
    // The overlay's lines of an object (diagram/overlay.h, diagram/mesh_overlay.h), by shape, model (null
    // but for a model), level (0 for a model), the sphere's normals, overlay and, for the normals, the
    // object's scale and the normal-matrix rule.
    using OverlayKey =
        std::tuple<Shape, const Model*, int, VertexNormals, Overlay, std::array<double, 3>, NormalMatrixRule>;
    struct CachedLines {
        std::shared_ptr<const Model> model; // a model's: held, so its address is not reused under the key
        std::unique_ptr<GpuLines> lines;
    };
    std::map<OverlayKey, CachedLines> overlays_;
    std::unique_ptr<GpuLines> streamedLines_, streamedTriangles_;
    VertexArray emptyVertexArray_{NoCreate}; // exact shading's proxies have no attributes (made at first use)
    std::vector<DrawPlan> plans_;            // drawPlan's, the latest first
    // draw()'s scene at the viewport's size and its lights in view space, and viewportOver's scene, assigned
    // every frame into the same storage: an unchanged scene's frame allocates nothing.
    Scene sized_, sizedOver_;
    std::vector<Light> lightsView_;
    // lightMarkers' lines and what they were made from (the lights, the eye and the target).
    struct LightMarkers {
        std::vector<Light> lights;
        glm::dvec3 eye{0}, target{0};
        std::vector<LineVertex> lines;
        bool made = false;
    } lightMarkers_;
};

} // namespace shadelab::gl
