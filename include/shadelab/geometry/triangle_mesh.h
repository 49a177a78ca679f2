// A triangle mesh as plain CPU data, in double, in object space: what the sphere, the teapot and a model
// file all become before upload (gl/mesh.h) and what the ray casts and the overlay read.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace shadelab {

struct TriangleMesh {
    std::vector<glm::dvec3> positions;     // object space
    std::vector<glm::uvec3> triangles;     // indices into positions, counter-clockwise seen from outside
    std::vector<glm::dvec3> faceNormals;   // one unit normal per triangle
    std::vector<glm::dvec3> vertexNormals; // one unit normal per vertex
};

} // namespace shadelab
