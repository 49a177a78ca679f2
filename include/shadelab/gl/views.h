// The teaching views (view.h; the "view" of DESIGN §4): the error heatmap, the split view and the intensity
// profile, each drawn by the one Renderer into whatever framebuffer is bound, legends and plots included, so
// the window, the page and a headless render show the same picture. The error view's figures are computed on
// the GPU (a compare pass and a reduction over float targets the views own).
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "shadelab/gl/handles.h"
#include "shadelab/scene/outside_view.h"
#include "shadelab/scene/scene.h"

namespace shadelab::gl {

class Renderer;
class Sprite;

// What the last view drawn measured, for the panel, the title and the tests.
struct ViewFigures {
    // Error view: over the interior as `shadelab report` counts it (both renders cover the 5×5 square around
    // the pixel, same object), in 1/255 units: the mean of |ΔR|, |ΔG|, |ΔB| and the largest of them.
    double interiorMean = 0, interiorMax = 0;
    std::size_t interiorPixels = 0;
    double scale = 0; // the heatmap's top, in 1/255
    // Profile view: the row (from the top) and its intensity, (R + G + B)/3 per pixel, for the current mode
    // and for exact; the columns where a mesh edge crosses the row.
    int row = -1;
    std::vector<float> modeRow, exactRow;
    std::vector<int> edgeColumns;
    // Every view: the labels' font scale (a line is textLineHeight(textScale) pixels, image.h) and where
    // each label (a box of text, the profile's plot) was drawn, in pixels from the viewport's top left.
    struct LabelBox {
        int left = 0, top = 0, width = 0, height = 0;
        bool overlaps(const LabelBox& o) const {
            return left < o.left + o.width && o.left < left + width && top < o.top + o.height &&
                   o.top < top + height;
        }
    };
    int textScale = 0;
    std::vector<LabelBox> labels;
};

class Views {
public:
    explicit Views(Renderer& renderer);
    ~Views();
    Views(const Views&) = delete;
    Views& operator=(const Views&) = delete;

    // Draws scene.view (not ViewKind::Scene) over the viewport (x, 0, width, height) of the bound
    // framebuffer. Throws RuntimeError where the context lacks float colour targets (error and profile
    // views measure unrounded values; DESIGN §7: refused, never silently replaced).
    void draw(const Scene& scene, int width, int height, int x);
    const ViewFigures& figures() const { return figures_; }

private:
    struct Targets;
    struct Programs;
    struct Labels;
    void drawError(const Scene& scene, int width, int height, int x, unsigned destination);
    void measureError(int width, int height);
    void drawHeatmap(const Scene& scene, int width, int height, int x, unsigned destination);
    void drawSplit(const Scene& scene, int width, int height, int x);
    void drawProfile(const Scene& scene, int width, int height, int x, unsigned destination);
    void drawOutside(const Scene& scene, int width, int height, int x);
    void drawNdc(const Scene& scene, int width, int height, int x);
    // What the outside and NDC views draw over the observer's render of the objects: the translucent faces,
    // the labels and the title (`title` and the drag hint), then the lines over them.
    void drawObserved(const OutsideDrawing& drawing, const Scene& observer, std::string_view title, int width,
                      int height, int x);
    // Each label beside the point it names, where the observer's camera puts that point in the picture: on
    // the side of the point that crosses the fewest of the drawing's lines and no other label.
    void drawLabels(const OutsideDrawing& drawing, const Scene& observer, int width, int height, int x);
    // A label's sprite at (left, top) of the viewport (x, 0, width, height), recorded in figures_.labels.
    void drawLabel(const Sprite& sprite, int left, int top, int x, int width, int height);
    // figures_ emptied, its labels' storage kept: an unchanged view's frame allocates nothing.
    void resetFigures();
    void renderModeAndExact(const Scene& scene, int width, int height);

    Renderer& renderer_;
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
int profileRow(const Scene& scene, int height);

} // namespace shadelab::gl
