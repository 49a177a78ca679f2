// The outside and NDC views (DESIGN §2's camera frame, view volume and normalization, drawn from an
// observer's camera): the scene rendered for the observer, the drawing's faces, labels and lines over it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "shadelab/diagram/outside_view.h"
#include "shadelab/io/text.h"

#include "gl/views.h"
#include "gl/views_internal.h"

namespace shadelab::gl {

using detail::labelImage;
using detail::textScale;

namespace {

using LabelBox = ViewFigures::LabelBox;

using Segment = detail::LabelSegment;

// The drawing's lines as the observer's camera puts them in the picture (the parts in front of its eye).
void segmentsInPicture(const std::vector<LineVertex>& lines, const glm::dmat4& clipFromWorld, int width,
                       int height, std::vector<Segment>& segments) {
    segments.clear();
    const auto pixel = [&](const glm::dvec4& clip) {
        return glm::dvec2((clip.x / clip.w + 1) / 2 * width, (1 - clip.y / clip.w) / 2 * height);
    };
    constexpr double kNearW = 1e-6;
    for (std::size_t i = 0; i + 1 < lines.size(); i += 2) {
        glm::dvec4 a = clipFromWorld * glm::dvec4(glm::dvec3(lines[i].position), 1);
        glm::dvec4 b = clipFromWorld * glm::dvec4(glm::dvec3(lines[i + 1].position), 1);
        if (a.w <= kNearW && b.w <= kNearW) continue;
        if (a.w <= kNearW) a = b + (a - b) * ((b.w - kNearW) / (b.w - a.w));
        if (b.w <= kNearW) b = a + (b - a) * ((a.w - kNearW) / (a.w - b.w));
        segments.push_back({pixel(a), pixel(b)});
    }
}

// Whether the segment passes through the box (Liang–Barsky).
bool crosses(const Segment& s, const LabelBox& box) {
    double t0 = 0, t1 = 1;
    const glm::dvec2 d = s.b - s.a;
    const double p[4] = {-d.x, d.x, -d.y, d.y};
    const double q[4] = {s.a.x - box.left, box.left + box.width - s.a.x, s.a.y - box.top,
                         box.top + box.height - s.a.y};
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0) {
            if (q[k] < 0) return false;
            continue;
        }
        const double t = q[k] / p[k];
        if (p[k] < 0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1) return false;
    }
    return true;
}

// Where a label of w × h goes beside the point (px, py): of six places (above, beside and below the point,
// on its own side first, then on the other), inside the picture, the first that covers no other label,
// then no object, and crosses the fewest lines.
LabelBox placeLabel(double px, double py, int w, int h, bool leftOfPoint, int gap,
                    const std::vector<Segment>& segments, const std::vector<LabelBox>& taken,
                    const std::vector<LabelBox>& objects, int width, int height) {
    LabelBox best{};
    long bestCost = -1;
    for (const bool left : {leftOfPoint, !leftOfPoint})
        for (const int row : {-1, 0, 1}) { // above the point, centred on it, below it
            const int l = left ? int(px) - gap - w : int(px) + gap;
            const int t = row < 0 ? int(py) - gap - h : row == 0 ? int(py) - h / 2 : int(py) + gap;
            const LabelBox box{std::clamp(l, 0, std::max(0, width - w)),
                               std::clamp(t, 0, std::max(0, height - h)), w, h};
            long cost = 0;
            for (const LabelBox& other : taken) cost += box.overlaps(other) ? 1000 : 0;
            for (const LabelBox& object : objects) cost += box.overlaps(object) ? 20 : 0;
            for (const Segment& s : segments) cost += crosses(s, box) ? 1 : 0;
            if (bestCost < 0 || cost < bestCost) {
                best = box;
                bestCost = cost;
            }
        }
    return best;
}

// The picture's box around each object's image: the box around its bounding box's corners (centre ±
// radius·|scale| in world space) where `pixelOf` puts them (nullopt: behind the eye). Labels keep off them.
template <typename PixelOf>
void objectBoxes(const Scene& scene, const PixelOf& pixelOf, std::vector<LabelBox>& boxes) {
    boxes.clear();
    for (const SceneObject& object : scene.objects) {
        const glm::dvec3 half = object.radius * glm::abs(object.scale);
        glm::dvec2 low(std::numeric_limits<double>::max()), high(std::numeric_limits<double>::lowest());
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 sign(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
            if (const std::optional<glm::dvec2> p = pixelOf(object.center + half * sign)) {
                low = glm::min(low, *p);
                high = glm::max(high, *p);
            }
        }
        if (!(low.x <= high.x)) continue;
        const glm::dvec2 from = glm::clamp(low, -1e6, 1e6), to = glm::clamp(high, -1e6, 1e6);
        boxes.push_back({int(std::floor(from.x)), int(std::floor(from.y)), int(std::ceil(to.x - from.x)),
                         int(std::ceil(to.y - from.y))});
    }
}

// Pixels from the top left where clipFromSpace puts a point; nullopt behind the eye.
std::optional<glm::dvec2> pixelAt(const glm::dmat4& clipFromSpace, const glm::dvec3& point, int width,
                                  int height) {
    const glm::dvec4 clip = clipFromSpace * glm::dvec4(point, 1);
    if (!(clip.w > 1e-9)) return std::nullopt;
    return glm::dvec2((clip.x / clip.w + 1) / 2 * width, (1 - clip.y / clip.w) / 2 * height);
}

// The scene at the viewport's size, and `make`'s observer of it, both into `kept`'s storage: the observer is
// made again only for another scene (an unchanged view's frame allocates nothing).
template <typename Make>
const Scene& observerOf(detail::ObservedScene& kept, const Scene& scene, const Viewport& viewport,
                        Make make) {
    Scene& sized = kept.sized;
    sized = scene;
    sized.width = viewport.width;
    sized.height = viewport.height;
    if (!kept.made || !(kept.madeFor == sized)) {
        kept.made = false;
        kept.observer = make(sized); // at the size of `sized`, as outside_view.h's observers are
        kept.madeFor = sized;
        kept.made = true;
    }
    return kept.observer;
}

} // namespace

void Views::drawOutside(const Scene& scene, const Viewport& viewport, const DrawOptions& options) {
    const int width = viewport.width, height = viewport.height;
    resetFigures();
    Labels& l = *labels_;
    const Scene& observer = observerOf(l.outside, scene, viewport, observerScene);
    const Scene& sized = l.outside.sized;
    sceneDraw_.draw(observer, viewport, options);
    // The drawing is in world space: made again only for another scene, not as the observer orbits.
    if (!l.drawing || !l.drawnScene || !(*l.drawnScene == sized)) {
        l.observed.clear();
        l.drawing = outsideDrawing(sized);
        l.drawnScene = sized;
    }
    const SceneView observerView = sceneView(observer);
    const glm::dmat4 observerClipFromWorld = observerView.clipFromView * observerView.viewFromWorld;
    objectBoxes(
        sized, [&](const glm::dvec3& p) { return pixelAt(observerClipFromWorld, p, width, height); },
        l.objectBoxes);
    drawObserved(*l.drawing, observer,
                 leavesOutTheMinusOne(scene) ? "OUTSIDE VIEW, UNNEGATED MATRIX" : "OUTSIDE VIEW", viewport);
}

void Views::drawObserved(const OutsideDrawing& drawing, const Scene& observer, std::string_view title,
                         const Viewport& viewport) {
    const int width = viewport.width, height = viewport.height, x = viewport.x;
    sceneDraw_.drawWorld(observer, {}, drawing.faces, kFaceAlpha, viewport);
    glDisable(GL_DEPTH_TEST);
    glViewport(x, 0, width, height);
    glBindVertexArray(programs_->images.emptyVertexArray().get());
    const int scale = textScale(width, height);
    figures_.textScale = scale;
    // The title alone: how to move the observer is said in the window's title and status line, which a
    // pointer reaches; the picture is also a PNG or a slide, which none does.
    const Sprite& titleLabel = labels_->title.update(std::pair{title, scale},
                                                     [&] { return labelImage({std::string(title)}, scale); });
    drawLabel(titleLabel, scale * 4, scale * 4, x, width, height);
    // The labels, then the lines over them, so that no label hides a corner of the view volume.
    drawLabels(drawing, observer, viewport);
    sceneDraw_.drawWorld(observer, drawing.lines, {}, kFaceAlpha, viewport);
    glEnable(GL_DEPTH_TEST);
}

// `observer` is at the viewport's size (observerOf).
void Views::drawLabels(const OutsideDrawing& drawing, const Scene& observer, const Viewport& viewport) {
    const int width = viewport.width, height = viewport.height, x = viewport.x;
    glDisable(GL_DEPTH_TEST);
    glViewport(x, 0, width, height);
    glBindVertexArray(programs_->images.emptyVertexArray().get());
    const int scale = textScale(width, height);
    const SceneView view = sceneView(observer);
    const glm::dmat4 clipFromWorld = view.clipFromView * view.viewFromWorld;
    std::vector<Segment>& segments = labels_->segments;
    segmentsInPicture(drawing.lines, clipFromWorld, width, height, segments);
    const std::vector<OutsideLabel>& labels = drawing.labels;
    if (labels_->observed.size() < labels.size()) labels_->observed.resize(labels.size());
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const OutsideLabel& label = labels[i];
        const glm::dvec4 clip = clipFromWorld * glm::dvec4(label.positionWorld, 1);
        if (!(clip.w > 0)) continue;
        const double px = (clip.x / clip.w + 1) / 2 * width, py = (1 - clip.y / clip.w) / 2 * height;
        if (!(px >= 0 && px < width && py >= 0 && py < height)) continue;
        const Sprite& image = labels_->observed[i].update(std::pair{std::string_view(label.text), scale},
                                                          [&] { return labelImage({label.text}, scale); });
        const LabelBox box = placeLabel(px, py, image.width(), image.height(), label.leftOfPoint, 3 * scale,
                                        segments, figures_.labels, labels_->objectBoxes, width, height);
        drawLabel(image, box.left, box.top, x, width, height);
    }
}

void Views::drawNdc(const Scene& scene, const Viewport& viewport, const DrawOptions& options) {
    const int width = viewport.width, height = viewport.height;
    resetFigures();
    Labels& l = *labels_;
    const Scene& observer = observerOf(l.ndc, scene, viewport, ndcObserverScene);
    const Scene& sized = l.ndc.sized;
    const SceneView observerView = sceneView(observer);
    Scene& objects = l.ndcObjects;
    objects = sized;
    objects.view = View{};
    DrawOptions ndcOptions = options;
    ndcOptions.observerClipFromNdc = observerView.clipFromView * observerView.viewFromWorld;
    sceneDraw_.draw(objects, viewport, ndcOptions);
    if (!l.drawing || l.drawnScene) {
        l.observed.clear();
        l.drawing = ndcCubeDrawing();
        l.drawnScene.reset();
    }
    // Each object's corners through the camera's standard-depth matrices (as the scene draw draws the
    // objects here) into NDC, kept to the cube (the rest is clipped), then through the observer.
    Scene& standard = l.ndcStandard;
    standard = sized;
    standard.depth = DepthMode::Standard;
    const SceneView camera = sceneView(standard);
    const glm::dmat4 cameraClipFromWorld = camera.clipFromView * camera.viewFromWorld;
    const glm::dmat4 observerClipFromNdc = observerView.clipFromView * observerView.viewFromWorld;
    objectBoxes(
        sized,
        [&](const glm::dvec3& p) -> std::optional<glm::dvec2> {
            const glm::dvec4 clip = cameraClipFromWorld * glm::dvec4(p, 1);
            if (!(clip.w > 1e-9)) return std::nullopt;
            return pixelAt(observerClipFromNdc, glm::clamp(glm::dvec3(clip) / clip.w, -1.0, 1.0), width,
                           height);
        },
        l.objectBoxes);
    drawObserved(*l.drawing, observer,
                 scene.projection.type == ProjectionType::Orthographic
                     ? "NDC VIEW: AFTER M_ORTH M_CAM AND THE DIVIDE"
                     : "NDC VIEW: AFTER M_PROJ M_CAM AND THE DIVIDE",
                 viewport);
}

} // namespace shadelab::gl
