#include "shadelab/geometry/subdivision.h"

#include <algorithm>

namespace shadelab {

double maxRadialDeviation(const SphereMesh& mesh) {
    // Vertices lie on the sphere, so the deepest point of a face is the foot of the perpendicular from the
    // origin when it falls inside the face; otherwise it lies on an edge, whose deepest point is its
    // midpoint (both ends are at radius 1).
    double minDistance = 1;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3& t = mesh.triangles[i];
        const glm::dvec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
        const glm::dvec3 n = mesh.faceNormals[i];
        const glm::dvec3 foot = glm::dot(a, n) * n;
        const bool inside = glm::dot(glm::cross(b - a, foot - a), n) >= 0 &&
                            glm::dot(glm::cross(c - b, foot - b), n) >= 0 &&
                            glm::dot(glm::cross(a - c, foot - c), n) >= 0;
        const double d = inside ? glm::length(foot)
                                : std::min({glm::length((a + b) * 0.5), glm::length((b + c) * 0.5),
                                            glm::length((c + a) * 0.5)});
        minDistance = std::min(minDistance, d);
    }
    return 1 - minDistance;
}

} // namespace shadelab
