// What a teaching view (view.h; drawn by gl/renderer.h) measured and where it put its labels: for the
// panel, the title and the tests. The views themselves are private to the GL layer (src/gl/views.h).
#pragma once

#include <cstddef>
#include <vector>

namespace shadelab::gl {

// What the last view drawn measured.
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

} // namespace shadelab::gl
