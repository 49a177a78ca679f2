// Newell's teapot (DESIGN §1, "The teapot"): the patches in object coordinates, their exact evaluation, and
// the level-n mesh, each patch on a uniform grid in (u, v) with its own vertices and analytic normals.
#include "shadelab/geometry/teapot.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "geometry/teapot_data.h"
#include "shadelab/errors.h"

namespace shadelab {
namespace {

// The data's height is 3.15: halved, it centres the teapot on y = 0 and scales it to height 2.
constexpr double kDataHalfHeight = 1.575;
// Two corners of a triangle closer than this, in the data's units, are one point (DESIGN §1).
constexpr double kSamePointInData = 1e-12;
// A point is on the axis of the lid's and the bottom's cusps when its object x and z are both within this:
// the position test (rather than |∂P/∂v × ∂P/∂u| against |∂P/∂u||∂P/∂v|) because the cusp is defined by
// where it is, the data's x = y = 0, and a collapsed row evaluates there exactly (B₀(0) = 1, the rest 0).
constexpr double kOnAxis = 1e-12;

// A triangle whose edges' cross product is this small against their lengths has no direction of its own.
constexpr double kFlat = 1e-12;

glm::dvec3 toObject(const glm::dvec3& data) {
    return glm::dvec3(data.x, data.z - kDataHalfHeight, -data.y) / kDataHalfHeight;
}

std::array<TeapotPatch, kTeapotPatchCount> convertPatches() {
    std::array<TeapotPatch, kTeapotPatchCount> patches{};
    for (int p = 0; p < kTeapotPatchCount; ++p)
        for (int k = 0; k < 16; ++k)
            patches[p][k] = toObject(detail::kTeapotDataPoints[detail::kTeapotPatchIndices[p][k]]);
    return patches;
}

// The cubic Bernstein polynomials B₀..B₃ at t and their derivatives.
struct Bases {
    std::array<double, 4> b, d;
};

Bases bernstein(double t) {
    const double s = 1 - t;
    return {{s * s * s, 3 * t * s * s, 3 * t * t * s, t * t * t},
            {-3 * s * s, 3 * s * s - 6 * t * s, 6 * t * s - 3 * t * t, 3 * t * t}};
}

// A row of the patch at u: the four points Σᵢ Bᵢ(u) P[4i + j] and their u-derivatives, j = 0..3. The
// column's bases then finish P(u, v), ∂P/∂u and ∂P/∂v (evaluatePatch and the grid share this order).
struct Row {
    std::array<glm::dvec3, 4> point, du;
};

Row rowAt(const TeapotPatch& patch, const Bases& u) {
    Row row{};
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            row.point[j] += u.b[i] * patch[4 * i + j];
            row.du[j] += u.d[i] * patch[4 * i + j];
        }
    return row;
}

PatchPoint pointOnRow(const Row& row, const Bases& v) {
    PatchPoint p{};
    for (int j = 0; j < 4; ++j) {
        p.position += v.b[j] * row.point[j];
        p.du += v.b[j] * row.du[j];
        p.dv += v.d[j] * row.point[j];
    }
    return p;
}

glm::dvec3 normalAt(const PatchPoint& p) {
    if (std::abs(p.position.x) <= kOnAxis && std::abs(p.position.z) <= kOnAxis)
        return {0, p.position.y > 0 ? 1.0 : -1.0, 0};
    return glm::normalize(glm::cross(p.dv, p.du));
}

// Compared squared: a build tests three pairs per triangle.
bool samePoint(const glm::dvec3& a, const glm::dvec3& b) {
    constexpr double kSameInObject = kSamePointInData / kDataHalfHeight;
    return glm::dot(a - b, a - b) <= kSameInObject * kSameInObject;
}

} // namespace

const std::array<TeapotPatch, kTeapotPatchCount>& teapotPatches() {
    static const std::array<TeapotPatch, kTeapotPatchCount> patches = convertPatches();
    return patches;
}

PatchPoint evaluatePatch(const TeapotPatch& patch, double u, double v) {
    return pointOnRow(rowAt(patch, bernstein(u)), bernstein(v));
}

glm::dvec3 patchNormal(const TeapotPatch& patch, double u, double v) {
    return normalAt(evaluatePatch(patch, u, v));
}

std::size_t teapotVertexCount(int level) {
    const std::size_t side = (std::size_t(1) << level) + 1;
    return kTeapotPatchCount * side * side;
}

// Eight patch edges are one point (the u = 0 rows of the lid's four knob patches and of the four bottom
// patches): along each, the first triangle of each of its 2ⁿ quads has two equal corners and is dropped.
std::size_t teapotTriangleCount(int level) {
    const std::size_t n = std::size_t(1) << level;
    return std::size_t(kTeapotPatchCount) * 2 * n * n - 8 * n;
}

void checkTeapotLevel(int level, std::string_view field) {
    if (level < 0 || level > kMaxTeapotLevel)
        throw InputError(std::string(field) + ": must be between 0 and " + std::to_string(kMaxTeapotLevel) +
                         ", got " + std::to_string(level));
}

TeapotMesh buildTeapot(int level) {
    checkTeapotLevel(level);
    const int n = 1 << level, side = n + 1;
    TeapotMesh mesh;
    mesh.level = level;
    mesh.positions.reserve(teapotVertexCount(level));
    mesh.vertexNormals.reserve(teapotVertexCount(level));
    mesh.patchUv.reserve(teapotVertexCount(level));
    mesh.triangles.reserve(teapotTriangleCount(level));
    mesh.faceNormals.reserve(teapotTriangleCount(level));
    // The grid's parameters are the same for every patch and in u and v: their bases once per build.
    std::vector<Bases> bases(side);
    for (int i = 0; i <= n; ++i) bases[i] = bernstein(double(i) / n);

    for (int p = 0; p < kTeapotPatchCount; ++p) {
        const TeapotPatch& patch = teapotPatches()[p];
        for (int i = 0; i <= n; ++i) {
            const Row row = rowAt(patch, bases[i]);
            for (int j = 0; j <= n; ++j) {
                const PatchPoint point = pointOnRow(row, bases[j]);
                mesh.positions.push_back(point.position);
                mesh.vertexNormals.push_back(normalAt(point));
                mesh.patchUv.emplace_back(p, double(i) / n, double(j) / n);
            }
        }
        // Quad (i, j), (i, j+1), (i+1, j+1), (i+1, j), split along (i, j)–(i+1, j+1): each triangle's
        // winding follows ∂P/∂v then ∂P/∂u, so its face normal points as ∂P/∂v × ∂P/∂u does, outward.
        const auto base = std::uint32_t(p * side * side);
        auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
            const glm::dvec3 &pa = mesh.positions[a], &pb = mesh.positions[b], &pc = mesh.positions[c];
            if (samePoint(pa, pb) || samePoint(pb, pc) || samePoint(pa, pc)) return;
            mesh.triangles.emplace_back(a, b, c);
            const glm::dvec3 ab = pb - pa, ac = pc - pa, across = glm::cross(ab, ac);
            const double across2 = glm::dot(across, across);
            if (across2 > kFlat * kFlat * glm::dot(ab, ab) * glm::dot(ac, ac)) {
                mesh.faceNormals.push_back(across / std::sqrt(across2));
            } else { // three corners in a line (the spout's tip at level 0): the normal at its centre
                const glm::dvec3 uv = (mesh.patchUv[a] + mesh.patchUv[b] + mesh.patchUv[c]) / 3.0;
                mesh.faceNormals.push_back(patchNormal(patch, uv.y, uv.z));
            }
        };
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const std::uint32_t a = base + std::uint32_t(i * side + j), b = a + 1,
                                    c = a + std::uint32_t(side) + 1, d = a + std::uint32_t(side);
                add(a, b, c);
                add(a, c, d);
            }
    }
    return mesh;
}

// DESIGN §1, "The teapot": on a grid cell of side h the mesh is the linear interpolation of P at the cell's
// triangle corners, so a mesh point is within (h²/8)·(max|P_uu| + 2·max|P_uv| + max|P_vv|) of the surface
// point at the same (u, v); over a patch |P_uu| ≤ 6·max|Δ²ᵤP|, |P_uv| ≤ 9·max|ΔᵤΔᵥP|, |P_vv| ≤ 6·max|Δ²ᵥP|
// (P's derivatives are Bernstein combinations of its control points' differences).
double teapotMeshError(int level) {
    static const double atLevel0 = [] {
        double worst = 0;
        for (const TeapotPatch& patch : teapotPatches()) {
            auto at = [&](int i, int j) { return patch[4 * i + j]; };
            double uu = 0, uv = 0, vv = 0;
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) {
                    if (i < 2) uu = std::max(uu, glm::length(at(i + 2, j) - 2.0 * at(i + 1, j) + at(i, j)));
                    if (j < 2) vv = std::max(vv, glm::length(at(i, j + 2) - 2.0 * at(i, j + 1) + at(i, j)));
                    if (i < 3 && j < 3)
                        uv = std::max(uv,
                                      glm::length(at(i + 1, j + 1) - at(i + 1, j) - at(i, j + 1) + at(i, j)));
                }
            worst = std::max(worst, (6 * uu + 2 * 9 * uv + 6 * vv) / 8);
        }
        return worst;
    }();
    return std::ldexp(atLevel0, -2 * level);
}

} // namespace shadelab
