#include "shadelab/geometry/mesh_layout.h"

#include <algorithm>
#include <cmath>

namespace shadelab {

std::vector<SmoothVertex> smoothVertices(const TriangleMesh& mesh) {
    std::vector<SmoothVertex> out(mesh.positions.size());
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = {glm::vec3(mesh.positions[i]), glm::vec3(mesh.vertexNormals[i])};
    return out;
}

std::vector<std::uint32_t> smoothIndices(const TriangleMesh& mesh) {
    std::vector<std::uint32_t> out;
    out.reserve(mesh.triangles.size() * 3);
    for (const glm::uvec3& t : mesh.triangles) out.insert(out.end(), {t.x, t.y, t.z});
    return out;
}

std::vector<FlatVertex> flatVertices(const TriangleMesh& mesh) {
    std::vector<FlatVertex> out;
    out.reserve(mesh.triangles.size() * 3);
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3& t = mesh.triangles[i];
        const glm::dvec3 centroid = (mesh.positions[t.x] + mesh.positions[t.y] + mesh.positions[t.z]) / 3.0;
        for (int k = 0; k < 3; ++k)
            out.push_back(
                {glm::vec3(mesh.positions[t[k]]), glm::vec3(centroid), glm::vec3(mesh.faceNormals[i])});
    }
    return out;
}

double meshBytes(int level, MeshLayout layout) {
    level =
        std::clamp(level, 0, 1000); // 2·level must not overflow int; 4^1000 is inf in double, which is fine
    const double triangles = std::ldexp(4.0, 2 * level), vertices = std::ldexp(2.0, 2 * level) + 2;
    if (layout == MeshLayout::Flat) return triangles * 3 * double(sizeof(FlatVertex));
    return vertices * double(sizeof(SmoothVertex)) + triangles * 3 * double(sizeof(std::uint32_t));
}

} // namespace shadelab
