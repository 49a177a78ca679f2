// The unit sphere of DESIGN §1, as the lecture builds it: start from the tetrahedron; split every triangle
// into four by the midpoints of its edges, pushed out onto the sphere (normalized); repeat n times. Then one
// normal per face, for flat shading, and one per vertex, for smooth shading.
//
// Neighbouring triangles share an edge, and so its midpoint: each midpoint is made once, by the first
// triangle that reaches its edge, and found again by the edge's number (the edge table below) rather than
// by searching for its two end points.
#include "shadelab/geometry/sphere.h"

#include <array>
#include <cmath>
#include <new>

namespace shadelab {
namespace {

// DESIGN §1: the start tetrahedron and its counter-clockwise faces (seen from outside).
const double kSqrt2 = std::sqrt(2.0), kSqrt6 = std::sqrt(6.0);
const std::array<glm::dvec3, 4> kTetrahedron = {
    glm::dvec3{0, 0, 1},
    glm::dvec3{0, 2 * kSqrt2 / 3, -1.0 / 3},
    glm::dvec3{-kSqrt6 / 3, -kSqrt2 / 3, -1.0 / 3},
    glm::dvec3{kSqrt6 / 3, -kSqrt2 / 3, -1.0 / 3},
};
constexpr std::array<glm::uvec3, 4> kTetrahedronFaces = {glm::uvec3{3, 2, 1}, glm::uvec3{0, 1, 2},
                                                         glm::uvec3{0, 3, 1}, glm::uvec3{0, 2, 3}};

constexpr std::uint32_t kNoVertex = 0xffffffffu;

// The edges of one level, numbered. Level n has F = 4ⁿ⁺¹ triangles and E = 6·4ⁿ edges; triangle t lists the
// numbers of its edges ab, bc, ac. A split numbers the next level's edges without a search: edge e's two
// halves are 2e (the half at its end point first[e]) and 2e + 1, and the three edges inside triangle t
// (ab–ac, ab–bc, bc–ac) are 2E + 3t, 2E + 3t + 1 and 2E + 3t + 2.
struct EdgeTable {
    std::vector<glm::uvec3> ofTriangle; // per triangle: its edges ab, bc, ac
    std::vector<std::uint32_t> first;   // per edge: the end point its half 2e starts from
};

void tetrahedronEdges(EdgeTable& table) {
    table.ofTriangle.clear();
    table.first.clear();
    std::vector<glm::uvec2> ends; // per edge numbered so far: its end points
    auto edge = [&](std::uint32_t a, std::uint32_t b) {
        for (std::uint32_t e = 0; e < ends.size(); ++e)
            if (ends[e] == glm::uvec2(a, b) || ends[e] == glm::uvec2(b, a)) return e;
        ends.emplace_back(a, b);
        table.first.push_back(a);
        return std::uint32_t(ends.size() - 1);
    };
    for (const glm::uvec3& t : kTetrahedronFaces)
        table.ofTriangle.push_back({edge(t.x, t.y), edge(t.y, t.z), edge(t.x, t.z)});
}

// What a split works in, kept by a builder between builds.
struct SplitState {
    std::vector<glm::uvec3> children; // the split's output; then swapped with the mesh's triangles
    EdgeTable edges, nextEdges;
    std::vector<std::uint32_t> midpointOf; // per edge of the level being split: its midpoint, or kNoVertex
};

// One split of every triangle (a, b, c) into (a, ab, ac), (ab, b, bc), (bc, c, ac), (ab, bc, ac), in order.
// The midpoint of an edge is normalize((a + b) / 2), appended to the positions the first time a triangle
// reaches the edge (triangles in order, each's edges ab, bc, ac). The next level's edge table is numbered
// too, unless this is the last split.
void split(std::vector<glm::dvec3>& positions, const std::vector<glm::uvec3>& triangles, SplitState& s,
           bool numberNextEdges) {
    const std::size_t edgeCount = s.edges.first.size();
    s.midpointOf.assign(edgeCount, kNoVertex);
    auto midpoint = [&](std::uint32_t edge, std::uint32_t a, std::uint32_t b) {
        if (s.midpointOf[edge] == kNoVertex) {
            s.midpointOf[edge] = std::uint32_t(positions.size());
            const glm::dvec3 m = glm::normalize((positions[a] + positions[b]) * 0.5);
            positions.push_back(m);
        }
        return s.midpointOf[edge];
    };
    s.children.resize(4 * triangles.size());
    if (numberNextEdges) {
        s.nextEdges.ofTriangle.resize(4 * triangles.size());
        s.nextEdges.first.resize(2 * edgeCount + 3 * triangles.size());
    }
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const glm::uvec3 t = triangles[i], e = s.edges.ofTriangle[i];
        const std::uint32_t ab = midpoint(e.x, t.x, t.y), bc = midpoint(e.y, t.y, t.z),
                            ac = midpoint(e.z, t.x, t.z);
        glm::uvec3* four = &s.children[4 * i];
        four[0] = {t.x, ab, ac};
        four[1] = {ab, t.y, bc};
        four[2] = {bc, t.z, ac};
        four[3] = {ab, bc, ac};
        if (!numberNextEdges) continue;
        // The half of edge `number` that ends at vertex v, and the three edges inside the triangle.
        auto half = [&](std::uint32_t number, std::uint32_t v) {
            return 2 * number + (s.edges.first[number] == v ? 0 : 1);
        };
        const auto abac = std::uint32_t(2 * edgeCount + 3 * i), abbc = abac + 1, bcac = abac + 2;
        glm::uvec3* childEdges = &s.nextEdges.ofTriangle[4 * i];
        childEdges[0] = {half(e.x, t.x), abac, half(e.z, t.x)};
        childEdges[1] = {half(e.x, t.y), half(e.y, t.y), abbc};
        childEdges[2] = {half(e.y, t.z), half(e.z, t.z), bcac};
        childEdges[3] = {abbc, bcac, abac};
        s.nextEdges.first[abac] = ab;
        s.nextEdges.first[abbc] = ab;
        s.nextEdges.first[bcac] = bc;
    }
    if (!numberNextEdges) return;
    // Half 2e starts at edge e's first end point, half 2e + 1 at its midpoint.
    for (std::size_t number = 0; number < edgeCount; ++number) {
        s.nextEdges.first[2 * number] = s.edges.first[number];
        s.nextEdges.first[2 * number + 1] = s.midpointOf[number];
    }
    std::swap(s.edges, s.nextEdges);
}

// Face normals: the unit normal of each counter-clockwise triangle. Vertex normals: the sphere's own
// (the position) when exact; averaged, the normalized sum of the unit normals of the faces around the
// vertex, added in triangle order (DESIGN §1).
void computeNormals(SphereMesh& mesh, VertexNormals kind) {
    const std::vector<glm::dvec3>& p = mesh.positions;
    mesh.faceNormals.resize(mesh.triangles.size());
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3 t = mesh.triangles[i];
        mesh.faceNormals[i] = glm::normalize(glm::cross(p[t.y] - p[t.x], p[t.z] - p[t.x]));
    }
    if (kind == VertexNormals::Exact) {
        mesh.vertexNormals.assign(p.begin(), p.end());
        return;
    }
    mesh.vertexNormals.assign(p.size(), glm::dvec3(0));
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) mesh.vertexNormals[mesh.triangles[i][k]] += mesh.faceNormals[i];
    for (glm::dvec3& n : mesh.vertexNormals) n = glm::normalize(n);
}

} // namespace

struct SphereBuilder::Scratch : SplitState {};

std::size_t sphereVertexCount(int level) {
    return 2 * (std::size_t(1) << (2 * level)) + 2;
}
std::size_t sphereTriangleCount(int level) {
    return std::size_t(4) << (2 * level);
}

SphereMesh buildSphere(int level, VertexNormals normals) {
    SphereBuilder builder;
    builder.build(level, normals);
    return builder.take();
}

SphereBuilder::SphereBuilder() = default;
SphereBuilder::~SphereBuilder() = default;
SphereBuilder::SphereBuilder(SphereBuilder&&) noexcept = default;
SphereBuilder& SphereBuilder::operator=(SphereBuilder&&) noexcept = default;

const SphereMesh& SphereBuilder::build(int level, VertexNormals normals) {
    checkSubdivisionLevel(level);
    if (!scratch_) scratch_ = std::make_unique<Scratch>();
    try {
        buildInto(level, normals);
        return mesh_;
    } catch (const std::bad_alloc&) {
        detail::failSphereBuild(level);
    }
}

void SphereBuilder::buildInto(int level, VertexNormals normals) {
    mesh_.level = level;
    mesh_.positions.clear();
    mesh_.positions.reserve(sphereVertexCount(level)); // so that no split moves them
    mesh_.positions.assign(kTetrahedron.begin(), kTetrahedron.end());
    mesh_.triangles.assign(kTetrahedronFaces.begin(), kTetrahedronFaces.end());
    tetrahedronEdges(scratch_->edges);
    for (int n = 0; n < level; ++n) {
        split(mesh_.positions, mesh_.triangles, *scratch_, n + 1 < level);
        std::swap(mesh_.triangles, scratch_->children);
    }
    computeNormals(mesh_, normals);
}

} // namespace shadelab
