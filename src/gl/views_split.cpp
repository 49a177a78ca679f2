// The split view (src/gl/views.h): two draws of the scene side by side or cut at a divider, each side its
// own shading, lighting, level or view, a label beside the divider on each side.
#include <algorithm>
#include <cmath>
#include <string>

#include <glad/gl.h>

#include "shadelab/exact/reference.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/auto_level.h"

#include "gl/views.h"
#include "gl/views_internal.h"

namespace shadelab::gl {

using detail::labelImage;
using detail::textScale;

void assignSplitSide(Scene& out, const Scene& scene, const SplitSide& side) {
    out = scene;
    out.view = View{};
    applySplitSideValues(out, side);
    if (side.view) {
        out.view.kind = *side.view;
        out.view.observer = scene.view.observer;
    }
    // The exact side is the truth, as the error view's exact: beside a picture with normals by M it shows
    // what the right matrix draws.
    if (side.shading == ShadingMode::Exact) setTrueNormals(out);
}

Scene splitSideScene(const Scene& scene, const SplitSide& side) {
    Scene out;
    assignSplitSide(out, scene, side);
    return out;
}

namespace {

// What a split side's label says, for the side's own scene (splitSideScene).
detail::SideFacts sideFacts(const Scene& sideScene, const SplitSide& side, int scale) {
    const bool levelled = sideScene.shading != ShadingMode::Exact && !sideScene.objects.empty();
    return {side, sideScene.shading, sideScene.lighting,
            levelled ? subdivisionLevel(sideScene, sideScene.objects[0]) : -1, scale};
}

std::string sideWords(const detail::SideFacts& facts) {
    if (facts.side.view) return upperAscii(toString(facts.side));
    std::string label = upperAscii(toString(facts.shading));
    if (facts.level >= 0) label += " L" + std::to_string(facts.level);
    if (facts.side.lighting || (!facts.side.shading && !facts.side.level))
        label += " " + upperAscii(toString(facts.lighting));
    // The side's settings as written: "PHONG L5 {SHININESS=8}".
    const std::string written = toString(facts.side);
    if (const std::size_t settings = written.find('{'); settings != std::string::npos)
        label += " " + upperAscii(written.substr(settings));
    return label;
}

// A side laid out side by side keeps the whole picture's width of the world in half the width: its view
// volume `factor` (the full width over the half's) times as tall, about the same centre, so that pixels
// stay square and no object the full picture shows is cut at the half's edge. The observer's views frame
// themselves.
void widenedForHalf(Scene& side, double factor) {
    if (observed(side.view.kind)) return;
    Projection& p = side.projection;
    if (p.type == ProjectionType::Perspective) {
        const double halfAngle = std::atan(std::tan(glm::radians(p.fovyDeg) / 2) * factor);
        p.fovyDeg = glm::degrees(2 * halfAngle);
    } else {
        const double centre = (p.top + p.bottom) / 2, half = (p.top - p.bottom) / 2 * factor;
        p.bottom = centre - half;
        p.top = centre + half;
    }
}

} // namespace

void Views::drawSplit(const Scene& scene, const Viewport& viewport, const DrawOptions& options) {
    const int width = viewport.width, height = viewport.height, x = viewport.x;
    resetFigures();
    // Side by side, each side is a whole picture of half the width (its own aspect); cut at the divider,
    // each is the part of a full-width picture on its side.
    const bool sideBySide = scene.view.layout == SplitLayout::SideBySide;
    const int divider =
        sideBySide ? width / 2 : std::clamp(int(std::lround(scene.view.at.value_or(0.5) * width)), 0, width);
    const int scale = textScale(width, height);
    // Each side clears and draws only its own pixels: the left side is a plain render of A there.
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, 0, divider, height);
    Scene& left = targets_->leftScene;
    assignSplitSide(left, scene, scene.view.left);
    if (sideBySide) widenedForHalf(left, double(width) / std::max(1, divider));
    drawPart(left, {x, sideBySide ? divider : width, height}, options); // a side may be a view
    glEnable(GL_SCISSOR_TEST);
    glScissor(x + divider, 0, width - divider, height);
    Scene& right = targets_->rightScene;
    assignSplitSide(right, scene, scene.view.right);
    if (sideBySide) {
        widenedForHalf(right, double(width) / std::max(1, width - divider));
        drawPart(right, {x + divider, width - divider, height}, options);
    } else
        drawPart(right, viewport, options);
    // The divider: two pixels of white straddling it.
    glEnable(GL_SCISSOR_TEST);
    glScissor(x + divider - 1, 0, 2, height);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
    glViewport(x, 0, width, height);
    glBindVertexArray(programs_->images.emptyVertexArray().get());
    const auto sprite = [&](KeyedSprite<detail::SideFacts>& label, const Scene& side,
                            const SplitSide& split) -> const Sprite& {
        const detail::SideFacts facts = sideFacts(side, split, scale);
        return label.update(facts, [&] { return labelImage({sideWords(facts)}, scale); });
    };
    const Sprite& leftLabel = sprite(labels_->left, left, scene.view.left);
    const Sprite& rightLabel = sprite(labels_->right, right, scene.view.right);
    // Each label beside the divider on its own side; a divider near an edge pushes one over the other,
    // and then the right side's goes under the left's.
    resetFigures();
    figures_.textScale = scale;
    const ViewFigures::LabelBox leftBox{std::max(0, divider - leftLabel.width() - 4 * scale), 4 * scale,
                                        leftLabel.width(), leftLabel.height()};
    ViewFigures::LabelBox rightBox{std::min(divider + 4 * scale, std::max(0, width - rightLabel.width())),
                                   4 * scale, rightLabel.width(), rightLabel.height()};
    if (rightBox.overlaps(leftBox)) rightBox.top = leftBox.top + leftBox.height + scale;
    drawLabel(leftLabel, leftBox.left, leftBox.top, x, width, height);
    drawLabel(rightLabel, rightBox.left, rightBox.top, x, width, height);
    glEnable(GL_DEPTH_TEST);
}

} // namespace shadelab::gl
