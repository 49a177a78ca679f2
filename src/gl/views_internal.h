// What the teaching views' files share (views.cpp: the dispatch and the error view; views_split.cpp: the
// split view; views_profile.cpp: the profile; views_observed.cpp: the outside and NDC views): the GL
// objects they draw with, the scenes they draw kept from frame to frame, the labels' layout and the
// sprites that keep each label until what it shows changes.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "shadelab/diagram/outside_view.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/gl/screen_pass.h"
#include "shadelab/image/image.h"

#include "gl/views.h"

namespace shadelab::gl {

struct Views::Targets {
    RenderTarget mode, exact, edges, error; // RGBA32F: unrounded colours, sampled and read back
    std::vector<RenderTarget> reduce;
    // The scenes drawn into them, the split view's sides and the profile's picture: assigned every frame
    // into the same storage, so that an unchanged view's frame allocates nothing.
    Scene modeScene, exactScene, leftScene, rightScene, profileScene, edgesScene, rowScene;
    std::vector<float> rows[3]; // the profile's row of mode, exact and edges, RGBA floats
};

namespace detail {
inline constexpr glm::u8vec4 kLabelText{240, 240, 240, 255};
inline constexpr glm::u8vec4 kLabelBox{0, 0, 0, 170}; // translucent: the picture shows through

// The error view's passes (shaders/error, reduce and heatmap.frag.glsl), their samplers' units set once.
struct ErrorPass : ScreenPass {
    ErrorPass() : ScreenPass("error.frag.glsl") {
        setSampler("uMode", 0);
        setSampler("uExact", 1);
    }
};
struct ReducePass : ScreenPass {
    ReducePass() : ScreenPass("reduce.frag.glsl") { setSampler("uInput", 0); }
};
struct HeatmapPass : ScreenPass {
    HeatmapPass() : ScreenPass("heatmap.frag.glsl") { setSampler("uError", 0); }
    int origin = location("uOrigin"), scale = location("uScale"), background = location("uBackground"),
        legend = location("uLegend");
};

// The labels' font scale for a viewport: 2 from 400 pixels on its shorter side, else 1.
int textScale(int width, int height);
// `lines` of text on a translucent box, as an image to draw over the picture.
Image labelImage(const std::vector<std::string>& lines, int scale);
} // namespace detail

struct Views::Programs {
    detail::ErrorPass error;
    detail::ReducePass reduce;
    detail::HeatmapPass heatmap;
    ImagePass images;
};

namespace detail {
// What the views' labels and plots show: the keys of their sprites (gl/screen_pass.h).
struct ErrorFigures {
    ShadingMode shading;
    int level; // -1: exact shading, no level
    double mean, max;
    int scale;
    bool operator==(const ErrorFigures&) const = default;
};
struct SideFacts { // one side of the split view
    SplitSide side;
    ShadingMode shading;
    LightingModel lighting;
    int level; // -1: exact shading, no level
    int scale;
    bool operator==(const SideFacts&) const = default;
};
struct LabelSegment { // a line of the outside or NDC view's drawing, in pixels from the top left
    glm::dvec2 a, b;
};
// The outside or NDC view's scene at the viewport's size, assigned every frame, and the observer's scene
// made from it (outside_view.h), kept while that scene stays the same.
struct ObservedScene {
    Scene sized, madeFor, observer;
    bool made = false;
};
struct ProfilePlot {
    int row, width, height, scale;
    ShadingMode shading;
    std::vector<float> modeRow, exactRow;
    std::vector<int> edgeColumns;
    bool operator==(const ProfilePlot&) const = default;
};
} // namespace detail

// The views' labels and plots as sprites, each keyed by the values it shows: a frame that shows the same
// figures, sides and titles as the last builds no text and uploads nothing.
struct Views::Labels {
    KeyedSprite<detail::ErrorFigures> errorFigures;
    KeyedSprite<glm::dvec2> legendTop; // (the heatmap's top in 1/255, text scale)
    KeyedSprite<int> legendBottom;     // "0", at a text scale
    KeyedSprite<detail::SideFacts> left, right;
    KeyedSprite<detail::ProfilePlot> profilePlot;
    detail::ProfilePlot profileShown{}; // the plot's key, assigned into this storage every frame
    KeyedSprite<int> profileMarker;     // its width
    // The outside and NDC views: their scenes and observers, the NDC view's objects and its camera's
    // standard-depth scene (kept storage, as Targets' scenes), the title (a literal), the drawing of the last
    // scene and its labels.
    detail::ObservedScene outside, ndc;
    Scene ndcObjects, ndcStandard;
    KeyedSprite<std::pair<std::string_view, int>> title;
    std::optional<Scene> drawnScene; // what `drawing` was made for (nullopt with a drawing: the NDC cube)
    std::optional<OutsideDrawing> drawing;
    // One per label of `drawing`, keyed by a view of its text: cleared whenever the drawing is made again.
    std::vector<KeyedSprite<std::pair<std::string_view, int>>> observed;
    std::vector<detail::LabelSegment> segments;     // the drawing's lines in the picture, placing its labels
    std::vector<ViewFigures::LabelBox> objectBoxes; // where the objects are in the picture, likewise
};

} // namespace shadelab::gl
