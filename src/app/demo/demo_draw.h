// What the demo's window and page draw each frame: the drawn scene through the one Renderer (so a
// screenshot is `shadelab render` of its JSON) and, over it, the probe's vectors, which are not part of
// the scene.
#pragma once

#include <memory>

#include "app/demo/demo_state.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/gl/renderer.h"

namespace shadelab::app {

// The bars beside a picture whose aspect differs from its area's: a grey darker than the panel's.
inline constexpr glm::vec3 kBarColour{0.06f, 0.06f, 0.07f};

// The picture as the window and the page show it: the area (the window right of its panel, the page's
// canvas) keeps the scene's framing. The picture is drawn offscreen at its own size exactly as `render`
// draws (the same target and depth format) and copied pixel for pixel into its place (fitPicture), the
// rest of the framebuffer cleared to kBarColour. The target is kept from frame to frame.
class FramedPicture {
public:
    // Clears the framebuffer (width × height) to the bars and draws the state's picture into `picture`
    // (pixels from the framebuffer's top left), after setting the state's viewport to the picture's size.
    // On a failure (a target the context cannot make) the bars stay, the window's framebuffer is bound,
    // no target is kept, and the error is thrown on.
    void draw(gl::Renderer& renderer, DemoState& state, const PictureRect& picture, int framebufferWidth,
              int framebufferHeight);

private:
    gl::RenderTarget target_; // follows the picture's size and the scene's depth mode
};

// Into the bound framebuffer, over a viewport of width × height moved `x` to the right; sets
// state.viewReport from what the view measured.
void drawDemo(gl::Renderer& renderer, DemoState& state, int width, int height, int x = 0);
// What a view measured, in words, for the title and the panel ("" for the plain scene).
std::string viewReport(const Scene& scene, const gl::ViewFigures& figures);

} // namespace shadelab::app
