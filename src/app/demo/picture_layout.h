// Where the demo's picture goes in its window or canvas: the panel's column and the rectangle of the
// scene's own aspect beside it (demo_camera.cpp).
#pragma once

namespace shadelab::app {

// The width of the demo's control panel, docked as a left column beside the picture (0 when hidden): at
// most 420 px and at most half the window, so the picture always keeps at least half of it.
// `uiScale` (--ui-scale, --present) widens it with the text.
inline int panelColumnWidth(int windowWidth, bool panelShown, double uiScale = 1) {
    if (!panelShown || windowWidth <= 0) return 0;
    const int widest = int(420 * uiScale);
    return windowWidth / 2 < widest ? windowWidth / 2 : widest;
}

// Where a picture goes in an area of the window (pixels, from the area's top left): the largest rectangle
// of the scene's own aspect that fits, centred, with bars above and below or at the sides. The window then
// frames the scene as `render` does at that size; a 0 × 0 rectangle for an empty area.
struct PictureRect {
    int x = 0, y = 0, width = 0, height = 0;
    bool contains(double px, double py) const {
        return px >= x && px < x + width && py >= y && py < y + height;
    }
};
PictureRect fitPicture(int sceneWidth, int sceneHeight, int areaWidth, int areaHeight);

} // namespace shadelab::app
