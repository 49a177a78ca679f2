// Screen-space subdivision (DESIGN §1): the smallest level whose silhouette error stays below a tolerance
// in pixels for an object's projected size. The mesh is inscribed in the sphere with max radial deviation
// δₙ < 4^(1−n) (geometry/subdivision.h), so the silhouette is at most R_px·δₙ pixels inside the exact one:
//   n = ⌈1 + ½·log₂(R_px / τ)⌉, with τ·cos²α for τ under perspective (sin α = r / distance).
#pragma once

#include "shadelab/scene/scene.h"

namespace shadelab {

// The object's bounding radius (radius × its largest |scale|) projected to pixels: under perspective the
// silhouette's radius on the image plane, under orthographic the radius times the pixels per unit. Returns
// +infinity when the eye is inside the bounding sphere.
double projectedRadiusPx(const Scene& scene, const SceneObject& object);

// The level "auto" chooses for `object` (0..kMaxSubdivisions).
int autoSubdivisionLevel(const Scene& scene, const SceneObject& object);

// The object's level: its own, or the one "auto" chooses.
int subdivisionLevel(const Scene& scene, const SceneObject& object);

} // namespace shadelab
