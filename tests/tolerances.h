// The image tolerances several tests share, each with its reason (DESIGN §6: every tolerance says why). A
// tolerance that belongs to one case lives in that case's table.
#pragma once

#include "shadelab/image/image.h"

namespace shadelab::test {

// A picture against its reference, made by the same Mesa. llvmpipe is deterministic, so most pixels match
// exactly; a different CPU gives llvmpipe other SIMD widths and FMA use: ±1/255 per channel from float
// rounding (maxDelta 1, mean 0.05/255). A pixel centre that lies within float rounding of a triangle edge
// may flip between two triangles or between object and background: a budget of 24 pixels beyond maxDelta.
inline constexpr Tolerance kRegressionTolerance{1, 0.05, 24};
// One picture drawn two ways by the same driver (specialized against uber programs, a geometry shader
// against duplicated vertices, a light attenuated to nothing against no light): the same coverage to the
// pixel, and the shading within float rounding.
inline constexpr Tolerance kSamePictureTwoWays{1, 0.05, 0};
// No pixel may differ at all: one driver through two backends, a screenshot against the render.
inline constexpr Tolerance kIdentical{0, 0, 0};
// For pictures that must differ: failing it means some channel is more than rounding (1/255) apart.
inline constexpr Tolerance kBeyondRounding{1, 0, 0};

} // namespace shadelab::test
