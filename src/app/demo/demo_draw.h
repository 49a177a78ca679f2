// What the demo's window and page draw each frame: the drawn scene through the one Renderer (so a
// screenshot is `shadelab render` of its JSON) and, over it, the probe's vectors, which are not part of
// the scene.
#pragma once

#include "app/demo/demo_state.h"
#include "shadelab/gl/renderer.h"

namespace shadelab::app {

// Into the bound framebuffer, over a viewport of width × height moved `x` to the right; sets
// state.viewReport from what the view measured.
void drawDemo(gl::Renderer& renderer, DemoState& state, int width, int height, int x = 0);
// What a view measured, in words, for the title and the panel ("" for the plain scene).
std::string viewReport(const Scene& scene, const gl::ViewFigures& figures);

} // namespace shadelab::app
