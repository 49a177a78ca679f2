// The presets M and L cycle through (demo_presets.cpp).
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "shadelab/scene/scene.h"

namespace shadelab::app {

struct MaterialPreset {
    std::string_view name;
    Material material;
};
struct LightPreset {
    std::string_view name;
    std::vector<Light> lights;
};
std::span<const MaterialPreset> materialPresets(); // matte (k_s = 0), plastic (α = 8), metal (α = 150)
std::span<const LightPreset> lightPresets();       // point, directional, spot, three coloured lights

} // namespace shadelab::app
