#include "shadelab/diagram/overlay.h"

#include <algorithm>
#include <cmath>

#include "diagram/overlay_lines.h"
#include "shadelab/scene/camera.h"

namespace shadelab {
namespace {

using detail::NormalTips;
using detail::segment;

} // namespace

NormalsShown normalsShown(int level) {
    const int shown = std::min(level, kNormalsOverlayLevel);
    return {shown, std::size_t(1) << (2 * (level - shown))};
}

std::vector<LineVertex> overlayLines(const SphereMesh& mesh, Overlay overlay,
                                     const glm::dmat3& worldFromObject, NormalMatrixRule rule) {
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
    // Past kNormalsOverlayLevel the normals would be a hairball: each face of that level shows the normal
    // of its centre descendant (the middle child, four[3] in sphere.cpp, again and again: face f of level
    // L descends from face f / 4^(L-k) of level k), and the vertices of that level show theirs (the
    // coarser levels' vertices come first). A little longer than an edge of the level shown (about
    // 1.63 / 2^level), but never a hair nor a spike; in world space, as long on every side of a stretched
    // object (the cube root of |det M| is its mean scale).
    const NormalsShown shown = normalsShown(mesh.level);
    const double length = std::clamp(0.7 * 1.63 / std::exp2(shown.level), 0.05, 0.35);
    const NormalTips tip{glm::inverse(worldFromObject),
                         normalViewFromObject(glm::dmat4(worldFromObject), rule),
                         length * std::cbrt(std::abs(glm::determinant(worldFromObject)))};
    for (std::size_t f = shown.faceStride - 1; f < mesh.triangles.size(); f += shown.faceStride) {
        const glm::uvec3 t = mesh.triangles[f];
        const glm::dvec3 centroid = (mesh.positions[t.x] + mesh.positions[t.y] + mesh.positions[t.z]) / 3.0;
        segment(lines, centroid, tip(centroid, mesh.faceNormals[f]), kFaceNormalColor);
    }
    for (std::size_t v = 0; v < std::min(mesh.positions.size(), sphereVertexCount(shown.level)); ++v) {
        const glm::dvec3 from = lift * mesh.positions[v];
        segment(lines, from, tip(from, mesh.vertexNormals[v]), kVertexNormalColor);
    }
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
    if (const NormalMatrixArgument& a = probe.normalMatrix; a.unevenScale) {
        segment(lines, p.position, p.position + length * a.tangentByM, kTangentByMColor);
        segment(lines, p.position, p.position + length * a.normalByM, kNormalByMColor);
        segment(lines, p.position, p.position + length * a.normalByInverseTranspose,
                kNormalByInverseTransposeColor);
    }
    const double arm = 0.1 * length;
    segment(lines, p.position - glm::dvec3(arm, 0, 0), p.position + glm::dvec3(arm, 0, 0), kProbeMarkColor);
    segment(lines, p.position - glm::dvec3(0, arm, 0), p.position + glm::dvec3(0, arm, 0), kProbeMarkColor);
    return lines;
}

} // namespace shadelab
