// What the teaching views' two files share (views.cpp: the dispatch, error, split and profile views;
// views_observed.cpp: the outside and NDC views): the GL objects they draw with and the labels' layout.
#pragma once

#include <string>
#include <vector>

#include "shadelab/gl/render_target.h"
#include "shadelab/gl/screen_pass.h"
#include "shadelab/gl/views.h"
#include "shadelab/image/image.h"

namespace shadelab::gl {

struct Views::Targets {
    RenderTarget mode, exact, edges, error; // RGBA32F: unrounded colours, sampled and read back
    std::vector<RenderTarget> reduce;
};

namespace detail {
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

} // namespace shadelab::gl
