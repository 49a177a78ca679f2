#include "app/demo/demo_draw.h"

#include <algorithm>
#include <cmath>

#include "shadelab/geometry/overlay.h"

namespace shadelab::app {

std::string viewReport(const Scene& scene, const gl::ViewFigures& figures) {
    char text[160];
    switch (scene.view.kind) {
    case ViewKind::Scene:
        return "";
    case ViewKind::Error:
        std::snprintf(text, sizeof text, "error vs exact: interior mean %.3f/255, max %.2f/255 (%zu px)",
                      figures.interiorMean, figures.interiorMax, figures.interiorPixels);
        return text;
    case ViewKind::Split:
        return "split: " + toString(scene.view.left) + " | " + toString(scene.view.right);
    case ViewKind::Profile:
        return "profile: row " + std::to_string(figures.row) + ", " +
               std::to_string(figures.edgeColumns.size()) + " edge crossings";
    case ViewKind::Outside:
    case ViewKind::Ndc:
        std::snprintf(
            text, sizeof text,
            "%s: observer at azimuth %.0f deg, elevation %.0f deg, zoom %.2f (drag: orbit, wheel: zoom)",
            toString(scene.view).c_str(), scene.view.observer.azimuthDeg, scene.view.observer.elevationDeg,
            scene.view.observer.zoom);
        return text;
    }
    return "";
}

void FramedPicture::drawPicture(gl::Renderer& renderer, DemoState& state, int width, int height) {
    const Scene scene = state.drawn();
    renderer.render(scene, width, height);
    const gl::ViewFigures& figures = renderer.viewFigures();
    const ReportFacts reported{scene.view,
                               figures.interiorMean,
                               figures.interiorMax,
                               figures.interiorPixels,
                               figures.edgeColumns.size(),
                               figures.row};
    if (reported_.changed(reported)) report_ = viewReport(scene, figures);
    // Copied only when the state's differs: a new state (a lesson step) starts without it.
    if (state.viewReport != report_) state.viewReport = report_;
    const auto probe = state.probe();
    // Behind the object the probe's table says so instead; and the vectors are in the camera's view, which
    // the outside and NDC views do not draw.
    if (probe && !probeFacesAway(*probe) && !observed(scene.view.kind)) {
        // The vectors are as long as 0.6 of the object's largest semi-axis: visible, and inside the picture.
        const SceneObject& object = scene.objects[probe->point.object];
        const double length =
            0.6 * object.radius *
            std::max({std::abs(object.scale.x), std::abs(object.scale.y), std::abs(object.scale.z)});
        renderer.drawLinesOver(scene, probeLines(*probe, length), width, height);
    }
    // Presentation mode, on top of everything: in a lesson the step's band across the bottom — the picture
    // is then what `shadelab slides` makes of the step at this size — otherwise the label over the bottom
    // left. Drawn here, so the window and the page draw them the same way.
    if (!state.presenting) return;
    if (const Lesson* lesson = state.lesson()) {
        const LessonStep& step = lesson->steps[state.step()];
        const gl::Sprite& band =
            band_.update(BandKey{state.sharedLesson(), state.step(), width, height},
                         [&] { return lessonBandImage(step.title, step.caption, width, height); });
        renderer.drawSpriteOver(band, 0, height - band.height(), width, height);
        return;
    }
    const PresentationFacts facts = presentationFacts(scene);
    const gl::Sprite& label = label_.update(std::tuple{facts, width, height}, [&] {
        PresentationLabelImage made = presentationLabelImage(presentationLabel(facts), width, height);
        labelMargin_ = made.margin;
        return std::move(made.image);
    });
    renderer.drawSpriteOver(label, labelMargin_, height - labelMargin_ - label.height(), width, height);
}

void FramedPicture::draw(gl::Renderer& renderer, DemoState& state, const PictureRect& picture,
                         int framebufferWidth, int framebufferHeight) {
    gl::clearWindow(framebufferWidth, framebufferHeight, kBarColour);
    if (picture.width <= 0 || picture.height <= 0) return;
    try {
        state.setViewport(picture.width, picture.height);
        target_.fit(picture.width, picture.height, gl::ColorFormat::Rgba8,
                    gl::depthFormatFor(state.scene().depth)); // the depth drawn() keeps
        target_.bind();
        drawPicture(renderer, state, picture.width, picture.height);
        // GL counts rows up from the bottom; the picture's place is measured from the top.
        target_.blitToWindow(picture.x, framebufferHeight - picture.y - picture.height);
    } catch (...) {
        target_ = gl::RenderTarget();
        gl::bindDefaultFramebuffer();
        throw;
    }
}

} // namespace shadelab::app
