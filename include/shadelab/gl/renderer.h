// The one render function shared by the window, the headless CLI, the showcase and the tests: draws a
// Scene into whatever framebuffer is bound. Programs and meshes are built on first use and cached.
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
#include "shadelab/gl/screen_pass.h"
#include "shadelab/gl/views.h"
#include "shadelab/scene/scene.h"

namespace shadelab::gl {

class Renderer {
public:
    Renderer();
    // Draws `scene` into the bound framebuffer over a viewport of width × height (which may differ from
    // the scene's image size, e.g. a resized window; the aspect comes from the viewport). A 0×0 viewport
    // draws nothing.
    // `x` moves the viewport right (the demo's picture beside its panel); the clear covers the whole target.
    // With scene.overlay, the objects' edges (and normals) are drawn over them, depth-tested.
    // scene.view other than "scene" draws that view (gl/views.h) from renders of the scene's parts.
    void render(const Scene& scene, int width, int height, int x = 0);
    // The scene itself, whatever its view says (what the views draw their parts with).
    void renderScene(const Scene& scene, int width, int height, int x = 0);
    // What the last view measured (the error view's mean and max, the profile's row).
    const ViewFigures& viewFigures() const;
    // Exact shading writes each object's index + 1 as alpha instead of 1 (the error view's compare pass).
    void setExactObjectIds(bool enabled) { exactObjectIds_ = enabled; }
    // Exact shading quantizes the lighting as toon shading does (the error view's exact answer for toon).
    void setExactToon(bool enabled) { exactToon_ = enabled; }
    // The NDC view (gl/views.cpp): while set, renderScene draws the meshes (and their overlay) through the
    // camera's M_proj·M_cam into its NDC space and on through `observerClipFromNdc`, every fragment outside
    // the camera's clip volume discarded; the camera's standard-depth matrices are used whatever its depth
    // mode, so NDC is the cube [−1, 1]³. Exact shading has no mesh to transform (the scene check refuses it).
    void setNdcObserver(std::optional<glm::dmat4> observerClipFromNdc) { ndcObserver_ = observerClipFromNdc; }

    // A CPU-made image (a label) blended over what render() drew into the viewport (x, 0, width, height),
    // its top left corner at (left, top) pixels from the viewport's top left.
    void drawImageOver(const Image& image, int left, int top, int width, int height, int x = 0);
    // The same for an image kept as a texture (gl/screen_pass.h), uploaded only when it changes.
    void drawSpriteOver(const Sprite& sprite, int left, int top, int width, int height, int x = 0);
    // Lines given in view space drawn over what render() drew into the same viewport, never hidden (the
    // demo's probe vectors).
    void drawLinesOver(const Scene& scene, std::span<const LineVertex> linesView, int width, int height,
                       int x = 0);
    // World-space triangles and lines (GL_LINES pairs), depth-tested against what scene's render left in
    // the depth buffer (the outside view: lines behind an object are hidden): the triangles first, blended
    // with `faceAlpha` and without writing depth, then the lines opaque over them.
    void drawWorld(const Scene& scene, std::span<const LineVertex> linesWorld,
                   std::span<const LineVertex> trianglesWorld, float faceAlpha, int width, int height,
                   int x = 0);

    // How far programs are specialized (gl/program.h): to each object's values (the default, as `render`
    // draws), to the scene's lights (the window: a colour change recompiles nothing), or not at all (the
    // uber program each is measured and cross-checked against).
    void setSpecialization(Specialization specialization);
    Specialization specialization() const { return specialization_; }
    // Flat shading from duplicated vertices with face data (the default) or from shared vertices with a
    // geometry shader; the same picture, measured against each other by `shadelab bench`.
    void setFlatGeometryShader(bool enabled) { flatGeometryShader_ = enabled; }
    // Programs compiled so far: switching back to a variant already built never recompiles.
    int programsBuilt() const { return programsBuilt_; }

private:
    const GpuMesh& mesh(int level, VertexNormals normals, MeshLayout layout);
    const SurfaceProgram& program(const ProgramVariant& variant);
    struct LineProgram {
        Program program;
        int clipFromSpace = -1; // uClipFromSpace, looked up once
        int translucency = -1;  // uTranslucency
    };
    const LineProgram& lineProgram();
    void drawOverlay(const Scene& sized, const SceneView& view);
    // What each object of a scene is drawn with, resolved once for the scene and kept while neither it nor
    // a setting changes: a frame then builds no variant's #define text and finds no program or mesh in a
    // map (programs_ and meshes_ never drop an entry, so the pointers stay valid).
    struct DrawPlan {
        Scene scene;                                 // the scene as renderScene draws it (atSize, the term)
        ProgramVariant variant;                      // the frame's variant, before an object's values
        Specialization specialization{};             // specialization_ when it was made
        std::vector<const SurfaceProgram*> programs; // one per object
        std::vector<const GpuMesh*> meshes;          // one per object (none in exact shading)
    };
    const DrawPlan& drawPlan(const Scene& sized, const ProgramVariant& variant);
    // Binds, for a frame, the program that draws each object (renderer.cpp).
    class ObjectBinder;
    void drawMeshes(const Scene& sized, const SceneView& view, const ProgramVariant& variant,
                    const DrawPlan& plan, ObjectBinder& bind);
    void drawExact(const Scene& sized, const SceneView& view, ObjectBinder& bind, int x);

    Specialization specialization_ = Specialization::Values;
    bool flatGeometryShader_ = false;
    int programsBuilt_ = 0;
    std::map<ProgramVariant, std::unique_ptr<SurfaceProgram>> programs_;
    std::map<std::tuple<int, VertexNormals, MeshLayout>, std::unique_ptr<GpuMesh>> meshes_;
    std::unique_ptr<LineProgram> lineProgram_;
    // By level, normals, overlay and, for the normals, the object's scale and the normal-matrix rule.
    using OverlayKey = std::tuple<int, VertexNormals, Overlay, std::array<double, 3>, NormalMatrixRule>;
    std::map<OverlayKey, std::unique_ptr<GpuLines>> overlays_;
    std::unique_ptr<GpuLines> streamedLines_, streamedTriangles_;
    std::unique_ptr<ImagePass> imagePass_;   // drawSpriteOver's, made at its first use
    Sprite imageOver_;                       // drawImageOver's image, uploaded at every call
    VertexArray emptyVertexArray_{NoCreate}; // exact shading's proxies have no attributes (made at first use)
    bool exactObjectIds_ = false, exactToon_ = false;
    std::optional<glm::dmat4> ndcObserver_;
    std::unique_ptr<Views> views_;
    std::vector<DrawPlan> plans_; // drawPlan's, the latest first
    // renderScene's scene at the viewport's size and its lights in view space, assigned every frame into
    // the same storage: an unchanged scene's frame allocates nothing.
    Scene sized_;
    std::vector<Light> lightsView_;
};

} // namespace shadelab::gl
