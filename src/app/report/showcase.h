// The showcase: one picture of a scene in every shading mode and lighting model, from headless renders
// (the demo's picture without a display, `shadelab showcase`).
#pragma once

#include "shadelab/context/headless.h"
#include "shadelab/image/image.h"
#include "shadelab/scene/scene.h"

namespace shadelab {

// Every shading mode × lighting model of `scene`, tileSize² each, labelled, side by side (modes across,
// lighting models down).
inline constexpr int kShowcaseTile = 256, kShowcaseStripHeight = 26; // a tile's side; a title strip's height
Image renderShowcase(HeadlessRenderer& renderer, const Scene& scene, int tileSize = kShowcaseTile);

} // namespace shadelab
