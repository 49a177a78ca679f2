#include "app/report/showcase.h"

#include <string>

#include "shadelab/context/headless.h"
#include "shadelab/io/text.h"

namespace shadelab {
namespace {

constexpr glm::u8vec4 kTextColor{235, 235, 235, 255};
constexpr glm::u8vec4 kBannerColor{52, 58, 74, 255};
constexpr glm::u8vec4 kPanelColor{24, 24, 28, 255};
constexpr int kTextScale = 2;
constexpr int kStripHeight =
    kShowcaseStripHeight; // one line of text at kTextScale (textLineHeight: 22 px) plus padding

void centredText(Image& canvas, int x, int y, int width, const std::string& text) {
    drawText(canvas, x + (width - textWidth(text, kTextScale)) / 2, y + 6, text, kTextScale, kTextColor);
}

} // namespace

// Rows: one per lighting model, headed by a banner naming it; columns: one per shading mode, each tile
// headed by the mode's name, and under it the mode's error view (|mode − exact| as a heatmap, labelled
// with its interior mean and max).
Image renderShowcase(HeadlessRenderer& renderer, const Scene& scene, int tileSize) {
    const int columns = int(kShadingModes.size()), rows = int(kLightingModels.size());
    const int rowHeight = 2 * kStripHeight + 2 * tileSize;
    Image canvas(columns * tileSize, rows * rowHeight);
    fillRect(canvas, 0, 0, canvas.width, canvas.height, kPanelColor);

    Scene tile = scene;
    tile.width = tile.height = tileSize;
    for (int row = 0; row < rows; ++row) {
        tile.lighting = kLightingModels[std::size_t(row)];
        const int y = row * rowHeight;
        fillRect(canvas, 0, y, canvas.width, kStripHeight, kBannerColor);
        centredText(canvas, 0, y, canvas.width, upperAscii(toString(tile.lighting)) + " LIGHTING");
        for (int column = 0; column < columns; ++column) {
            tile.shading = kShadingModes[std::size_t(column)];
            const int x = column * tileSize;
            centredText(canvas, x, y + kStripHeight, tileSize,
                        upperAscii(toString(tile.shading)) + " SHADING");
            tile.view = View{};
            blit(canvas, renderer.render(tile), x, y + 2 * kStripHeight);
            tile.view.kind = ViewKind::Error;
            blit(canvas, renderer.render(tile), x, y + 2 * kStripHeight + tileSize);
        }
    }
    return canvas;
}

} // namespace shadelab
