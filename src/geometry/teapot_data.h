// Newell's teapot as distributed (docs/DESIGN.md §1, "The teapot"): the data's control points and the 32
// patches' indices into them, in the data's own coordinates (z up, height 3.15). teapot.cpp converts them to
// object coordinates.
#pragma once

#include <array>

#include <glm/glm.hpp>

namespace shadelab::detail {

inline constexpr int kTeapotDataPointCount = 306;
// Part by part, in the data's order: rim 0–3, body 4–11, handle 12–15, spout 16–19, lid 20–27, bottom 28–31.
extern const std::array<std::array<int, 16>, 32> kTeapotPatchIndices;
extern const std::array<glm::dvec3, kTeapotDataPointCount> kTeapotDataPoints;

} // namespace shadelab::detail
