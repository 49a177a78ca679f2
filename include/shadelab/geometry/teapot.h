// Newell's teapot (docs/DESIGN.md §1, "The teapot"): 32 bicubic Bézier patches, evaluated exactly and
// tessellated on a uniform grid per patch. Pure CPU data, in double, in object coordinates: y up, height 2,
// centred on y = 0 (the data's (x, y, z) becomes (x, z − 1.575, −y) / 1.575).
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "shadelab/geometry/triangle_mesh.h"

namespace shadelab {

inline constexpr int kTeapotPatchCount = 32;
inline constexpr int kMaxTeapotLevel = 8;

// Patch p's 16 control points in object coordinates, P[4i + j] in the data's order (i: the u row, j: the
// v column).
using TeapotPatch = std::array<glm::dvec3, 16>;
const std::array<TeapotPatch, kTeapotPatchCount>& teapotPatches();

// P(u, v) = Σᵢ Σⱼ Bᵢ(u) Bⱼ(v) P[4i + j] and its partial derivatives, for u, v in [0, 1].
struct PatchPoint {
    glm::dvec3 position, du, dv;
};
PatchPoint evaluatePatch(const TeapotPatch& patch, double u, double v);
// The unit outward normal normalize(∂P/∂v × ∂P/∂u); at a cusp (the data's x = y = 0, where the cross
// product vanishes) +y above the middle and −y below.
glm::dvec3 patchNormal(const TeapotPatch& patch, double u, double v);

// Counts for level n: (2ⁿ + 1)² vertices per patch (not shared between patches); 2·4ⁿ triangles per patch
// less the dropped degenerate ones (level 2: 992, level 3: 4,032).
std::size_t teapotVertexCount(int level);
std::size_t teapotTriangleCount(int level);
// Throws InputError "<field>: must be between 0 and 8, got 9" outside 0..kMaxTeapotLevel.
void checkTeapotLevel(int level, std::string_view field = "subdivisions");

// The level-n mesh: each patch on a uniform (2ⁿ)² grid, the analytic normals per vertex, flat face normals.
// patchUv holds each vertex's (patch, u, v): the start exact shading refines from.
struct TeapotMesh : TriangleMesh {
    int level = 0;
    std::vector<glm::dvec3> patchUv;
};
TeapotMesh buildTeapot(int level);

// The largest distance, in object units, between the level-n mesh and the surface it approximates (a
// bound, DESIGN §1): "auto" picks the level from it as it does for the sphere from δₙ.
double teapotMeshError(int level);

} // namespace shadelab
