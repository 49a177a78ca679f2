// The outside and NDC views (DESIGN §2's camera frame, view volume and normalization, drawn from an
// observer's camera): the scene rendered for the observer, the drawing's faces, labels and lines over it.
#include <algorithm>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "gl/views_internal.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/outside_view.h"

namespace shadelab::gl {

using detail::labelImage;
using detail::textScale;

void Views::drawOutside(const Scene& scene, int width, int height, int x) {
    figures_ = ViewFigures{};
    const Scene sized = atSize(scene, width, height);
    const Scene observer = observerScene(sized);
    renderer_.renderScene(observer, width, height, x);
    // The drawing is in world space: made again only for another scene, not as the observer orbits.
    Labels& l = *labels_;
    if (!l.drawing || !l.drawnScene || !(*l.drawnScene == sized)) {
        l.observed.clear();
        l.drawing = outsideDrawing(sized);
        l.drawnScene = sized;
    }
    drawObserved(*l.drawing, observer,
                 leavesOutTheMinusOne(scene) ? "OUTSIDE VIEW, UNNEGATED MATRIX" : "OUTSIDE VIEW", width,
                 height, x);
}

void Views::drawObserved(const OutsideDrawing& drawing, const Scene& observer, std::string_view title,
                         int width, int height, int x) {
    renderer_.drawWorld(observer, {}, drawing.faces, kFaceAlpha, width, height, x);
    // The labels, then the lines over them, so that no label hides a corner of the view volume.
    drawLabels(drawing.labels, observer, width, height, x);
    const int scale = textScale(width, height);
    // The title alone: how to move the observer is said in the window's title and status line, which a
    // pointer reaches; the picture is also a PNG or a slide, which none does.
    const Sprite& titleLabel = labels_->title.update(std::pair{title, scale},
                                                     [&] { return labelImage({std::string(title)}, scale); });
    programs_->images.draw(titleLabel, scale * 4, scale * 4, x, width, height);
    renderer_.drawWorld(observer, drawing.lines, {}, kFaceAlpha, width, height, x);
    glEnable(GL_DEPTH_TEST);
}

void Views::drawLabels(const std::vector<OutsideLabel>& labels, const Scene& observer, int width, int height,
                       int x) {
    glDisable(GL_DEPTH_TEST);
    glViewport(x, 0, width, height);
    glBindVertexArray(programs_->images.emptyVertexArray().get());
    const int scale = textScale(width, height);
    const Scene sized = atSize(observer, width, height);
    const SceneView view = sceneView(sized);
    const glm::dmat4 clipFromWorld = view.clipFromView * view.viewFromWorld;
    if (labels_->observed.size() < labels.size()) labels_->observed.resize(labels.size());
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const OutsideLabel& label = labels[i];
        const glm::dvec4 clip = clipFromWorld * glm::dvec4(label.positionWorld, 1);
        if (!(clip.w > 0)) continue;
        const double px = (clip.x / clip.w + 1) / 2 * width, py = (1 - clip.y / clip.w) / 2 * height;
        if (!(px >= 0 && px < width && py >= 0 && py < height)) continue;
        const Sprite& image = labels_->observed[i].update(std::pair{std::string_view(label.text), scale},
                                                          [&] { return labelImage({label.text}, scale); });
        const int left = label.leftOfPoint ? int(px) - 3 * scale - image.width() : int(px) + 3 * scale;
        programs_->images.draw(
            image, std::clamp(left, 0, std::max(0, width - image.width())),
            std::clamp(int(py) - image.height() / 2, 0, std::max(0, height - image.height())), x, width,
            height);
    }
}

void Views::drawNdc(const Scene& scene, int width, int height, int x) {
    figures_ = ViewFigures{};
    const Scene sized = atSize(scene, width, height);
    const Scene observer = ndcObserverScene(sized);
    const SceneView observerView = sceneView(observer);
    Scene objects = sized;
    objects.view = View{};
    renderer_.setNdcObserver(observerView.clipFromView * observerView.viewFromWorld);
    try {
        renderer_.renderScene(objects, width, height, x);
    } catch (...) {
        renderer_.setNdcObserver(std::nullopt);
        throw;
    }
    renderer_.setNdcObserver(std::nullopt);
    Labels& l = *labels_;
    if (!l.drawing || l.drawnScene) {
        l.observed.clear();
        l.drawing = ndcCubeDrawing();
        l.drawnScene.reset();
    }
    drawObserved(*l.drawing, observer,
                 scene.projection.type == ProjectionType::Orthographic
                     ? "NDC VIEW: AFTER M_ORTH M_CAM AND THE DIVIDE"
                     : "NDC VIEW: AFTER M_PROJ M_CAM AND THE DIVIDE",
                 width, height, x);
}

} // namespace shadelab::gl
