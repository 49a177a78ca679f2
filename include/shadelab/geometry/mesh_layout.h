// The sphere's GPU-ready vertex layouts (float, converted once from the double mesh of sphere.h), and what
// they take in memory, for every estimate that needs it (sphere_limits.cpp, app/measure/memory_budget.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "shadelab/geometry/sphere.h"

namespace shadelab {

// Gouraud, Phong and toon shading: the shared vertices and 32-bit indices, three per triangle.
struct SmoothVertex {
    glm::vec3 position;
    glm::vec3 normal;
};
// Flat shading: three vertices per triangle, each carrying the triangle's centroid and face normal, so
// the lighting is evaluated once per triangle at its centroid (DESIGN §3) whichever vertex provokes.
struct FlatVertex {
    glm::vec3 position;
    glm::vec3 centroid;
    glm::vec3 faceNormal;
};

std::vector<SmoothVertex> smoothVertices(const TriangleMesh& mesh);
std::vector<std::uint32_t> smoothIndices(const TriangleMesh& mesh);
std::vector<FlatVertex> flatVertices(const TriangleMesh& mesh);

enum class MeshLayout { Smooth, Flat };
// The bytes of a level's arrays in `layout`: smoothVertices and smoothIndices, or flatVertices. In double,
// so that an absurd level (asked for by mistake) gives a huge figure rather than a wrapped one.
double meshBytes(int level, MeshLayout layout);

} // namespace shadelab
