// What the demo's window and page draw each frame: the drawn scene through the one Renderer (so a
// screenshot is `shadelab render` of its JSON) and, over it, the probe's vectors, which are not part of
// the scene.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
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
    // (pixels from the framebuffer's top left) — presenting a lesson, into the part of it above the step's
    // band (pictureAboveBand), the band across its bottom over the bars — after setting the state's
    // viewport to the size the picture is drawn at; sets state.viewReport from what the view measured. On a
    // failure (a target the context cannot make) the bars stay, the window's framebuffer is bound, no target
    // is kept, and the error is thrown on.
    void draw(gl::Renderer& renderer, DemoState& state, const PictureRect& picture, int framebufferWidth,
              int framebufferHeight);

    // Where the last draw put the picture (framebuffer pixels from the top left): `picture`, or presenting a
    // lesson the part above the step's band; what a click or the pointer is measured in. Empty before the
    // first draw.
    const PictureRect& shown() const { return shown_; }

private:
    // The picture into the bound target (width × height): the scene, the probe's vectors and, in
    // presentation mode without a lesson, the label.
    void drawPicture(gl::Renderer& renderer, DemoState& state, int width, int height);

    gl::RenderTarget target_; // follows the picture's size and the scene's depth mode
    PictureRect shown_;
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

// The probe's vectors (overlay.h's probeLines) over the picture of `drawn` just drawn into the bound target
// (width × height): in the camera's picture over everything, in the outside view in world space as its
// observer sees them (an object in front hides them); nothing in the NDC view or without a probe.
void drawProbeVectors(gl::Renderer& renderer, const Scene& drawn, const std::optional<ProbeReport>& probe,
                      int width, int height);

// Where a presented lesson step's picture goes in a frame of width × height whose bottom `bandHeight` rows
// hold the step's band (lessonBandImage): the largest rectangle of the scene's aspect above the band,
// centred, bars beside it (fitPicture). The window, the page and `shadelab slides` place it so.
PictureRect pictureAboveBand(int sceneWidth, int sceneHeight, int width, int height, int bandHeight);

// What a view measured, in words, for the title and the panel ("" for the plain scene).
std::string viewReport(const Scene& scene, const gl::ViewFigures& figures);

} // namespace shadelab::app
