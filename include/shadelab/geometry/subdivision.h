// The subdivided sphere's error against the sphere it approximates (DESIGN §1): what a level leaves, which
// the scene's "auto" level (scene/auto_level.h) bounds by 4^(1−n).
#pragma once

#include "shadelab/geometry/sphere.h"

namespace shadelab {

// δₙ, the error a level leaves: the mesh's max radial deviation from the unit sphere, 1 − min over
// triangles of the distance from the origin to the triangle (the deepest point of a face is its foot point
// or on an edge). DESIGN §1 bounds it by 4^(1−n).
double maxRadialDeviation(const SphereMesh& mesh);

} // namespace shadelab
