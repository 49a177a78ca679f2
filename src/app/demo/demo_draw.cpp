#include "app/demo/demo_draw.h"

#include <algorithm>
#include <cmath>

#include <vector>

#include "shadelab/diagram/outside_view.h"
#include "shadelab/diagram/overlay.h"

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
    const Scene& scene = state.drawn();
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
    state.setViewReport(report_);
    drawProbeVectors(renderer, scene, state.probe(), width, height);
    // Presentation mode without a lesson: the label over the bottom left, drawn here, so that the window
    // and the page draw it the same way (a lesson's band is drawn by draw(), under the picture).
    if (!state.presenting() || state.lesson()) return;
    const PresentationFacts facts = presentationFacts(scene);
    const gl::Sprite& label = label_.update(std::tuple{facts, width, height}, [&] {
        PresentationLabelImage made = presentationLabelImage(presentationLabel(facts), width, height);
        labelMargin_ = made.margin;
        return std::move(made.image);
    });
    renderer.drawSpriteOver(label, labelMargin_, height - labelMargin_ - label.height(), width, height);
}

// The probe's vectors, 0.6 of the object's largest semi-axis long (visible, and inside the picture). The
// camera's picture draws them in its view space; the outside view in world space as its observer sees them,
// 1.5 semi-axes long, hidden where an object is in front. Not in the NDC view: M_proj does not keep angles or
// lengths, so n, l, v and r carried into NDC would no longer be the unit vectors of the lighting (and the
// lecture draws them at the surface, in world or camera space).
void drawProbeVectors(gl::Renderer& renderer, const Scene& scene, const std::optional<ProbeReport>& probe,
                      int width, int height) {
    if (!probe || scene.view.kind == ViewKind::Ndc) return;
    const bool outside = scene.view.kind == ViewKind::Outside;
    // Behind the object the camera's picture cannot show them: the probe's table says so instead.
    if (!outside && probeFacesAway(*probe)) return;
    const SceneObject& object = scene.objects[probe->point.object];
    // The outside view's observer stands back to show the whole view volume: there they are longer.
    const double length =
        (outside ? 1.5 : 0.6) * object.radius *
        std::max({std::abs(object.scale.x), std::abs(object.scale.y), std::abs(object.scale.z)});
    std::vector<LineVertex> lines = probeLines(*probe, length);
    if (!outside) {
        renderer.drawLinesOver(scene, lines, width, height);
        return;
    }
    const glm::dmat4 worldFromView = glm::inverse(sceneView(scene).viewFromWorld);
    for (LineVertex& vertex : lines)
        vertex.position = glm::vec3(worldFromView * glm::dvec4(glm::dvec3(vertex.position), 1));
    renderer.drawWorld(observerScene(scene), lines, {}, 1.0f, width, height);
}

void FramedPicture::draw(gl::Renderer& renderer, DemoState& state, const PictureRect& picture,
                         int framebufferWidth, int framebufferHeight) {
    gl::clearWindow(framebufferWidth, framebufferHeight, kBarColour);
    shown_ = {};
    if (picture.width <= 0 || picture.height <= 0) return;
    try {
        // Presenting a lesson, the step's band takes the bottom of the picture's place and the picture is
        // drawn above it (pictureAboveBand), as `shadelab slides` composes the step's slide at this size.
        const Lesson* lesson = state.presenting() ? state.lesson() : nullptr;
        const gl::Sprite* band = nullptr;
        shown_ = picture;
        if (lesson) {
            const LessonStep& step = lesson->steps[state.step()];
            band = &band_.update(
                BandKey{state.sharedLesson(), state.step(), picture.width, picture.height},
                [&] { return lessonBandImage(step.title, step.caption, picture.width, picture.height); });
            const PictureRect above = pictureAboveBand(state.sceneWidth(), state.sceneHeight(), picture.width,
                                                       picture.height, band->height());
            shown_ = {picture.x + above.x, picture.y + above.y, above.width, above.height};
        }
        if (shown_.width > 0 && shown_.height > 0) {
            state.setViewport(shown_.width, shown_.height);
            target_.fit(shown_.width, shown_.height, gl::ColorFormat::Rgba8,
                        gl::depthFormatFor(state.drawn().depth));
            target_.bind();
            drawPicture(renderer, state, shown_.width, shown_.height);
            // GL counts rows up from the bottom; the picture's place is measured from the top.
            target_.blitToWindow(shown_.x, framebufferHeight - shown_.y - shown_.height);
        }
        if (band) { // over the bars, in a viewport whose top is the picture's place's
            gl::bindDefaultFramebuffer();
            renderer.drawSpriteOver(*band, 0, picture.height - band->height(), picture.width,
                                    framebufferHeight - picture.y, picture.x);
        }
    } catch (...) {
        target_ = gl::RenderTarget();
        gl::bindDefaultFramebuffer();
        throw;
    }
}

PictureRect pictureAboveBand(int sceneWidth, int sceneHeight, int width, int height, int bandHeight) {
    return fitPicture(sceneWidth, sceneHeight, width, height - bandHeight);
}

} // namespace shadelab::app
