// Newell's teapot against DESIGN §1 ("The teapot"), without a GL context: the data's parts and symmetry,
// the patches' evaluation and derivatives, the outward normals and the cusp rule, the level-n mesh's counts,
// split, winding and vertices, the level limits, and the bound teapotMeshError gives.
#include "shadelab/geometry/teapot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "shadelab/errors.h"

namespace shadelab {
namespace {

const TeapotPatch& patch(int p) {
    return teapotPatches()[std::size_t(p)];
}

// The parts, in the data's order.
enum class Part { Rim, Body, Handle, Spout, Lid, Bottom };
Part partOf(int p) {
    return p < 4    ? Part::Rim
           : p < 12 ? Part::Body
           : p < 16 ? Part::Handle
           : p < 20 ? Part::Spout
           : p < 28 ? Part::Lid
                    : Part::Bottom;
}

// Every level's mesh built once (level 5 is the largest the tests read).
const TeapotMesh& mesh(int level) {
    static std::array<TeapotMesh, 6> meshes;
    static std::array<bool, 6> built{};
    if (!built[std::size_t(level)]) {
        meshes[std::size_t(level)] = buildTeapot(level);
        built[std::size_t(level)] = true;
    }
    return meshes[std::size_t(level)];
}

// Object y of a height in the data (z up, 0 to 3.15).
double objectY(double dataZ) {
    return (dataZ - 1.575) / 1.575;
}

TEST(Teapot, PartsAreInTheDataOrder) {
    for (int p = 0; p < kTeapotPatchCount; ++p)
        for (const glm::dvec3& point : patch(p)) {
            SCOPED_TRACE("patch " + std::to_string(p));
            switch (partOf(p)) {
            case Part::Rim: // the lip, between 2.4 and 2.53125 high
                EXPECT_GE(point.y, objectY(2.4) - 1e-12);
                EXPECT_LE(point.y, objectY(2.53125) + 1e-12);
                break;
            case Part::Body: // from the rim down to the bottom's edge
                EXPECT_LE(point.y, objectY(2.4) + 1e-12);
                EXPECT_GE(point.y, objectY(0.15) - 1e-12);
                break;
            case Part::Handle:
                EXPECT_LT(point.x, -1.4 / 1.575);
                break; // behind (−x)
            case Part::Spout:
                EXPECT_GT(point.x, 1.6 / 1.575);
                break; // in front (+x)
            case Part::Lid:
                EXPECT_GE(point.y, objectY(2.4) - 1e-12);
                break;
            case Part::Bottom:
                EXPECT_LE(point.y, objectY(0.15) + 1e-12);
                break;
            }
        }
}

TEST(Teapot, CornersInterpolateTheCornerControlPoints) {
    for (int p = 0; p < kTeapotPatchCount; ++p) {
        SCOPED_TRACE("patch " + std::to_string(p));
        // P[4i + j] with i the u row: (u, v) = (1, 0) is P[12], (0, 1) is P[3].
        EXPECT_EQ(evaluatePatch(patch(p), 0, 0).position, patch(p)[0]);
        EXPECT_EQ(evaluatePatch(patch(p), 0, 1).position, patch(p)[3]);
        EXPECT_EQ(evaluatePatch(patch(p), 1, 0).position, patch(p)[12]);
        EXPECT_EQ(evaluatePatch(patch(p), 1, 1).position, patch(p)[15]);
    }
}

// The teapot's plane of symmetry holds the handle and the spout: the data's y = 0, object z = 0.
TEST(Teapot, MirrorSymmetricInObjectZ) {
    const TeapotMesh& m = mesh(3);
    auto key = [](const glm::dvec3& p) {
        return std::make_tuple(std::llround(p.x * 1e9), std::llround(p.y * 1e9), std::llround(p.z * 1e9));
    };
    std::set<std::tuple<long long, long long, long long>> positions;
    for (const glm::dvec3& p : m.positions) positions.insert(key(p));
    for (const glm::dvec3& p : m.positions)
        ASSERT_TRUE(positions.count(key({p.x, p.y, -p.z}))) << p.x << " " << p.y << " " << p.z;
}

TEST(Teapot, HeightTwoCentredOnZero) {
    double low = 1e9, high = -1e9;
    for (const TeapotPatch& controls : teapotPatches())
        for (const glm::dvec3& point : controls) {
            low = std::min(low, point.y);
            high = std::max(high, point.y);
        }
    EXPECT_EQ(low, -1.0);
    EXPECT_EQ(high, 1.0);
    // The surface reaches both ends of its hull: the bottom's centre and the lid's top.
    low = 1e9, high = -1e9;
    for (const glm::dvec3& p : mesh(2).positions) {
        low = std::min(low, p.y);
        high = std::max(high, p.y);
    }
    EXPECT_EQ(low, -1.0);
    EXPECT_EQ(high, 1.0);
}

TEST(Teapot, DerivativesMatchFiniteDifferences) {
    const double h = 1e-6;
    for (int p = 0; p < kTeapotPatchCount; ++p)
        for (double u : {0.1, 0.37, 0.5, 0.83})
            for (double v : {0.05, 0.4, 0.61, 0.9}) {
                const PatchPoint at = evaluatePatch(patch(p), u, v);
                const glm::dvec3 du = (evaluatePatch(patch(p), u + h, v).position -
                                       evaluatePatch(patch(p), u - h, v).position) /
                                      (2 * h);
                const glm::dvec3 dv = (evaluatePatch(patch(p), u, v + h).position -
                                       evaluatePatch(patch(p), u, v - h).position) /
                                      (2 * h);
                EXPECT_LT(glm::length(at.du - du), 1e-7) << "patch " << p << " u " << u << " v " << v;
                EXPECT_LT(glm::length(at.dv - dv), 1e-7) << "patch " << p << " u " << u << " v " << v;
            }
}

// Outward, part by part where the direction is plain, then carried over every edge two patches share.
TEST(Teapot, NormalsAreUnitAndOutward) {
    const int n = 32;
    for (int p = 0; p < kTeapotPatchCount; ++p)
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) {
                const double u = double(i) / n, v = double(j) / n;
                const glm::dvec3 normal = patchNormal(patch(p), u, v);
                const glm::dvec3 position = evaluatePatch(patch(p), u, v).position;
                SCOPED_TRACE("patch " + std::to_string(p) + " u " + std::to_string(u) + " v " +
                             std::to_string(v));
                ASSERT_NEAR(glm::length(normal), 1.0, 1e-12);
                if (partOf(p) == Part::Body) {
                    EXPECT_GT(glm::dot(normal, glm::dvec3(position.x, 0, position.z)), 0);
                }
                // The handle's and the spout's tubes, away from their centre line (the mid-point of the two
                // points of the cross-section in the plane of symmetry); not at the spout's rolled lip.
                if (partOf(p) == Part::Handle || p == 16 || p == 17) {
                    const glm::dvec3 centre =
                        (evaluatePatch(patch(p), u, 0).position + evaluatePatch(patch(p), u, 1).position) /
                        2.0;
                    EXPECT_GT(glm::dot(normal, position - centre), 0);
                }
            }
    for (int p = 24; p < 28; ++p) EXPECT_GT(patchNormal(patch(p), 0.5, 0.5).y, 0.9);  // the lid's top
    for (int p = 28; p < 32; ++p) EXPECT_LT(patchNormal(patch(p), 0.5, 0.5).y, -0.9); // the bottom

    // Edges shared by two patches: the same normal from both sides (never flipped).
    auto uvOn = [](int edge, double t) {
        return edge == 0   ? glm::dvec2(0, t)
               : edge == 1 ? glm::dvec2(1, t)
               : edge == 2 ? glm::dvec2(t, 0)
                           : glm::dvec2(t, 1);
    };
    auto point = [&](int p, glm::dvec2 uv) { return evaluatePatch(patch(p), uv.x, uv.y).position; };
    int shared = 0;
    for (int a = 0; a < kTeapotPatchCount; ++a)
        for (int b = a + 1; b < kTeapotPatchCount; ++b)
            for (int ea = 0; ea < 4; ++ea)
                for (int eb = 0; eb < 4; ++eb)
                    for (bool reversed : {false, true}) {
                        auto along = [&](double t) { return uvOn(eb, reversed ? 1 - t : t); };
                        bool same = glm::length(point(a, uvOn(ea, 0)) - point(a, uvOn(ea, 1))) > 1e-9;
                        for (int k = 0; k <= 8 && same; ++k)
                            same =
                                glm::length(point(a, uvOn(ea, k / 8.0)) - point(b, along(k / 8.0))) < 1e-12;
                        if (!same) continue;
                        ++shared;
                        for (int k = 0; k <= 32; ++k) {
                            const glm::dvec2 uvA = uvOn(ea, k / 32.0), uvB = along(k / 32.0);
                            EXPECT_GT(glm::dot(patchNormal(patch(a), uvA.x, uvA.y),
                                               patchNormal(patch(b), uvB.x, uvB.y)),
                                      0.99)
                                << "patches " << a << " and " << b;
                        }
                    }
    // Rim–body, body–body, body–bottom, the lid's, the handle's and the spout's seams.
    EXPECT_EQ(shared, 52);
}

// At the lid's top and the bottom's centre ∂P/∂v vanishes: the normal is ±y, the limit of its neighbours'.
TEST(Teapot, CuspNormals) {
    for (int p = 20; p < 24; ++p)
        for (double v : {0.0, 0.3, 1.0}) {
            EXPECT_EQ(patchNormal(patch(p), 0, v), glm::dvec3(0, 1, 0));
            EXPECT_GT(patchNormal(patch(p), 1e-4, v).y, 0.999);
        }
    for (int p = 28; p < 32; ++p)
        for (double v : {0.0, 0.3, 1.0}) {
            EXPECT_EQ(patchNormal(patch(p), 0, v), glm::dvec3(0, -1, 0));
            EXPECT_LT(patchNormal(patch(p), 1e-4, v).y, -0.999);
        }
}

TEST(Teapot, CountsPerLevel) {
    EXPECT_EQ(teapotTriangleCount(2), 992u);
    EXPECT_EQ(teapotTriangleCount(3), 4032u);
    for (int level = 0; level <= 4; ++level) {
        const TeapotMesh& m = mesh(level);
        const std::size_t side = (std::size_t(1) << level) + 1;
        EXPECT_EQ(m.level, level);
        EXPECT_EQ(m.positions.size(), teapotVertexCount(level));
        EXPECT_EQ(m.positions.size(), 32 * side * side);
        EXPECT_EQ(m.vertexNormals.size(), m.positions.size());
        EXPECT_EQ(m.patchUv.size(), m.positions.size());
        EXPECT_EQ(m.triangles.size(), teapotTriangleCount(level));
        EXPECT_EQ(m.faceNormals.size(), m.triangles.size());
    }
    EXPECT_EQ(mesh(2).triangles.size(), 992u);
    EXPECT_EQ(mesh(3).triangles.size(), 4032u);
}

TEST(Teapot, VerticesLieOnTheSurface) {
    for (int level : {0, 3, 5}) {
        const TeapotMesh& m = mesh(level);
        const double h = std::ldexp(1.0, -level);
        for (std::size_t k = 0; k < m.positions.size(); ++k) {
            const glm::dvec3 uv = m.patchUv[k];
            // Patch by patch, u the row, on the grid.
            const std::size_t side = (std::size_t(1) << level) + 1, inPatch = k % (side * side);
            ASSERT_EQ(uv.x, double(k / (side * side)));
            ASSERT_EQ(uv.y, double(inPatch / side) * h);
            ASSERT_EQ(uv.z, double(inPatch % side) * h);
            const TeapotPatch& controls = patch(int(uv.x));
            ASSERT_LT(glm::length(m.positions[k] - evaluatePatch(controls, uv.y, uv.z).position), 1e-12);
            ASSERT_LT(glm::length(m.vertexNormals[k] - patchNormal(controls, uv.y, uv.z)), 1e-12);
        }
    }
}

// Each quad splits along (i, j)–(i+1, j+1): every triangle has that diagonal, corners in the order
// (i,j)(i,j+1)(i+1,j+1) or (i,j)(i+1,j+1)(i+1,j).
TEST(Teapot, QuadsSplitAlongTheMainDiagonal) {
    for (int level : {0, 2, 4}) {
        const TeapotMesh& m = mesh(level);
        const double h = std::ldexp(1.0, -level);
        for (const glm::uvec3& t : m.triangles) {
            const glm::dvec3 a = m.patchUv[t.x], b = m.patchUv[t.y], c = m.patchUv[t.z];
            ASSERT_TRUE(a.x == b.x && b.x == c.x);
            const glm::dvec2 ab = glm::dvec2(b.y - a.y, b.z - a.z), ac = glm::dvec2(c.y - a.y, c.z - a.z);
            const bool first = ab == glm::dvec2(0, h) && ac == glm::dvec2(h, h);
            const bool second = ab == glm::dvec2(h, h) && ac == glm::dvec2(h, 0);
            ASSERT_TRUE(first || second) << "level " << level;
        }
    }
}

// Counter-clockwise seen from outside: the winding's normal agrees with the analytic one at the centroid.
TEST(Teapot, TrianglesAreCounterClockwiseFromOutside) {
    int flat = 0;
    for (int level = 0; level <= 5; ++level) {
        const TeapotMesh& m = mesh(level);
        for (std::size_t k = 0; k < m.triangles.size(); ++k) {
            const glm::uvec3 t = m.triangles[k];
            const glm::dvec3 ab = m.positions[t.y] - m.positions[t.x],
                             ac = m.positions[t.z] - m.positions[t.x];
            const glm::dvec3 uv = (m.patchUv[t.x] + m.patchUv[t.y] + m.patchUv[t.z]) / 3.0;
            const glm::dvec3 analytic = patchNormal(patch(int(m.patchUv[t.x].x)), uv.y, uv.z);
            ASSERT_NEAR(glm::length(m.faceNormals[k]), 1.0, 1e-12) << "level " << level << " triangle " << k;
            if (glm::length(glm::cross(ab, ac)) <= 1e-12 * glm::length(ab) * glm::length(ac)) {
                // Three corners in a line: only the spout's tip at level 0.
                EXPECT_EQ(level, 0);
                EXPECT_EQ(m.faceNormals[k], analytic);
                ++flat;
                continue;
            }
            const glm::dvec3 winding = glm::normalize(glm::cross(ab, ac));
            ASSERT_LT(glm::length(m.faceNormals[k] - winding), 1e-12);
            ASSERT_GT(glm::dot(winding, analytic), 0.4) << "level " << level << " triangle " << k;
        }
    }
    EXPECT_EQ(flat, 4); // two per tip patch
}

TEST(Teapot, LevelsOutOfRangeAreRefused) {
    for (int level : {-1, 9, 40}) {
        try {
            buildTeapot(level);
            ADD_FAILURE() << "level " << level << " accepted";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()),
                      "subdivisions: must be between 0 and 8, got " + std::to_string(level));
        }
    }
    EXPECT_THROW(checkTeapotLevel(9, "objects[1].subdivisions"), InputError);
    EXPECT_NO_THROW(checkTeapotLevel(0));
    EXPECT_NO_THROW(checkTeapotLevel(8));
    try {
        checkTeapotLevel(-2, "objects[1].subdivisions");
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "objects[1].subdivisions: must be between 0 and 8, got -2");
    }
}

// The largest gap between a mesh point and the surface point at the same (u, v), sampled on each triangle.
double measuredError(int level) {
    const TeapotMesh& m = mesh(level);
    const int samples = 6;
    double worst = 0;
    for (const glm::uvec3& t : m.triangles)
        for (int a = 0; a <= samples; ++a)
            for (int b = 0; a + b <= samples; ++b) {
                const double la = double(a) / samples, lb = double(b) / samples, lc = 1 - la - lb;
                const glm::dvec3 onMesh =
                    la * m.positions[t.x] + lb * m.positions[t.y] + lc * m.positions[t.z];
                const glm::dvec3 uv = la * m.patchUv[t.x] + lb * m.patchUv[t.y] + lc * m.patchUv[t.z];
                const glm::dvec3 onSurface = evaluatePatch(patch(int(m.patchUv[t.x].x)), uv.y, uv.z).position;
                worst = std::max(worst, glm::length(onMesh - onSurface));
            }
    return worst;
}

TEST(Teapot, MeshErrorBoundsTheMeasuredErrorAndFallsFourfold) {
    double previous = 0;
    for (int level = 1; level <= 5; ++level) {
        const double measured = measuredError(level), bound = teapotMeshError(level);
        SCOPED_TRACE("level " + std::to_string(level) + ": measured " + std::to_string(measured) +
                     ", bound " + std::to_string(bound));
        EXPECT_LE(measured, bound);
        // A bound, not a wild one: within 20× of the largest gap found.
        EXPECT_GT(measured, bound / 20);
        EXPECT_DOUBLE_EQ(teapotMeshError(level - 1) / bound, 4.0);
        if (level >= 3) {
            EXPECT_GT(previous / measured, 3.5);
            EXPECT_LT(previous / measured, 4.5);
        }
        previous = measured;
    }
}

} // namespace
} // namespace shadelab
