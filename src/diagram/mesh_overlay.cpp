#include "shadelab/diagram/mesh_overlay.h"
#include "diagram/overlay_lines.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace shadelab {
namespace {

using detail::NormalTips;
using detail::segment;

double boundRadius(const TriangleMesh& mesh) {
    double largest = 0;
    for (const glm::dvec3& p : mesh.positions) largest = std::max(largest, glm::length(p));
    return largest;
}

// Each vertex's first vertex at the same position (itself if none came before). Positions that meet are
// computed from different control points or rows (the teapot's patch borders) and may differ in the last
// bits, so they are compared on a grid of 2⁻³⁰ of the mesh's size: two copies of one point fall into
// different cells only when they straddle a cell's wall, for a rounding difference of 1e-16 about once in
// 10⁷ points — an edge then drawn twice, over itself.
std::vector<std::uint32_t> firstAtSamePlace(const TriangleMesh& mesh, double radius) {
    using Cell = std::array<long long, 3>;
    struct CellHash {
        std::size_t operator()(const Cell& c) const {
            return std::size_t(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
        }
    };
    const double cellsPerUnit = std::ldexp(1.0, 30) / std::max(radius, 1e-300);
    std::unordered_map<Cell, std::uint32_t, CellHash> seen;
    seen.reserve(mesh.positions.size());
    std::vector<std::uint32_t> first(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::dvec3 c = glm::round(mesh.positions[v] * cellsPerUnit);
        first[v] = seen.try_emplace(Cell{(long long)c.x, (long long)c.y, (long long)c.z}, std::uint32_t(v))
                       .first->second;
    }
    return first;
}

// Which normals a shape shows, and how much longer than its mean edge they are drawn (the edge of the
// level they stand for).
struct NormalsChoice {
    std::vector<bool> vertices, faces;
    double edgesPerNormal = 1;
};

std::vector<LineVertex> meshLines(const TriangleMesh& mesh, Overlay overlay,
                                  const glm::dmat3& worldFromObject, NormalMatrixRule rule,
                                  const NormalsChoice& shown) {
    std::vector<LineVertex> lines;
    if (overlay != Overlay::Wireframe && overlay != Overlay::Normals) return lines;
    const double radius = boundRadius(mesh);
    const std::vector<std::uint32_t> first = firstAtSamePlace(mesh, radius);
    // Every edge by its ends' first vertices, smaller first, sorted, each kept once; an edge whose ends are
    // one point (a cusp's collapsed row) has no length and is not drawn.
    std::vector<std::uint64_t> edges;
    edges.reserve(3 * mesh.triangles.size());
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = first[t[k]], b = first[t[(k + 1) % 3]];
            if (a != b) edges.push_back(std::uint64_t(std::min(a, b)) << 32 | std::max(a, b));
        }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    // Lifted along the vertex normal, not scaled about the origin as the sphere's: the teapot and a model are
    // not star-shaped about their centre (the handle, the spout).
    const double lift = (double(kOverlayLift) - 1) * radius;
    auto lifted = [&](std::size_t v) { return mesh.positions[v] + lift * mesh.vertexNormals[v]; };
    lines.reserve(2 * edges.size());
    double edgeLengths = 0;
    for (const std::uint64_t e : edges) {
        const auto a = std::size_t(e >> 32), b = std::size_t(e & 0xffffffffu);
        segment(lines, lifted(a), lifted(b), kEdgeColor);
        edgeLengths += glm::length(mesh.positions[a] - mesh.positions[b]);
    }
    if (overlay != Overlay::Normals || edges.empty()) return lines;
    // A little longer than an edge of the level shown, but never a hair nor a spike; in world space as long
    // on every side of a stretched object (the cube root of |det M| is its mean scale).
    const double meanEdge = edgeLengths / double(edges.size());
    const double length = std::clamp(0.7 * meanEdge * shown.edgesPerNormal, 0.05 * radius, 0.35 * radius);
    const NormalTips tip{glm::inverse(worldFromObject),
                         normalViewFromObject(glm::dmat4(worldFromObject), rule),
                         length * std::cbrt(std::abs(glm::determinant(worldFromObject)))};
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (!shown.faces[f]) continue;
        const glm::uvec3 t = mesh.triangles[f];
        const glm::dvec3 centroid = (mesh.positions[t.x] + mesh.positions[t.y] + mesh.positions[t.z]) / 3.0;
        segment(lines, centroid, tip(centroid, mesh.faceNormals[f]), kFaceNormalColor);
    }
    // A copy of an earlier vertex (a patch border, a cusp's collapsed row) with its normal would draw the
    // same line again; at a crease the normals differ and each shows once.
    std::unordered_map<std::uint32_t, std::vector<glm::dvec3>> normalsDrawnAt;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        if (!shown.vertices[v]) continue;
        std::vector<glm::dvec3>& drawn = normalsDrawnAt[first[v]];
        const glm::dvec3 n = mesh.vertexNormals[v];
        if (std::any_of(drawn.begin(), drawn.end(),
                        [&](const glm::dvec3& d) { return glm::dot(d, n) > 1 - 1e-9; }))
            continue;
        drawn.push_back(n);
        const glm::dvec3 from = lifted(v);
        segment(lines, from, tip(from, mesh.vertexNormals[v]), kVertexNormalColor);
    }
    return lines;
}

} // namespace

std::vector<LineVertex> teapotOverlayLines(const TeapotMesh& mesh, Overlay overlay,
                                           const glm::dmat3& worldFromObject, NormalMatrixRule rule) {
    NormalsChoice shown;
    if (overlay == Overlay::Normals) {
        // A vertex's and a triangle's place on its patch's grid, from patchUv's (patch, u, v).
        const int n = 1 << mesh.level;
        const int stride = 1 << (mesh.level - std::min(mesh.level, kTeapotNormalsOverlayLevel));
        auto gridIndex = [n](double t) { return int(std::lround(t * n)); };
        shown.edgesPerNormal = stride;
        shown.vertices.resize(mesh.positions.size());
        for (std::size_t v = 0; v < mesh.positions.size(); ++v)
            shown.vertices[v] =
                gridIndex(mesh.patchUv[v].y) % stride == 0 && gridIndex(mesh.patchUv[v].z) % stride == 0;
        // A coarse quad's triangles (I, J)(I, J+1)(I+1, J+1) and (I, J)(I+1, J+1)(I+1, J) have their
        // centroids at (I + 1/3, J + 2/3) and (I + 2/3, J + 1/3): the fine quad there and its triangle of the
        // same half stand for them (a triangle's first corner is its quad's (i, j), its second (i, j + 1) in
        // the first half) — unless the coarse triangle has two equal corners (the lid's top, the bottom's
        // centre), which the coarse level drops (DESIGN §1 "The teapot").
        const int third = stride / 3, twoThirds = 2 * stride / 3;
        const int coarseLevelN = n / stride; // whole: both are powers of two, stride <= n
        const double coarseN = coarseLevelN;
        auto coarseDropped = [&](const glm::dvec3& patchUv, int coarseI, int coarseJ, bool firstHalf) {
            const TeapotPatch& patch = teapotPatches()[std::size_t(std::lround(patchUv.x))];
            auto at = [&](int di, int dj) {
                return evaluatePatch(patch, (coarseI + di) / coarseN, (coarseJ + dj) / coarseN).position;
            };
            const glm::dvec3 a = at(0, 0), b = firstHalf ? at(0, 1) : at(1, 1),
                             c = firstHalf ? at(1, 1) : at(1, 0);
            // The build's rule: within 1e-12 in the data's units, 1.575 of the object's.
            auto equal = [](const glm::dvec3& p, const glm::dvec3& q) {
                return glm::distance(p, q) <= 1e-12 / 1.575;
            };
            return equal(a, b) || equal(b, c) || equal(a, c);
        };
        shown.faces.resize(mesh.triangles.size());
        for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
            const glm::dvec3 &a = mesh.patchUv[mesh.triangles[f].x], &b = mesh.patchUv[mesh.triangles[f].y];
            const int i = gridIndex(a.y), j = gridIndex(a.z);
            const bool firstHalf = gridIndex(b.y) == i;
            const bool standIn = firstHalf ? i % stride == third && j % stride == twoThirds
                                           : i % stride == twoThirds && j % stride == third;
            shown.faces[f] = standIn && (stride == 1 || !coarseDropped(a, i / stride, j / stride, firstHalf));
        }
    }
    return meshLines(mesh, overlay, worldFromObject, rule, shown);
}

std::vector<LineVertex> modelOverlayLines(const TriangleMesh& mesh, Overlay overlay,
                                          const glm::dmat3& worldFromObject, NormalMatrixRule rule) {
    NormalsChoice shown;
    if (overlay == Overlay::Normals) {
        auto strideOf = [](std::size_t count) {
            return std::max<std::size_t>(1, (count + kModelNormalsShown - 1) / kModelNormalsShown);
        };
        const std::size_t faceStride = strideOf(mesh.triangles.size()),
                          vertexStride = strideOf(mesh.positions.size());
        // A face in faceStride stands for that many faces: about √faceStride edges across.
        shown.edgesPerNormal = std::sqrt(double(faceStride));
        shown.faces.resize(mesh.triangles.size());
        for (std::size_t f = 0; f < mesh.triangles.size(); f += faceStride) shown.faces[f] = true;
        shown.vertices.resize(mesh.positions.size());
        for (std::size_t v = 0; v < mesh.positions.size(); v += vertexStride) shown.vertices[v] = true;
    }
    return meshLines(mesh, overlay, worldFromObject, rule, shown);
}

} // namespace shadelab
