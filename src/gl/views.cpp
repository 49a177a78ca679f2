// The teaching views' dispatch (src/gl/views.h), what every view shares (the labels' scale and images,
// the figures) and the error view: DESIGN §6's interior error measured on the GPU and drawn as a heatmap.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include <glad/gl.h>

#include "shadelab/diagram/outside_view.h"
#include "shadelab/errors.h"
#include "shadelab/exact/reference.h"
#include "shadelab/gl/loader.h"
#include "shadelab/gl/program.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/gl/screen_pass.h"
#include "shadelab/image/image.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/auto_level.h"

#include "gl/views.h"
#include "gl/views_internal.h"

namespace shadelab::gl {
namespace {

using detail::labelImage;
using detail::textScale;

// 1, 2 or 5 times a power of ten, at least `value`: the heatmap's top (at least 0.5/255).
double niceCeiling(double value) {
    if (!(value > 0.5)) return 0.5;
    const double decade = std::pow(10.0, std::floor(std::log10(value)));
    for (double step : {1.0, 2.0, 5.0, 10.0})
        if (step * decade >= value * (1 - 1e-9)) return step * decade;
    return 10 * decade;
}

std::string formatError(double value) {
    char text[32];
    std::snprintf(text, sizeof text, value < 10 ? "%.2f" : "%.1f", value);
    return text;
}

std::string formatScale(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

} // namespace

namespace detail {
// Lines of 11 px (textLineHeight(1)), twice that from a 400-pixel picture on; from 600 pixels on (a
// lecture hall's picture: a 1080-line slide keeps at least 3/5 of its height above the lesson band) a
// line is about a 33rd of the shorter side and at least 33 px.
int textScale(int width, int height) {
    const int side = std::min(width, height);
    if (side < 600) return side >= 400 ? 2 : 1;
    return std::max(3, int(std::lround(side / 360.0)));
}

// `lines` of text on a translucent box, as an image to draw over the picture.
Image labelImage(const std::vector<std::string>& lines, int scale) {
    int width = 0;
    for (const std::string& line : lines) width = std::max(width, textWidth(line, scale));
    const int lineHeight = textLineHeight(scale), pad = 3 * scale;
    Image image(width + 2 * pad, int(lines.size()) * lineHeight + 2 * pad);
    fillRect(image, 0, 0, image.width, image.height, kLabelBox);
    for (std::size_t i = 0; i < lines.size(); ++i)
        drawText(image, pad, pad + int(i) * lineHeight, lines[i], scale, kLabelText);
    return image;
}

} // namespace detail

Views::Views(SceneDraw& sceneDraw)
    : sceneDraw_(sceneDraw), targets_(std::make_unique<Targets>()), programs_(std::make_unique<Programs>()),
      labels_(std::make_unique<Labels>()) {}

Views::~Views() = default;

void Views::resetFigures() {
    ViewFigures& f = figures_;
    f.interiorMean = f.interiorMax = f.scale = 0;
    f.interiorPixels = 0;
    f.row = -1;
    f.modeRow.clear();
    f.exactRow.clear();
    f.edgeColumns.clear();
    f.textScale = 0;
    f.labels.clear();
}

void Views::drawLabel(const Sprite& sprite, int left, int top, int x, int width, int height) {
    programs_->images.draw(sprite, left, top, x, width, height);
    figures_.labels.push_back({left, top, sprite.width(), sprite.height()});
}

void Views::drawPart(const Scene& scene, const Viewport& viewport, const DrawOptions& options) {
    if (scene.view.kind == ViewKind::Scene)
        sceneDraw_.draw(scene, viewport, options);
    else
        draw(scene, viewport, options);
}

void Views::draw(const Scene& scene, const Viewport& viewport, const DrawOptions& options) {
    if (viewport.width <= 0 || viewport.height <= 0) return;
    GLint destination = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &destination);
    switch (scene.view.kind) {
    case ViewKind::Scene:
        sceneDraw_.draw(scene, viewport, options);
        break;
    case ViewKind::Error:
        drawError(scene, viewport, options, unsigned(destination));
        break;
    case ViewKind::Split:
        drawSplit(scene, viewport, options);
        break;
    case ViewKind::Profile:
        drawProfile(scene, viewport, options, unsigned(destination));
        break;
    case ViewKind::Outside:
        drawOutside(scene, viewport, options);
        break;
    case ViewKind::Ndc:
        drawNdc(scene, viewport, options);
        break;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(destination));
    glEnable(GL_DEPTH_TEST); // as a scene draw leaves it
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(0);
    glUseProgram(0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    checkGlError("drawing a teaching view");
}

// The exact render's alpha holds each object's index + 1, so the compare pass knows which pixels one object
// covers.
void Views::drawModeAndExact(const Scene& scene, int width, int height, const DrawOptions& options) {
    if (!capabilities().floatColorTargets)
        throw RuntimeError("the " + toString(scene.view) +
                           " view measures unrounded colours in float (RGBA32F) "
                           "targets, which need EXT_color_buffer_float; this " +
                           std::string(displayName(capabilities().api)) + " context lacks it");
    const DepthFormat depth = depthFormatFor(scene.depth);
    targets_->mode.fit(width, height, ColorFormat::Rgba32F, depth);
    targets_->exact.fit(width, height, ColorFormat::Rgba32F, depth);
    Scene& mode = targets_->modeScene;
    mode = scene;
    mode.view = View{};
    mode.overlay = Overlay::None; // the lines are no part of the shading's error
    Scene& exact = targets_->exactScene;
    exact = mode;
    setTrueNormals(exact); // with normals by M, the error is what the wrong matrix costs
    exact.shading = ShadingMode::Exact;
    targets_->mode.bind();
    sceneDraw_.draw(mode, {0, width, height}, options);
    targets_->exact.bind();
    // Toon is measured against the exact sphere quantized the same way, as `shadelab report` does: its bands
    // are the mode's design, not its error.
    DrawOptions exactOptions = options;
    exactOptions.exactObjectIds = true;
    exactOptions.exactToon = scene.shading == ShadingMode::Toon;
    sceneDraw_.draw(exact, {0, width, height}, exactOptions);
}

// DESIGN §6's interior error, measured on the GPU (error.frag.glsl, then reduce.frag.glsl) and drawn as a
// heatmap with its legend and figures.
void Views::drawError(const Scene& scene, const Viewport& viewport, const DrawOptions& options,
                      unsigned destination) {
    drawModeAndExact(scene, viewport.width, viewport.height, options);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(programs_->images.emptyVertexArray().get());
    measureError(viewport.width, viewport.height);
    drawHeatmap(scene, viewport, destination);
}

// The mode's and exact's renders compared pixel by pixel into targets_->error, then reduced to one texel
// read back into figures_.
void Views::measureError(int width, int height) {
    Targets& t = *targets_;
    const Programs& p = *programs_;
    // Compare pass: the per-pixel error and the interior.
    t.error.fit(width, height, ColorFormat::Rgba32F, DepthFormat::None);
    t.error.bind();
    glViewport(0, 0, width, height);
    glUseProgram(p.error.program.get());
    bindTexture(0, t.mode.color());
    bindTexture(1, t.exact.color());
    p.error.draw(0, 0, width, height, width, height);

    // Reduction: 4×4 blocks per step down to one texel (sum of the mean error, interior pixels, largest).
    glUseProgram(p.reduce.program.get());
    std::size_t steps = 0;
    for (int w = width, h = height; w > 1 || h > 1; w = (w + 3) / 4, h = (h + 3) / 4) ++steps;
    if (t.reduce.size() < steps) t.reduce.resize(steps); // before taking pointers into it
    const RenderTarget* input = &t.error;
    for (std::size_t step = 0; step < steps; ++step) {
        RenderTarget& output = t.reduce[step];
        output.fit((input->width() + 3) / 4, (input->height() + 3) / 4, ColorFormat::Rgba32F,
                   DepthFormat::None);
        output.bind();
        glViewport(0, 0, output.width(), output.height());
        bindTexture(0, input->color());
        p.reduce.draw(0, 0, output.width(), output.height(), output.width(), output.height());
        input = &output;
    }
    float total[4] = {0, 0, 0, 0};
    input->bind();
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, total);
    resetFigures();
    figures_.interiorPixels = std::size_t(std::lround(total[1]));
    figures_.interiorMean = total[1] > 0 ? double(total[0]) / double(total[1]) : 0;
    figures_.interiorMax = total[2];
    figures_.scale = niceCeiling(figures_.interiorMax);
}

// targets_->error as a heatmap over the viewport of `destination`, the legend's bar and its two ends, and
// the figures' label.
void Views::drawHeatmap(const Scene& scene, const Viewport& viewport, unsigned destination) {
    const int width = viewport.width, height = viewport.height, x = viewport.x;
    const Targets& t = *targets_;
    const Programs& p = *programs_;
    // The heatmap over the viewport, then its legend and figures.
    glBindFramebuffer(GL_FRAMEBUFFER, destination);
    glViewport(x, 0, width, height);
    glClearColor(float(scene.background.x), float(scene.background.y), float(scene.background.z), 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glUseProgram(p.heatmap.program.get());
    glUniform2f(p.heatmap.origin, float(x), 0.0f);
    glUniform1f(p.heatmap.scale, float(figures_.scale));
    const glm::vec3 background(glm::clamp(scene.background, 0.0, 1.0));
    glUniform3fv(p.heatmap.background, 1, glm::value_ptr(background));
    glUniform1i(p.heatmap.legend, 0);
    bindTexture(0, t.error.color());
    p.heatmap.draw(0, 0, width, height, width, height);

    const int scale = textScale(width, height);
    const bool levelled = scene.shading != ShadingMode::Exact && !scene.objects.empty();
    const detail::ErrorFigures shown{scene.shading, levelled ? subdivisionLevel(scene, scene.objects[0]) : -1,
                                     figures_.interiorMean, figures_.interiorMax, scale};
    const Sprite& label = labels_->errorFigures.update(shown, [&] {
        std::string mode = upperAscii(toString(shown.shading));
        if (shown.level >= 0) mode += " L" + std::to_string(shown.level);
        return labelImage({"ERROR: " + mode + " - EXACT", "MEAN " + formatError(shown.mean) + "  MAX " +
                                                              formatError(shown.max) + " (1/255)"},
                          scale);
    });
    const ViewFigures::LabelBox figuresBox{scale * 4, scale * 4, label.width(), label.height()};
    // The legend's bar along the right edge, its top under the figures where the picture is too narrow for
    // both side by side.
    Labels& l = *labels_;
    const Sprite& top = l.legendTop.update(glm::dvec2(figures_.scale, scale), [&] {
        return labelImage({formatScale(figures_.scale) + "/255"}, scale);
    });
    const int barWidth = 8 * scale, barLeft = width - barWidth - 8 * scale,
              topLeft = std::max(0, barLeft + barWidth - top.width());
    int barTop = 22 * scale;
    if (ViewFigures::LabelBox{topLeft, barTop - top.height() - scale, top.width(), top.height()}.overlaps(
            figuresBox))
        barTop = figuresBox.top + figuresBox.height + top.height() + 2 * scale;
    const int barBottom = height - 22 * scale;
    if (barBottom - barTop > 8) {
        glUniform1i(p.heatmap.legend, 1);
        p.heatmap.draw(barLeft, height - barBottom, barLeft + barWidth, height - barTop, width, height);
        const Sprite& bottom = l.legendBottom.update(scale, [&] { return labelImage({"0"}, scale); });
        drawLabel(top, topLeft, barTop - top.height() - scale, x, width, height);
        drawLabel(bottom, std::max(0, barLeft + barWidth - bottom.width()), barBottom + scale, x, width,
                  height);
    }
    drawLabel(label, figuresBox.left, figuresBox.top, x, width, height);
    figures_.textScale = scale;
}

} // namespace shadelab::gl
