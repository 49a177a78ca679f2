// Screen-space subdivision (DESIGN §1): the smallest level whose silhouette error stays below a tolerance
// in pixels for an object's projected size. The sphere's mesh is inscribed with max radial deviation
// δₙ < 4^(1−n) (geometry/subdivision.h), so its silhouette is at most R_px·δₙ pixels inside the exact one:
//   n = ⌈1 + ½·log₂(R_px / τ)⌉, with τ·cos²α for τ under perspective (sin α = r / distance).
// The teapot's level-n mesh lies within teapotMeshError(n) object units of its patches (teapot.h), which
// the bounding radius B turns into pixels: the smallest n with teapotMeshError(n)·R_px/B ≤ τ·cos²α.
#pragma once

#include <cstddef>

#include "shadelab/scene/scene.h"

namespace shadelab {

// The radius, in object units, of a sphere about the object's origin that holds it: 1 for the sphere; for
// the teapot the largest |P| over its control points (a Bézier patch lies in their convex hull); for a mesh
// the largest |p| over its vertices, 1 while its model is not loaded.
double boundingRadius(const SceneObject& object);
double teapotBoundingRadius();

// The object's bounding radius (radius × its largest |scale| × boundingRadius) projected to pixels: under
// perspective the silhouette's radius on the image plane, under orthographic the radius times the pixels
// per unit. Returns +infinity when the eye is inside the bounding sphere.
double projectedRadiusPx(const Scene& scene, const SceneObject& object);

// The level "auto" chooses for `object`: the sphere's 0..kMaxSubdivisions, the teapot's 0..kMaxTeapotLevel;
// 0 for a mesh, which has no levels.
int autoSubdivisionLevel(const Scene& scene, const SceneObject& object);

// The object's level: its own, or the one "auto" chooses (0 for a mesh).
int subdivisionLevel(const Scene& scene, const SceneObject& object);

// The triangles `object` draws at `level` (subdivisionLevel's, or a split side's): the sphere's 4^(level+1),
// the teapot's teapotTriangleCount, a mesh its model's whatever the level (0 while it is not loaded).
std::size_t triangleCount(const SceneObject& object, int level);

} // namespace shadelab
