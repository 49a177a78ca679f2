// What the demo's window and page draw each frame: the drawn scene through the one Renderer (so a
// screenshot is `shadelab render` of its JSON) and, over it, the probe's vectors, which are not part of
// the scene.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <tuple>

#include "app/demo/demo_state.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/gl/screen_pass.h"
#include "shadelab/last_key.h"

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
    // (pixels from the framebuffer's top left), after setting the state's viewport to the picture's size;
    // sets state.viewReport from what the view measured. On a failure (a target the context cannot make)
    // the bars stay, the window's framebuffer is bound, no target is kept, and the error is thrown on.
    void draw(gl::Renderer& renderer, DemoState& state, const PictureRect& picture, int framebufferWidth,
              int framebufferHeight);

private:
    // The picture into the bound target (width × height): the scene, the probe's vectors and, in
    // presentation mode, the label or the lesson step's band.
    void drawPicture(gl::Renderer& renderer, DemoState& state, int width, int height);

    gl::RenderTarget target_; // follows the picture's size and the scene's depth mode
    // What the picture shows besides the scene, each made again only when what it says changes: a frame of
    // an unchanged picture builds no text and uploads no image.
    struct ReportFacts {
        View view;
        double mean = 0, max = 0;
        std::size_t pixels = 0, edges = 0;
        int row = -1;
        bool operator==(const ReportFacts&) const = default;
    };
    LastKey<ReportFacts> reported_;
    std::string report_; // viewReport's words for the last ReportFacts
    struct BandKey {
        std::shared_ptr<const Lesson> lesson; // held, so that its address names this lesson
        std::size_t step = 0;
        int width = 0, height = 0;
        bool operator==(const BandKey&) const = default;
    };
    gl::KeyedSprite<BandKey> band_;
    gl::KeyedSprite<std::tuple<PresentationFacts, int, int>> label_; // with the picture's size
    int labelMargin_ = 0;
};

// What a view measured, in words, for the title and the panel ("" for the plain scene).
std::string viewReport(const Scene& scene, const gl::ViewFigures& figures);

} // namespace shadelab::app
