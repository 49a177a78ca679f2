// The one render function shared by the window, the headless CLI, the showcase and the tests: draws a
// Scene into whatever framebuffer is bound. A front over two private parts (src/gl/): the scene draw,
// which takes the scene, the viewport and its options as arguments and caches the programs and meshes it
// builds, and the teaching views, compositions of scene draws (DESIGN §4's views). Nothing either draws
// calls back up.
#pragma once

#include <memory>
#include <span>

#include "shadelab/diagram/overlay.h"
#include "shadelab/gl/program_variant.h"
#include "shadelab/gl/screen_pass.h"
#include "shadelab/gl/view_figures.h"
#include "shadelab/image/image.h"
#include "shadelab/scene/scene.h"

namespace shadelab::gl {

class SceneDraw;
class Views;

class Renderer {
public:
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Draws `scene` into the bound framebuffer over a viewport of width × height (which may differ from
    // the scene's image size, e.g. a resized window; the aspect comes from the viewport). A 0×0 viewport
    // draws nothing.
    // `x` moves the viewport right (the demo's picture beside its panel); the clear covers the whole target.
    // With scene.overlay, the objects' edges (and normals) are drawn over them, depth-tested.
    // scene.view other than "scene" draws that view from draws of the scene's parts; those that measure
    // unrounded values throw RuntimeError where the context lacks float colour targets (DESIGN §7).
    void render(const Scene& scene, int width, int height, int x = 0);
    // What the last view measured (the error view's mean and max, the profile's row, the labels' boxes).
    const ViewFigures& viewFigures() const;

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

    // How far programs are specialized (gl/program_variant.h): to each object's values (the default, as
    // `render` draws), to the scene's lights (the window: a colour change recompiles nothing), or not at
    // all (the uber program each is measured and cross-checked against).
    void setSpecialization(Specialization specialization) { specialization_ = specialization; }
    Specialization specialization() const { return specialization_; }
    // Flat shading from duplicated vertices with face data (the default) or from shared vertices with a
    // geometry shader; the same picture, measured against each other by `shadelab bench`.
    void setFlatGeometryShader(bool enabled) { flatGeometryShader_ = enabled; }
    // Programs compiled so far: switching back to a variant already built never recompiles.
    int programsBuilt() const;

private:
    Specialization specialization_ = Specialization::Values;
    bool flatGeometryShader_ = false;
    std::unique_ptr<SceneDraw> sceneDraw_;
    std::unique_ptr<Views> views_;         // made at the first view drawn (it builds the views' passes)
    std::unique_ptr<ImagePass> imagePass_; // drawSpriteOver's, made at its first use
    Sprite imageOver_;                     // drawImageOver's image, uploaded at every call
};

} // namespace shadelab::gl
