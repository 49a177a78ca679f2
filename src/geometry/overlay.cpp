#include "shadelab/geometry/overlay.h"

#include <algorithm>
#include <cmath>

namespace shadelab {
namespace {

void segment(std::vector<LineVertex>& lines, const glm::dvec3& from, const glm::dvec3& to, glm::vec3 color) {
    lines.push_back({glm::vec3(from), color});
    lines.push_back({glm::vec3(to), color});
}

} // namespace

std::vector<LineVertex> overlayLines(const SphereMesh& mesh, Overlay overlay) {
    std::vector<LineVertex> lines;
    if (overlay == Overlay::None) return lines;
    const double lift = kOverlayLift;
    // Each edge is shared by two triangles, once in each direction: keep the direction with a < b.
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const unsigned a = t[k], b = t[(k + 1) % 3];
            if (a < b) segment(lines, lift * mesh.positions[a], lift * mesh.positions[b], kEdgeColor);
        }
    if (overlay != Overlay::Normals) return lines;
    // A little longer than an edge (about 1.63 / 2^level), but never a hair nor a spike.
    const double length = std::clamp(0.7 * 1.63 / std::exp2(mesh.level), 0.05, 0.35);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const glm::uvec3 t = mesh.triangles[f];
        const glm::dvec3 centroid = (mesh.positions[t.x] + mesh.positions[t.y] + mesh.positions[t.z]) / 3.0;
        segment(lines, centroid, centroid + length * mesh.faceNormals[f], kFaceNormalColor);
    }
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
        segment(lines, lift * mesh.positions[v], mesh.positions[v] + length * mesh.vertexNormals[v],
                kVertexNormalColor);
    return lines;
}

std::vector<LineVertex> probeLines(const ProbeReport& probe, double length) {
    std::vector<LineVertex> lines;
    const SurfacePoint& p = probe.mode.pointView;
    segment(lines, p.position, p.position + length * p.normal, kNormalColor);
    segment(lines, p.position, p.position + length * p.toViewer, kToViewerColor);
    if (probe.light >= 0) {
        segment(lines, p.position, p.position + length * probe.mode.toLight, kToLightColor);
        segment(lines, p.position, p.position + length * probe.mode.specularVector, kSpecularVectorColor);
    }
    const double arm = 0.1 * length;
    segment(lines, p.position - glm::dvec3(arm, 0, 0), p.position + glm::dvec3(arm, 0, 0), kProbeMarkColor);
    segment(lines, p.position - glm::dvec3(0, arm, 0), p.position + glm::dvec3(0, arm, 0), kProbeMarkColor);
    return lines;
}

} // namespace shadelab
