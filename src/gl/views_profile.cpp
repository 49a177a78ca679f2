// The profile view (src/gl/views.h): the intensity along one row of the picture, the current mode's against
// exact shading's, with the columns where a mesh edge crosses the row — where Gouraud's and flat's steps
// and kinks come from.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <glad/gl.h>

#include "shadelab/image/image.h"
#include "shadelab/io/text.h"

#include "gl/views.h"
#include "gl/views_internal.h"

namespace shadelab::gl {
namespace {

using detail::kLabelBox;
using detail::kLabelText;
using detail::textScale;

constexpr glm::u8vec4 kModeCurve{255, 150, 40, 255};   // orange: the current mode
constexpr glm::u8vec4 kExactCurve{255, 255, 255, 255}; // white: exact
constexpr glm::u8vec4 kEdgeTick{80, 220, 255, 255};    // cyan: a mesh edge crosses the row

// A straight line of pixels from (x0, y0) to (x1, y1) into the image (rows from the top).
void drawLine(Image& image, int x0, int y0, int x1, int y1, glm::u8vec4 color) {
    const int steps = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
    for (int i = 0; i <= steps; ++i) {
        const double t = steps ? double(i) / steps : 0;
        fillRect(image, int(std::lround(x0 + t * (x1 - x0))), int(std::lround(y0 + t * (y1 - y0))), 1, 1,
                 color);
    }
}

// The profile's plot: the mode's and exact shading's intensity along the row, the edge crossings as ticks
// and a key, each name in its curve's colour.
Image profilePlot(const detail::ProfilePlot& p) {
    Image plot(p.width, p.height);
    fillRect(plot, 0, 0, p.width, p.height, kLabelBox);
    const int margin = 3 * p.scale, textHeight = textLineHeight(p.scale);
    const int y0 = p.height - margin - 4 * p.scale, y1 = std::min(margin + textHeight, y0); // intensity 0, 1
    auto yOf = [&](float v) { return int(std::lround(y0 + (y1 - y0) * std::clamp(double(v), 0.0, 1.0))); };
    for (int column : p.edgeColumns) drawLine(plot, column, y0 + 1, column, y0 + 4 * p.scale, kEdgeTick);
    for (int i = 1; i < p.width; ++i) {
        const std::size_t a = std::size_t(i - 1), b = std::size_t(i);
        drawLine(plot, i - 1, yOf(p.exactRow[a]), i, yOf(p.exactRow[b]), kExactCurve);
        drawLine(plot, i - 1, yOf(p.modeRow[a]), i, yOf(p.modeRow[b]), kModeCurve);
    }
    int textX = margin;
    for (const auto& [word, colour] :
         {std::pair{"ROW " + std::to_string(p.row), kLabelText},
          std::pair{upperAscii(toString(p.shading)), kModeCurve},
          std::pair{std::string("EXACT"), kExactCurve}, std::pair{std::string("EDGES"), kEdgeTick}}) {
        drawText(plot, textX, margin, word, p.scale, colour);
        textX += textWidth(word + "  ", p.scale);
    }
    return plot;
}

} // namespace

int profileRow(const Scene& scene, int height, Scene& sized) {
    if (scene.view.at) return std::clamp(int(*scene.view.at * height), 0, height - 1);
    if (scene.objects.empty()) return height / 2;
    sized = scene;
    sized.height = height;
    const SceneView view = sceneView(sized);
    const glm::dvec4 clip = view.clipFromView * view.viewFromWorld * glm::dvec4(scene.objects[0].center, 1);
    if (!(clip.w > 0)) return height / 2;
    const double yFromTop = (1 - clip.y / clip.w) / 2 * height;
    if (!(yFromTop >= 0 && yFromTop < height)) return height / 2;
    return int(yFromTop);
}

namespace {

// Row y (from the bottom) of `target` as RGBA floats, into `row`'s storage.
void readFloatRow(const RenderTarget& target, int y, std::vector<float>& row) {
    row.resize(std::size_t(target.width()) * 4);
    target.bind();
    glReadPixels(0, y, target.width(), 1, GL_RGBA, GL_FLOAT, row.data());
}

} // namespace

void Views::drawProfile(const Scene& scene, const Viewport& viewport, const DrawOptions& options,
                        unsigned destination) {
    const int width = viewport.width, height = viewport.height;
    drawModeAndExact(scene, width, height, options);
    Targets& t = *targets_;
    Scene& mode = t.profileScene;
    mode = scene;
    mode.view = View{};
    Scene& edges = t.edgesScene; // the same render with the mesh's edges over it: where they differ, an edge
    edges = mode;                // crosses
    edges.overlay = Overlay::Wireframe;
    t.edges.fit(width, height, ColorFormat::Rgba32F, depthFormatFor(scene.depth));
    t.edges.bind();
    sceneDraw_.draw(edges, {0, width, height}, options);

    resetFigures();
    const int row = profileRow(scene, height, t.rowScene);
    figures_.row = row;
    const int glRow = height - 1 - row;
    std::vector<float>&m = t.rows[0], &e = t.rows[1], &w = t.rows[2];
    readFloatRow(t.mode, glRow, m);
    readFloatRow(t.exact, glRow, e);
    readFloatRow(t.edges, glRow, w);
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
    sceneDraw_.draw(mode, viewport, options);
    const int x = viewport.x;
    glDisable(GL_DEPTH_TEST);
    glViewport(x, 0, width, height);
    glBindVertexArray(programs_->images.emptyVertexArray().get());
    const int scale = textScale(width, height);
    const int plotHeight = std::max(height / 3, 24);
    const int plotTop = row < height / 2 ? height - plotHeight : 0;
    // The plot's key assigned into kept storage, not built: its rows are copied without allocating.
    detail::ProfilePlot& shown = labels_->profileShown;
    shown.row = row;
    shown.width = width;
    shown.height = plotHeight;
    shown.scale = scale;
    shown.shading = scene.shading;
    shown.modeRow = figures_.modeRow;
    shown.exactRow = figures_.exactRow;
    shown.edgeColumns = figures_.edgeColumns;
    const Sprite& plot = labels_->profilePlot.update(shown, [&] { return profilePlot(shown); });
    figures_.textScale = scale;
    drawLabel(plot, 0, plotTop, x, width, height);
    const Sprite& marker = labels_->profileMarker.update(width, [&] {
        Image line(width, 1);
        for (int i = 0; i < width; ++i)
            fillRect(line, i, 0, 1, 1, (i / 4) % 2 ? glm::u8vec4(255, 230, 0, 255) : glm::u8vec4(0, 0, 0, 0));
        return line;
    });
    programs_->images.draw(marker, 0, row, x, width, height);
    glEnable(GL_DEPTH_TEST);
}

} // namespace shadelab::gl
