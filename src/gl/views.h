// The teaching views (view.h; the "view" of DESIGN §4), private to the GL layer (gl/renderer.h draws them):
// the error heatmap, the split view, the intensity profile and the outside and NDC views, each a
// composition of scene draws (gl/scene_draw.h), screen passes and label sprites into whatever framebuffer is
// bound, legends and plots included, so the window, the page and a headless render show the same picture.
// Each draw is given its options as arguments: nothing is switched on the scene draw and restored after, so
// a draw that throws leaves nothing to undo. The error view's figures are computed on the GPU (a compare
// pass and a reduction over float targets the views own).
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "shadelab/diagram/outside_view.h"
#include "shadelab/gl/handles.h"
#include "shadelab/gl/view_figures.h"
#include "shadelab/scene/scene.h"

#include "gl/scene_draw.h"

namespace shadelab::gl {

class Sprite;

class Views {
public:
    explicit Views(SceneDraw& sceneDraw);
    ~Views();
    Views(const Views&) = delete;
    Views& operator=(const Views&) = delete;

    // Draws scene.view over the viewport of the bound framebuffer, each of its scene draws with `options`
    // and what the view adds to them (exact shading's object ids, the NDC observer). Throws RuntimeError
    // where the context lacks float colour targets (error and profile views measure unrounded values;
    // DESIGN §7: refused, never silently replaced).
    void draw(const Scene& scene, const Viewport& viewport, const DrawOptions& options);
    const ViewFigures& figures() const { return figures_; }

private:
    struct Targets;
    struct Programs;
    struct Labels;
    // A split's side: a plain scene drawn, or a view composed like any other.
    void drawPart(const Scene& scene, const Viewport& viewport, const DrawOptions& options);
    void drawError(const Scene& scene, const Viewport& viewport, const DrawOptions& options,
                   unsigned destination);
    void measureError(int width, int height);
    void drawHeatmap(const Scene& scene, const Viewport& viewport, unsigned destination);
    void drawSplit(const Scene& scene, const Viewport& viewport, const DrawOptions& options);
    void drawProfile(const Scene& scene, const Viewport& viewport, const DrawOptions& options,
                     unsigned destination);
    void drawOutside(const Scene& scene, const Viewport& viewport, const DrawOptions& options);
    void drawNdc(const Scene& scene, const Viewport& viewport, const DrawOptions& options);
    // What the outside and NDC views draw over the observer's render of the objects: the translucent faces,
    // the labels and the title (`title` and the drag hint), then the lines over them.
    void drawObserved(const OutsideDrawing& drawing, const Scene& observer, std::string_view title,
                      const Viewport& viewport);
    // Each label beside the point it names, where the observer's camera puts that point in the picture: on
    // the side of the point that crosses the fewest of the drawing's lines and no other label.
    void drawLabels(const OutsideDrawing& drawing, const Scene& observer, const Viewport& viewport);
    // A label's sprite at (left, top) of the viewport (x, 0, width, height), recorded in figures_.labels.
    void drawLabel(const Sprite& sprite, int left, int top, int x, int width, int height);
    // figures_ emptied, the storage of its labels and rows kept: an unchanged view's frame allocates nothing.
    void resetFigures();
    // The current mode and exact shading of the scene into the two float targets, at the viewport's size.
    void drawModeAndExact(const Scene& scene, int width, int height, const DrawOptions& options);

    SceneDraw& sceneDraw_;
    std::unique_ptr<Targets> targets_;
    std::unique_ptr<Programs> programs_;
    std::unique_ptr<Labels> labels_;
    ViewFigures figures_;
};

// The scene one side of a split view draws: the scene with the side's shading, lighting and level.
Scene splitSideScene(const Scene& scene, const SplitSide& side);
void assignSplitSide(Scene& out, const Scene& scene, const SplitSide& side); // into out's storage
// The profile's row, from the top: view.at of the height, or the row through the first object's centre
// (the middle row without objects or with the centre outside the picture).
// `sized` is storage for the scene at that height (kept by a caller that draws every frame).
int profileRow(const Scene& scene, int height, Scene& sized);
inline int profileRow(const Scene& scene, int height) {
    Scene sized;
    return profileRow(scene, height, sized);
}

} // namespace shadelab::gl
