// The levels each shape is tessellated at (DESIGN §1), for the commands that step through them: the demo's
// + and −, and the report's rows.
#pragma once

#include "shadelab/geometry/sphere.h"
#include "shadelab/geometry/teapot.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app {

// The finest level of `shape`: the sphere's kMaxSubdivisions, the teapot's kMaxTeapotLevel, 0 for a mesh
// read from a file (it has no levels).
constexpr int finestLevel(Shape shape) {
    return shape == Shape::Teapot ? kMaxTeapotLevel : shape == Shape::Sphere ? kMaxSubdivisions : 0;
}

} // namespace shadelab::app
