#include <string>

#include "shadelab/headless.h"

namespace shadelab {
namespace {

constexpr glm::u8vec4 kLabelColor{235, 235, 235, 255};
constexpr glm::u8vec4 kPanelColor{24, 24, 28, 255};
constexpr int kLabelScale = 2;
constexpr int kLabelHeight = 7 * kLabelScale + 12; // one line of the 5×7 font plus padding

std::string upper(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = char(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

} // namespace

Image renderShowcase(HeadlessRenderer& renderer, const Scene& scene, int tileSize) {
    const int columns = int(kShadingModes.size()), rows = int(kLightingModels.size());
    const int cellHeight = tileSize + kLabelHeight;
    Image canvas(columns * tileSize, rows * cellHeight);
    fillRect(canvas, 0, 0, canvas.width, canvas.height, kPanelColor);

    Scene tile = scene;
    tile.width = tile.height = tileSize;
    for (int row = 0; row < rows; ++row) {
        for (int column = 0; column < columns; ++column) {
            tile.shading = kShadingModes[std::size_t(column)];
            tile.lighting = kLightingModels[std::size_t(row)];
            const int x = column * tileSize, y = row * cellHeight;
            const std::string label = upper(toString(tile.shading)) + " / " + upper(toString(tile.lighting));
            drawText(canvas, x + (tileSize - textWidth(label, kLabelScale)) / 2, y + 6, label, kLabelScale,
                     kLabelColor);
            blit(canvas, renderer.render(tile), x, y + kLabelHeight);
        }
    }
    return canvas;
}

} // namespace shadelab
