#include "shadelab/gl/views.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include <glad/gl.h>

#include "shadelab/errors.h"
#include "shadelab/geometry/subdivision.h"
#include "shadelab/gl/loader.h"
#include "shadelab/gl/program.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/gl/screen_pass.h"
#include "shadelab/image/image.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/outside_view.h"
#include "shadelab/shading/reference.h"

#include "gl/views_internal.h"

namespace shadelab::gl {
namespace {

using detail::labelImage;
using detail::textScale;

constexpr glm::u8vec4 kLabelText{240, 240, 240, 255};
constexpr glm::u8vec4 kLabelBox{0, 0, 0, 170};
constexpr glm::u8vec4 kModeCurve{255, 150, 40, 255};   // orange: the current mode
constexpr glm::u8vec4 kExactCurve{255, 255, 255, 255}; // white: exact
constexpr glm::u8vec4 kEdgeTick{80, 220, 255, 255};    // cyan: a mesh edge crosses the row

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

// A straight line of pixels from (x0, y0) to (x1, y1) into the image (rows from the top).
void drawLine(Image& image, int x0, int y0, int x1, int y1, glm::u8vec4 color) {
    const int steps = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
    for (int i = 0; i <= steps; ++i) {
        const double t = steps ? double(i) / steps : 0;
        fillRect(image, int(std::lround(x0 + t * (x1 - x0))), int(std::lround(y0 + t * (y1 - y0))), 1, 1,
                 color);
    }
}

} // namespace

namespace detail {

// Lines of 11 px (textLineHeight(1)), twice that from a 400-pixel picture on.
int textScale(int width, int height) {
    return std::min(width, height) >= 400 ? 2 : 1;
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

Views::Views(Renderer& renderer)
    : renderer_(renderer), targets_(std::make_unique<Targets>()), programs_(std::make_unique<Programs>()) {}

Views::~Views() = default;

void Views::draw(const Scene& scene, int width, int height, int x) {
    if (width <= 0 || height <= 0) return;
    GLint destination = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &destination);
    switch (scene.view.kind) {
    case ViewKind::Scene:
        renderer_.renderScene(scene, width, height, x);
        break;
    case ViewKind::Error:
        drawError(scene, width, height, x, unsigned(destination));
        break;
    case ViewKind::Split:
        drawSplit(scene, width, height, x);
        break;
    case ViewKind::Profile:
        drawProfile(scene, width, height, x, unsigned(destination));
        break;
    case ViewKind::Outside:
        drawOutside(scene, width, height, x);
        break;
    case ViewKind::Ndc:
        drawNdc(scene, width, height, x);
        break;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(destination));
    glEnable(GL_DEPTH_TEST); // as renderScene leaves it
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(0);
    glUseProgram(0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    checkGlError("drawing a teaching view");
}

// The current mode and exact shading of the scene into the two float targets, at the viewport's size; the
// exact render's alpha holds each object's index + 1, so the compare pass knows which pixels one object
// covers.
void Views::renderModeAndExact(const Scene& scene, int width, int height) {
    if (!capabilities().floatColorTargets)
        throw RuntimeError("the " + toString(scene.view) +
                           " view measures unrounded colours in float (RGBA32F) "
                           "targets, which need EXT_color_buffer_float; this " +
                           std::string(displayName(capabilities().api)) + " context lacks it");
    const DepthFormat depth = depthFormatFor(scene.depth);
    targets_->mode.fit(width, height, ColorFormat::Rgba32F, depth);
    targets_->exact.fit(width, height, ColorFormat::Rgba32F, depth);
    Scene mode = scene;
    mode.view = View{};
    mode.overlay = Overlay::None;        // the lines are no part of the shading's error
    Scene exact = withTrueNormals(mode); // with normals by M, the error is what the wrong matrix costs
    exact.shading = ShadingMode::Exact;
    exact.overlay = Overlay::None;
    targets_->mode.bind();
    renderer_.renderScene(mode, width, height, 0);
    targets_->exact.bind();
    // Toon is measured against the exact sphere quantized the same way, as `shadelab report` does: its bands
    // are the mode's design, not its error.
    renderer_.setExactObjectIds(true);
    renderer_.setExactToon(scene.shading == ShadingMode::Toon);
    renderer_.renderScene(exact, width, height, 0);
    renderer_.setExactObjectIds(false);
    renderer_.setExactToon(false);
}

void Views::drawError(const Scene& scene, int width, int height, int x, unsigned destination) {
    renderModeAndExact(scene, width, height);
    Targets& t = *targets_;
    const Programs& p = *programs_;
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(p.images.emptyVertexArray().get());

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
    figures_ = ViewFigures{};
    figures_.interiorPixels = std::size_t(std::lround(total[1]));
    figures_.interiorMean = total[1] > 0 ? double(total[0]) / double(total[1]) : 0;
    figures_.interiorMax = total[2];
    figures_.scale = niceCeiling(figures_.interiorMax);

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
    const int barWidth = 8 * scale, barLeft = width - barWidth - 8 * scale;
    const int barTop = 22 * scale, barBottom = height - 22 * scale;
    if (barBottom - barTop > 8) {
        glUniform1i(p.heatmap.legend, 1);
        p.heatmap.draw(barLeft, height - barBottom, barLeft + barWidth, height - barTop, width, height);
        const Image top = labelImage({formatScale(figures_.scale) + "/255"}, scale);
        const Image bottom = labelImage({"0"}, scale);
        p.images.draw(top, std::max(0, barLeft + barWidth - top.width), barTop - top.height - scale, x, width,
                      height);
        p.images.draw(bottom, std::max(0, barLeft + barWidth - bottom.width), barBottom + scale, x, width,
                      height);
    }
    std::string mode = upperAscii(toString(scene.shading));
    if (scene.shading != ShadingMode::Exact && !scene.objects.empty())
        mode += " L" + std::to_string(subdivisionLevel(scene, scene.objects[0]));
    p.images.draw(
        labelImage({"ERROR: " + mode + " - EXACT", "MEAN " + formatError(figures_.interiorMean) + "  MAX " +
                                                       formatError(figures_.interiorMax) + " (1/255)"},
                   scale),
        scale * 4, scale * 4, x, width, height);
}

Scene splitSideScene(const Scene& scene, const SplitSide& side) {
    Scene out = scene;
    out.view = View{};
    if (side.shading) out.shading = *side.shading;
    if (side.lighting) out.lighting = *side.lighting;
    if (side.level)
        for (SceneObject& o : out.objects) o.subdivisions = *side.level;
    if (side.view) {
        out.view.kind = *side.view;
        out.view.observer = scene.view.observer;
    }
    // The exact side is the truth, as the error view's exact: beside a picture with normals by M it shows
    // what the right matrix draws.
    return side.shading == ShadingMode::Exact ? withTrueNormals(out) : out;
}

std::string sideLabel(const Scene& scene, const SplitSide& side) {
    if (side.view) return upperAscii(toString(side));
    const Scene s = splitSideScene(scene, side);
    std::string label = upperAscii(toString(s.shading));
    if (s.shading != ShadingMode::Exact && !s.objects.empty())
        label += " L" + std::to_string(subdivisionLevel(s, s.objects[0]));
    if (side.lighting || (!side.shading && !side.level)) label += " " + upperAscii(toString(s.lighting));
    return label;
}

void Views::drawSplit(const Scene& scene, int width, int height, int x) {
    figures_ = ViewFigures{};
    const int divider = std::clamp(int(std::lround(scene.view.at.value_or(0.5) * width)), 0, width);
    // Each side clears and draws only its own pixels: the left side is a plain render of A there.
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, 0, divider, height);
    renderer_.render(splitSideScene(scene, scene.view.left), width, height, x); // a side may be a view
    glEnable(GL_SCISSOR_TEST);
    glScissor(x + divider, 0, width - divider, height);
    renderer_.render(splitSideScene(scene, scene.view.right), width, height, x);
    // The divider: two pixels of white straddling it.
    glEnable(GL_SCISSOR_TEST);
    glScissor(x + divider - 1, 0, 2, height);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
    glViewport(x, 0, width, height);
    glBindVertexArray(programs_->images.emptyVertexArray().get());
    const int scale = textScale(width, height);
    const Image left = labelImage({sideLabel(scene, scene.view.left)}, scale);
    const Image right = labelImage({sideLabel(scene, scene.view.right)}, scale);
    programs_->images.draw(left, std::max(0, divider - left.width - 4 * scale), 4 * scale, x, width, height);
    programs_->images.draw(right, std::min(divider + 4 * scale, std::max(0, width - right.width)), 4 * scale,
                           x, width, height);
    glEnable(GL_DEPTH_TEST);
}

int profileRow(const Scene& scene, int height) {
    if (scene.view.at) return std::clamp(int(*scene.view.at * height), 0, height - 1);
    if (scene.objects.empty()) return height / 2;
    Scene sized = scene;
    sized.height = height;
    const SceneView view = sceneView(sized);
    const glm::dvec4 clip = view.clipFromView * view.viewFromWorld * glm::dvec4(scene.objects[0].center, 1);
    if (!(clip.w > 0)) return height / 2;
    const double yFromTop = (1 - clip.y / clip.w) / 2 * height;
    if (!(yFromTop >= 0 && yFromTop < height)) return height / 2;
    return int(yFromTop);
}

void Views::drawProfile(const Scene& scene, int width, int height, int x, unsigned destination) {
    renderModeAndExact(scene, width, height);
    Targets& t = *targets_;
    Scene mode = scene;
    mode.view = View{};
    Scene edges = mode; // the same render with the mesh's edges over it: where they differ, an edge crosses
    edges.overlay = Overlay::Wireframe;
    t.edges.fit(width, height, ColorFormat::Rgba32F, depthFormatFor(scene.depth));
    t.edges.bind();
    renderer_.renderScene(edges, width, height, 0);

    figures_ = ViewFigures{};
    const int row = profileRow(scene, height);
    figures_.row = row;
    const int glRow = height - 1 - row;
    const std::vector<float> m = t.mode.readFloatRow(glRow), e = t.exact.readFloatRow(glRow),
                             w = t.edges.readFloatRow(glRow);
    figures_.modeRow.resize(std::size_t(width));
    figures_.exactRow.resize(std::size_t(width));
    for (int i = 0; i < width; ++i) {
        const std::size_t k = std::size_t(i) * 4;
        figures_.modeRow[std::size_t(i)] = (m[k] + m[k + 1] + m[k + 2]) / 3;
        figures_.exactRow[std::size_t(i)] = (e[k] + e[k + 1] + e[k + 2]) / 3;
        if (scene.shading != ShadingMode::Exact && m[k + 3] > 0.5f &&
            (w[k] != m[k] || w[k + 1] != m[k + 1] || w[k + 2] != m[k + 2]))
            figures_.edgeColumns.push_back(i);
    }

    // The picture itself, then the plot over a third of it (below the row, or above it when the row is in
    // the lower half), the row marked across the picture.
    glBindFramebuffer(GL_FRAMEBUFFER, destination);
    renderer_.renderScene(mode, width, height, x);
    glDisable(GL_DEPTH_TEST);
    glViewport(x, 0, width, height);
    glBindVertexArray(programs_->images.emptyVertexArray().get());
    const int scale = textScale(width, height);
    const int plotHeight = std::max(height / 3, 24);
    const int plotTop = row < height / 2 ? height - plotHeight : 0;
    Image plot(width, plotHeight);
    fillRect(plot, 0, 0, width, plotHeight, kLabelBox);
    const int margin = 3 * scale, textHeight = textLineHeight(scale);
    const int y0 = plotHeight - margin - 4 * scale, y1 = std::min(margin + textHeight, y0); // intensity 0, 1
    auto yOf = [&](float v) { return int(std::lround(y0 + (y1 - y0) * std::clamp(double(v), 0.0, 1.0))); };
    for (int column : figures_.edgeColumns) drawLine(plot, column, y0 + 1, column, y0 + 4 * scale, kEdgeTick);
    for (int i = 1; i < width; ++i) {
        const std::size_t a = std::size_t(i - 1), b = std::size_t(i);
        drawLine(plot, i - 1, yOf(figures_.exactRow[a]), i, yOf(figures_.exactRow[b]), kExactCurve);
        drawLine(plot, i - 1, yOf(figures_.modeRow[a]), i, yOf(figures_.modeRow[b]), kModeCurve);
    }
    // The key: each name in its curve's colour.
    int textX = margin;
    for (const auto& [word, colour] :
         {std::pair{"ROW " + std::to_string(row), kLabelText},
          std::pair{upperAscii(toString(scene.shading)), kModeCurve},
          std::pair{std::string("EXACT"), kExactCurve}, std::pair{std::string("EDGES"), kEdgeTick}}) {
        drawText(plot, textX, margin, word, scale, colour);
        textX += textWidth(word + "  ", scale);
    }
    programs_->images.draw(plot, 0, plotTop, x, width, height);
    Image marker(width, 1);
    for (int i = 0; i < width; ++i)
        fillRect(marker, i, 0, 1, 1, (i / 4) % 2 ? glm::u8vec4(255, 230, 0, 255) : glm::u8vec4(0, 0, 0, 0));
    programs_->images.draw(marker, 0, row, x, width, height);
    glEnable(GL_DEPTH_TEST);
}

} // namespace shadelab::gl
