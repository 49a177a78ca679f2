// The presets M and L cycle through: materials, and light set-ups.
#include <vector>

#include "app/demo/demo_state.h"

namespace shadelab::app {
namespace {

Light pointLight(glm::dvec3 position, glm::dvec3 color) {
    Light light;
    light.position = position;
    light.ambient = {0.1, 0.1, 0.1};
    light.diffuse = light.specular = color;
    return light;
}

} // namespace

std::span<const MaterialPreset> materialPresets() {
    static const MaterialPreset kPresets[] = {
        {"matte", {{0.1, 0.1, 0.1}, {0.2, 0.55, 0.25}, {0, 0, 0}, 1}},
        {"plastic", {{0.1, 0.1, 0.1}, {0.15, 0.3, 0.75}, {0.8, 0.8, 0.8}, 8}},
        {"metal", {{0.12, 0.1, 0.05}, {0.35, 0.28, 0.12}, {0.95, 0.8, 0.45}, 150}},
    };
    return kPresets;
}

std::span<const LightPreset> lightPresets() {
    static const std::vector<LightPreset> kPresets = [] {
        Light directional;
        directional.type = LightType::Directional;
        directional.direction = {-1, -1, -1.5};
        directional.ambient = {0.1, 0.1, 0.1};
        Light spot = pointLight({1.5, 1.5, 3}, {1, 1, 1});
        spot.type = LightType::Spot;
        spot.direction = {-1.5, -1.5, -3};
        spot.cutoffDeg = 18;
        spot.exponent = 10;
        return std::vector<LightPreset>{
            {"point", {pointLight({3, 3, 5}, {1, 1, 1})}},
            {"directional", {directional}},
            {"spot", {spot}},
            {"three coloured",
             {pointLight({3, 2, 4}, {0.9, 0.3, 0.3}), pointLight({-3, 2, 4}, {0.3, 0.9, 0.3}),
              pointLight({0, -3, 4}, {0.3, 0.4, 1.0})}},
        };
    }();
    return kPresets;
}

} // namespace shadelab::app
