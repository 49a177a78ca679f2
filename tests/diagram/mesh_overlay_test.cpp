// The overlay of the teapot and of a model (shadelab/diagram/mesh_overlay.h) on the CPU: every edge once
// by position, whatever vertices the mesh splits; the normals thinned so that they read at any level, the
// teapot's analytic ones, running along the normal matrix of the rule. Expected values come from the
// meshes' definitions (a cube's 18 edges, the teapot's patch grid), not from the code under test.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "shadelab/diagram/mesh_overlay.h"
#include "shadelab/geometry/sphere.h"

namespace shadelab {
namespace {

using Point = std::tuple<long long, long long, long long>;
// A position on a grid of 1e-7 (coarser than the overlay's own), for sets of points and edges.
Point key(const glm::dvec3& p) {
    return {std::llround(p.x * 1e7), std::llround(p.y * 1e7), std::llround(p.z * 1e7)};
}

std::vector<LineVertex> ofColor(const std::vector<LineVertex>& lines, glm::vec3 color) {
    std::vector<LineVertex> out;
    for (std::size_t i = 0; i < lines.size(); i += 2)
        if (lines[i].color == color) out.insert(out.end(), {lines[i], lines[i + 1]});
    return out;
}

// The segments' end pairs (lifted: the overlay draws kOverlayLift − 1 of the radius off the surface; the
// mesh's ends are lifted the same way here to match them, by the first vertex at each place's normal).
std::multiset<std::pair<Point, Point>> endPairs(const std::vector<LineVertex>& edges) {
    std::multiset<std::pair<Point, Point>> pairs;
    for (std::size_t i = 0; i < edges.size(); i += 2) {
        Point a = key(glm::dvec3(edges[i].position)), b = key(glm::dvec3(edges[i + 1].position));
        if (b < a) std::swap(a, b);
        pairs.insert({a, b});
    }
    return pairs;
}

// A cube of side 2 as a file gives it: 24 vertices (each corner three times, one per face's normal), 12
// triangles. Its wireframe is 12 sides and 6 face diagonals.
TriangleMesh splitCube() {
    TriangleMesh cube;
    for (int axis = 0; axis < 3; ++axis)
        for (const double side : {-1.0, 1.0}) {
            glm::dvec3 n(0);
            n[axis] = side;
            const glm::dvec3 u = glm::dvec3(n.y, n.z, n.x), w = glm::cross(n, u);
            const auto base = unsigned(cube.positions.size());
            for (const glm::dvec2 c :
                 {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)}) {
                cube.positions.push_back(n + c.x * u + c.y * w);
                cube.vertexNormals.push_back(n);
            }
            cube.triangles.insert(cube.triangles.end(), {glm::uvec3(base, base + 1, base + 2),
                                                         glm::uvec3(base, base + 2, base + 3)});
            cube.faceNormals.insert(cube.faceNormals.end(), {n, n});
        }
    return cube;
}

TEST(MeshOverlay, ACubesSplitCornersDrawEachEdgeOnce) {
    const TriangleMesh cube = splitCube();
    const auto lines = modelOverlayLines(cube, Overlay::Wireframe);
    EXPECT_EQ(lines.size(), 2u * 18u);
    const auto pairs = endPairs(lines);
    EXPECT_EQ(std::set(pairs.begin(), pairs.end()).size(), pairs.size()) << "an edge drawn twice";
    // Lifted outside the cube (|x|∞ > 1), by 0.3 % of its bounding radius √3 at most.
    for (const LineVertex& v : lines) {
        const double out = std::max({std::abs(v.position.x), std::abs(v.position.y), std::abs(v.position.z)});
        EXPECT_GT(out, 1.0);
        EXPECT_LT(out, 1.0 + 0.0031 * std::sqrt(3.0));
    }
    // Normals: a face normal per triangle, and at each corner its three faces' normals (they differ).
    const auto normals = modelOverlayLines(cube, Overlay::Normals);
    EXPECT_EQ(ofColor(normals, kFaceNormalColor).size(), 2u * 12u);
    EXPECT_EQ(ofColor(normals, kVertexNormalColor).size(), 2u * 24u);
    EXPECT_EQ(ofColor(normals, kEdgeColor).size(), 2u * 18u);
}

// Each patch has its own vertices: the edges along the patches' borders are in two patches' triangles,
// and the lid's and the bottom's collapsed rows are edges of no length.
TEST(MeshOverlay, TeapotWireframeDrawsEveryEdgeOnce) {
    for (const int level : {0, 2, 3}) {
        const TeapotMesh mesh = buildTeapot(level);
        const auto lines = teapotOverlayLines(mesh, Overlay::Wireframe);
        ASSERT_EQ(ofColor(lines, kEdgeColor).size(), lines.size());
        const auto drawn = endPairs(lines);
        const std::set<std::pair<Point, Point>> distinct(drawn.begin(), drawn.end());
        EXPECT_EQ(distinct.size(), drawn.size()) << "level " << level << ": an edge drawn twice";
        // Every triangle's edge of some length is drawn: its ends, lifted along the normal of the first
        // vertex at their place, are a drawn pair.
        std::map<Point, glm::dvec3> normalAt;
        for (std::size_t v = 0; v < mesh.positions.size(); ++v)
            normalAt.try_emplace(key(mesh.positions[v]), mesh.vertexNormals[v]);
        double radius = 0;
        for (const glm::dvec3& p : mesh.positions) radius = std::max(radius, glm::length(p));
        const double lift = (double(kOverlayLift) - 1) * radius;
        std::set<std::pair<Point, Point>> expected;
        for (const glm::uvec3& t : mesh.triangles)
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3 p = mesh.positions[t[k]], q = mesh.positions[t[(k + 1) % 3]];
                if (key(p) == key(q)) continue;
                Point a = key(glm::dvec3(glm::vec3(p + lift * normalAt[key(p)])));
                Point b = key(glm::dvec3(glm::vec3(q + lift * normalAt[key(q)])));
                if (b < a) std::swap(a, b);
                expected.insert({a, b});
            }
        EXPECT_EQ(distinct, expected) << "level " << level;
        // Each patch's grid has 3·4ⁿ + 2·2ⁿ edges; shared borders and collapsed rows make it fewer.
        const std::size_t n = std::size_t(1) << level;
        EXPECT_LT(drawn.size(), 32 * (3 * n * n + 2 * n)) << "level " << level;
    }
}

// A level-`shown` grid point of the teapot: where it is and its analytic normal.
struct GridPoint {
    glm::dvec3 position, normal;
};
std::vector<GridPoint> gridPoints(int shown) {
    std::vector<GridPoint> points;
    for (const TeapotPatch& patch : teapotPatches())
        for (int i = 0; i <= (1 << shown); ++i)
            for (int j = 0; j <= (1 << shown); ++j) {
                const double u = std::ldexp(i, -shown), v = std::ldexp(j, -shown);
                const glm::dvec3 p = evaluatePatch(patch, u, v).position, n = patchNormal(patch, u, v);
                const bool again = std::any_of(points.begin(), points.end(), [&](const GridPoint& g) {
                    return glm::length(g.position - p) < 1e-9 && glm::dot(g.normal, n) > 1 - 1e-9;
                });
                if (!again) points.push_back({p, n});
            }
    return points;
}

double teapotRadius(const TeapotMesh& mesh) {
    double radius = 0;
    for (const glm::dvec3& p : mesh.positions) radius = std::max(radius, glm::length(p));
    return radius;
}

// The vertex normal lines as (surface point, world direction) under M: the start less the lift along the
// line's object-space direction... the lift is along the object normal n, so the surface point is found as
// the grid point nearest the start.
const GridPoint* nearest(const std::vector<GridPoint>& points, const glm::dvec3& from, double lift) {
    const GridPoint* best = nullptr;
    double bestDistance = 1e300;
    for (const GridPoint& g : points) {
        const double d = glm::length(g.position + lift * g.normal - from);
        if (d < bestDistance) bestDistance = d, best = &g;
    }
    return bestDistance < 1e-5 ? best : nullptr;
}

// Past level 2 the teapot shows the normals of level 2's grid: as many lines at every finer level, each
// vertex normal the analytic one at a level-2 grid point (u, v multiples of 1/4), each place and normal
// once; one face normal per level-2 triangle.
TEST(MeshOverlay, TeapotNormalsAreThinnedToLevelTwosGrid) {
    for (const int level : {1, 2, 3, 5}) {
        const TeapotMesh mesh = buildTeapot(level);
        const auto lines = teapotOverlayLines(mesh, Overlay::Normals);
        const auto vertexLines = ofColor(lines, kVertexNormalColor);
        EXPECT_EQ(ofColor(lines, kEdgeColor).size(), teapotOverlayLines(mesh, Overlay::Wireframe).size());
        const int shown = std::min(level, 2);
        EXPECT_EQ(ofColor(lines, kFaceNormalColor).size(), 2 * teapotTriangleCount(shown))
            << "level " << level;
        const std::vector<GridPoint> points = gridPoints(shown);
        ASSERT_EQ(vertexLines.size(), 2 * points.size()) << "level " << level;
        const double lift = (double(kOverlayLift) - 1) * teapotRadius(mesh);
        std::set<const GridPoint*> met;
        for (std::size_t k = 0; k < vertexLines.size(); k += 2) {
            const glm::dvec3 from(vertexLines[k].position), to(vertexLines[k + 1].position);
            const GridPoint* g = nearest(points, from, lift);
            ASSERT_NE(g, nullptr) << "level " << level << ": a vertex normal off level 2's grid";
            met.insert(g);
            EXPECT_NEAR(glm::length(glm::normalize(to - from) - g->normal), 0, 1e-5) << "level " << level;
        }
        EXPECT_EQ(met.size(), points.size()) << "level " << level;
    }
}

// Under an uneven M, the teapot's normals run along (M⁻¹)ᵀ·n or, wrong on purpose, M·n (a diagonal M's
// inverse transpose is 1/s per axis), as long as each other in world space.
TEST(MeshOverlay, TeapotNormalsRunAlongTheNormalMatrixOfTheRule) {
    const glm::dvec3 scale{1.8, 0.45, 0.9};
    const glm::dmat3 m(glm::dvec3(scale.x, 0, 0), glm::dvec3(0, scale.y, 0), glm::dvec3(0, 0, scale.z));
    const TeapotMesh mesh = buildTeapot(2);
    const std::vector<GridPoint> points = gridPoints(2);
    const double lift = (double(kOverlayLift) - 1) * teapotRadius(mesh);
    for (const NormalMatrixRule rule : {NormalMatrixRule::InverseTranspose, NormalMatrixRule::Model}) {
        const auto vertexLines =
            ofColor(teapotOverlayLines(mesh, Overlay::Normals, m, rule), kVertexNormalColor);
        ASSERT_EQ(vertexLines.size(), 2 * points.size());
        std::size_t tilted = 0;
        for (std::size_t k = 0; k < vertexLines.size(); k += 2) {
            const glm::dvec3 from(vertexLines[k].position), to(vertexLines[k + 1].position);
            const GridPoint* g = nearest(points, from, lift);
            ASSERT_NE(g, nullptr);
            const glm::dvec3 expected =
                glm::normalize(rule == NormalMatrixRule::Model ? g->normal * scale : g->normal / scale);
            EXPECT_NEAR(glm::length(glm::normalize(m * (to - from)) - expected), 0, 1e-5);
            tilted += glm::length(expected - glm::normalize(g->normal)) > 0.05;
        }
        EXPECT_GT(tilted, points.size() / 2);
    }
}

// A model finer than kModelNormalsShown shows about that many face and vertex normals, whatever its size.
TEST(MeshOverlay, ModelNormalsAreThinnedToAFewHundred) {
    for (const int level : {3, 6}) {
        const SphereMesh sphere = buildSphere(level, VertexNormals::Exact);
        const TriangleMesh& mesh = sphere; // drawn as a model: no hierarchy known
        const auto lines = modelOverlayLines(mesh, Overlay::Normals);
        const std::size_t faces = ofColor(lines, kFaceNormalColor).size() / 2;
        const std::size_t vertices = ofColor(lines, kVertexNormalColor).size() / 2;
        EXPECT_EQ(faces, std::min(mesh.triangles.size(), std::size_t(kModelNormalsShown))) << level;
        EXPECT_LE(vertices, kModelNormalsShown) << level;
        EXPECT_GE(vertices, std::min(mesh.positions.size(), kModelNormalsShown / 2)) << level;
        // The sphere's edges, shared by its triangles, once each: 1.5 per triangle.
        EXPECT_EQ(ofColor(lines, kEdgeColor).size(), 3 * mesh.triangles.size()) << level;
    }
}

} // namespace
} // namespace shadelab
