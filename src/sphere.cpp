#include "shadelab/sphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <new>
#include <sstream>
#include <system_error>
#include <thread>

#include "shadelab/errors.h"

namespace shadelab {
namespace {

// DESIGN §1: the start tetrahedron and its counter-clockwise faces.
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

// Below this many items a second thread costs more to start than it saves.
constexpr std::size_t kParallelItems = 1 << 15;

// body(begin, end) over [0, n): on two threads for large n (this one takes the second half), else here.
// The page has no threads (Emscripten without pthreads).
template <typename Body> void inParallel(std::size_t n, const Body& body) {
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
    body(0, n);
#else
    if (n < kParallelItems || std::thread::hardware_concurrency() < 2) {
        body(0, n);
        return;
    }
    std::thread first;
    try {
        first = std::thread([&] { body(0, n / 2); });
    } catch (const std::system_error&) { // no thread to be had (a process limit): all of it here
        body(0, n);
        return;
    }
    body(n / 2, n);
    first.join();
#endif
}

// The midpoint vertex of edge `number` (end points a, b), numbered on first use: vertex first + k for the
// k-th midpoint of the level, whose end points are parents[k]. Positions are computed afterwards.
inline std::uint32_t midpointOf(std::vector<std::uint32_t>& midpoint, std::vector<glm::uvec2>& parents,
                                std::uint32_t first, std::uint32_t number, std::uint32_t a, std::uint32_t b) {
    std::uint32_t& m = midpoint[number];
    if (m == kNoVertex) {
        m = first + std::uint32_t(parents.size());
        parents.push_back({a, b});
    }
    return m;
}

glm::dvec3 faceNormal(const std::vector<glm::dvec3>& p, const glm::uvec3& t) {
    return glm::normalize(glm::cross(p[t.y] - p[t.x], p[t.z] - p[t.x]));
}

// Bytes for a level, in double so that absurd levels (asked for by mistake) do not wrap around.
double memoryBytes(int level) {
    level = std::min(level, 1000); // 2·level must not overflow int; 4^1000 is inf in double, which is fine
    const double f = std::ldexp(4.0, 2 * level), v = std::ldexp(2.0, 2 * level) + 2;
    const double cpu = v * 2 * sizeof(glm::dvec3) + f * (sizeof(glm::uvec3) + sizeof(glm::dvec3));
    // The last split's edge numbers: three per triangle of the level before (F/4), and the first end point
    // and the midpoint of each of its 3F/8 edges.
    const double edgeMap = (f / 4) * sizeof(glm::uvec3) + 2 * (3 * f / 8) * sizeof(std::uint32_t);
    const double gpuReady =
        std::max(v * sizeof(SmoothVertex) + f * 3 * sizeof(std::uint32_t), f * 3 * sizeof(FlatVertex));
    return cpu + edgeMap + gpuReady;
}

std::string humanBytes(double bytes) {
    static constexpr const char* kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB", "ZiB", "YiB"};
    int unit = 0;
    while (bytes >= 1024 && unit < 8) {
        bytes /= 1024;
        ++unit;
    }
    std::ostringstream out;
    out << std::fixed;
    out.precision(1);
    out << bytes << " " << kUnits[unit];
    return out.str();
}

} // namespace

std::size_t sphereVertexCount(int level) {
    return 2 * (std::size_t(1) << (2 * level)) + 2;
}
std::size_t sphereTriangleCount(int level) {
    return std::size_t(4) << (2 * level);
}

std::size_t sphereMemoryBytes(int level) {
    const double bytes = memoryBytes(level);
    return bytes < double(std::numeric_limits<std::size_t>::max()) ? std::size_t(bytes)
                                                                   : std::numeric_limits<std::size_t>::max();
}

void checkSubdivisionLevel(int level, std::string_view field) {
    if (level < 0) {
        throw InputError(std::string(field) + ": must be between 0 and " + std::to_string(kMaxSubdivisions) +
                         ", got " + std::to_string(level));
    }
    if (level > kMaxSubdivisions) {
        const std::string triangles =
            level <= 30 ? " (" + std::to_string(sphereTriangleCount(level)) + " triangles)" : "";
        // Beyond about level 40 the figure leaves every unit (and double, past level 500): give its power of
        // two, from the per-triangle cost at a level where it is exact.
        const std::string need =
            level <= 40
                ? humanBytes(memoryBytes(level))
                : "2^" + std::to_string(long(std::floor(2.0 * level + std::log2(memoryBytes(20)) - 40))) +
                      " bytes";
        throw InputError(std::string(field) + ": level " + std::to_string(level) + " would need about " +
                         need + triangles + "; the maximum supported level is " +
                         std::to_string(kMaxSubdivisions) + " (" + humanBytes(memoryBytes(kMaxSubdivisions)) +
                         ")");
    }
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
        throw RuntimeError("out of memory building the level-" + std::to_string(level) + " sphere (" +
                           std::to_string(sphereTriangleCount(level)) + " triangles), which needs about " +
                           humanBytes(memoryBytes(level)) +
                           "; free memory or raise the limit (ulimit -v), or use a lower --subdivisions");
    }
}

namespace {

// One level of the subdivision with its edges numbered, so that each edge's midpoint is found by its
// number instead of by a hash of its end points. Level n has F = 4ⁿ⁺¹ triangles and E = 6·4ⁿ edges; a
// triangle (a, b, c) lists its edges ab, bc, ac. Splitting numbers the edges of level n + 1 without a
// search: edge e's halves are 2e (the one at its first end point, `first[e]`) and 2e + 1, and triangle t's
// three inner edges (ab–ac, ab–bc, bc–ac) are 2E + 3t, 2E + 3t + 1 and 2E + 3t + 2.
struct EdgeLevel {
    std::vector<glm::uvec3> edges;    // per triangle: its edges ab, bc, ac
    std::vector<std::uint32_t> first; // per edge: the end point its half 2e starts from
};

void tetrahedronEdges(EdgeLevel& level) {
    level.edges.clear();
    level.first.clear();
    // (a, b) → edge number, for the six edges of the four start faces.
    std::vector<std::pair<glm::uvec2, std::uint32_t>> seen;
    auto edge = [&](std::uint32_t a, std::uint32_t b) {
        for (const auto& [ends, number] : seen)
            if ((ends.x == a && ends.y == b) || (ends.x == b && ends.y == a)) return number;
        seen.push_back({{a, b}, std::uint32_t(seen.size())});
        level.first.push_back(a);
        return seen.back().second;
    };
    for (const glm::uvec3& t : kTetrahedronFaces)
        level.edges.push_back({edge(t.x, t.y), edge(t.y, t.z), edge(t.x, t.z)});
}

} // namespace

struct SphereBuilder::Scratch {
    EdgeLevel edges, nextEdges;
    std::vector<glm::uvec3> next; // the triangles of the level being made (swapped with the mesh's)
    std::vector<std::uint32_t> midpoint;
    std::vector<glm::uvec2> parents; // per midpoint of the level: its edge's end points
};

// Every array is cleared and refilled in place: memory kept from an earlier build is reused, and the
// triangle arrays get their final capacity up front instead of growing level by level.
void SphereBuilder::buildInto(int level, VertexNormals normals) {
    SphereMesh& mesh = mesh_;
    EdgeLevel& edges = scratch_->edges;
    EdgeLevel& nextEdges = scratch_->nextEdges;
    std::vector<glm::uvec3>& next = scratch_->next;
    std::vector<std::uint32_t>& midpoint = scratch_->midpoint;
    std::vector<glm::uvec2>& parents = scratch_->parents;
    mesh.level = level;
    mesh.positions.clear();
    mesh.positions.reserve(sphereVertexCount(level));
    mesh.positions.assign(kTetrahedron.begin(), kTetrahedron.end());
    mesh.triangles.reserve(sphereTriangleCount(level));
    mesh.triangles.assign(kTetrahedronFaces.begin(), kTetrahedronFaces.end());
    next.reserve(sphereTriangleCount(level));
    tetrahedronEdges(edges);
    for (int n = 0; n < level; ++n) {
        const bool last = n + 1 == level; // the last split needs no edge numbers for a level after it
        const std::size_t edgeCount = edges.first.size(), triangleCount = mesh.triangles.size();
        // Midpoints are numbered in the order the triangles first reach their edges (ab, bc, ac), which is
        // the order the seed's edge-midpoint map made them in: the same vertices, bit for bit, in the same
        // order.
        midpoint.assign(edgeCount, kNoVertex);
        parents.clear();
        parents.reserve(edgeCount);
        const auto first = std::uint32_t(mesh.positions.size());
        next.resize(4 * triangleCount);
        if (!last) {
            nextEdges.edges.resize(4 * triangleCount);
            nextEdges.first.resize(2 * edgeCount + 3 * triangleCount);
        }
        for (std::size_t i = 0; i < triangleCount; ++i) {
            const glm::uvec3 t = mesh.triangles[i], e = edges.edges[i];
            const std::uint32_t ab = midpointOf(midpoint, parents, first, e.x, t.x, t.y);
            const std::uint32_t bc = midpointOf(midpoint, parents, first, e.y, t.y, t.z);
            const std::uint32_t ac = midpointOf(midpoint, parents, first, e.z, t.x, t.z);
            glm::uvec3* children = &next[4 * i];
            children[0] = {t.x, ab, ac};
            children[1] = {ab, t.y, bc};
            children[2] = {bc, t.z, ac};
            children[3] = {ab, bc, ac};
            if (last) continue;
            // The half of edge `number` that ends at vertex v, and the three inner edges.
            auto half = [&](std::uint32_t number, std::uint32_t v) {
                return 2 * number + (edges.first[number] == v ? 0 : 1);
            };
            const std::uint32_t inner = std::uint32_t(2 * edgeCount + 3 * i);
            const std::uint32_t abac = inner, abbc = inner + 1, bcac = inner + 2;
            glm::uvec3* childEdges = &nextEdges.edges[4 * i];
            childEdges[0] = {half(e.x, t.x), abac, half(e.z, t.x)};
            childEdges[1] = {half(e.x, t.y), half(e.y, t.y), abbc};
            childEdges[2] = {half(e.y, t.z), half(e.z, t.z), bcac};
            childEdges[3] = {abbc, bcac, abac};
            nextEdges.first[abac] = ab;
            nextEdges.first[abbc] = ab;
            nextEdges.first[bcac] = bc;
        }
        // normalize((a + b)/2) for every midpoint of the level; its end points are older vertices.
        mesh.positions.resize(first + parents.size());
        inParallel(parents.size(), [&](std::size_t begin, std::size_t end) {
            for (std::size_t k = begin; k < end; ++k)
                mesh.positions[first + k] =
                    glm::normalize((mesh.positions[parents[k].x] + mesh.positions[parents[k].y]) * 0.5);
        });
        if (!last) {
            // Half 2e starts at edge e's first end point, half 2e + 1 at its midpoint.
            for (std::size_t number = 0; number < edgeCount; ++number) {
                nextEdges.first[2 * number] = edges.first[number];
                nextEdges.first[2 * number + 1] = midpoint[number];
            }
            std::swap(edges, nextEdges);
        }
        std::swap(mesh.triangles, next);
    }

    const std::size_t faces = mesh.triangles.size(), vertices = mesh.positions.size();
    mesh.faceNormals.resize(faces);
    inParallel(faces, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
            mesh.faceNormals[i] = faceNormal(mesh.positions, mesh.triangles[i]);
    });
    if (normals == VertexNormals::Exact) {
        mesh.vertexNormals.assign(mesh.positions.begin(), mesh.positions.end()); // the unit sphere's normal
        return;
    }
    // DESIGN §1's definition: the normalized average of the unit normals of the incident faces. Each part
    // owns a range of vertices and adds their faces' normals in triangle order, as one pass over the
    // triangles does: the same sums, bit for bit, whatever the number of parts.
    mesh.vertexNormals.resize(vertices);
    inParallel(vertices, [&](std::size_t begin, std::size_t end) {
        std::fill(mesh.vertexNormals.begin() + std::ptrdiff_t(begin),
                  mesh.vertexNormals.begin() + std::ptrdiff_t(end), glm::dvec3(0));
        for (std::size_t i = 0; i < faces; ++i)
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = mesh.triangles[i][k];
                if (v >= begin && v < end) mesh.vertexNormals[v] += mesh.faceNormals[i];
            }
        for (std::size_t v = begin; v < end; ++v)
            mesh.vertexNormals[v] = glm::normalize(mesh.vertexNormals[v]);
    });
}

std::vector<SmoothVertex> smoothVertices(const SphereMesh& mesh) {
    std::vector<SmoothVertex> out(mesh.positions.size());
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = {glm::vec3(mesh.positions[i]), glm::vec3(mesh.vertexNormals[i])};
    return out;
}

std::vector<std::uint32_t> smoothIndices(const SphereMesh& mesh) {
    std::vector<std::uint32_t> out;
    out.reserve(mesh.triangles.size() * 3);
    for (const glm::uvec3& t : mesh.triangles) out.insert(out.end(), {t.x, t.y, t.z});
    return out;
}

std::vector<FlatVertex> flatVertices(const SphereMesh& mesh) {
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
