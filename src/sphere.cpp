#include "shadelab/sphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <new>
#include <sstream>

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

// The edge-midpoint map: each edge's midpoint vertex is made once and shared by both faces of the edge.
// An open-addressing table (linear probing, power-of-two size, at most half full), cleared per level:
// a level's edges are looked up only while that level is split. std::unordered_map spent half of a
// level-8 build in node allocation (measured by `shadelab bench`, sphere/build against memcpy).
class MidpointCache {
public:
    explicit MidpointCache(std::vector<glm::dvec3>& positions) : positions_(positions) {}

    void startLevel(std::size_t edges) {
        std::size_t capacity = 16;
        shift_ = 60;
        while (capacity < 2 * edges) {
            capacity *= 2;
            --shift_;
        }
        keys_.assign(capacity, kEmpty);
        values_.resize(capacity);
        mask_ = capacity - 1;
    }

    std::uint32_t midpoint(std::uint32_t a, std::uint32_t b) {
        const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b); // never 0: a != b
        for (std::size_t slot = hash(key);; slot = (slot + 1) & mask_) {
            if (keys_[slot] == key) return values_[slot];
            if (keys_[slot] == kEmpty) {
                keys_[slot] = key;
                values_[slot] = std::uint32_t(positions_.size());
                positions_.push_back(glm::normalize((positions_[a] + positions_[b]) * 0.5));
                return values_[slot];
            }
        }
    }

private:
    static constexpr std::uint64_t kEmpty = 0;
    std::size_t hash(std::uint64_t key) const {
        return std::size_t((key * 0x9E3779B97F4A7C15ull) >> shift_); // Fibonacci hashing: the top bits
    }

    std::vector<glm::dvec3>& positions_;
    std::vector<std::uint64_t> keys_;
    std::vector<std::uint32_t> values_;
    std::size_t mask_ = 0;
    int shift_ = 60;
};

glm::dvec3 faceNormal(const std::vector<glm::dvec3>& p, const glm::uvec3& t) {
    return glm::normalize(glm::cross(p[t.y] - p[t.x], p[t.z] - p[t.x]));
}

// Bytes for a level, in double so that absurd levels (asked for by mistake) do not wrap around.
double memoryBytes(int level) {
    level = std::min(level, 1000); // 2·level must not overflow int; 4^1000 is inf in double, which is fine
    const double f = std::ldexp(4.0, 2 * level), v = std::ldexp(2.0, 2 * level) + 2;
    const double cpu = v * 2 * sizeof(glm::dvec3) + f * (sizeof(glm::uvec3) + sizeof(glm::dvec3));
    // The last split's midpoint table: 3F/8 edges in at most 4× as many slots of key + value.
    const double edgeMap = 4 * (3 * f / 8) * (sizeof(std::uint64_t) + sizeof(std::uint32_t));
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

void checkSubdivisionLevel(int level, const char* field) {
    if (level < 0) {
        throw InputError(std::string(field) + ": must be >= 0, got " + std::to_string(level));
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

namespace {
SphereMesh buildSphereUnchecked(int level, VertexNormals normals);
} // namespace

SphereMesh buildSphere(int level, VertexNormals normals) {
    checkSubdivisionLevel(level);
    try {
        return buildSphereUnchecked(level, normals);
    } catch (const std::bad_alloc&) {
        throw RuntimeError("out of memory building the level-" + std::to_string(level) + " sphere (" +
                           std::to_string(sphereTriangleCount(level)) + " triangles), which needs about " +
                           humanBytes(memoryBytes(level)) +
                           "; free memory or raise the limit (ulimit -v), or use a lower --subdivisions");
    }
}

namespace {

SphereMesh buildSphereUnchecked(int level, VertexNormals normals) {
    SphereMesh mesh;
    mesh.level = level;
    mesh.positions.reserve(sphereVertexCount(level));
    mesh.positions.assign(kTetrahedron.begin(), kTetrahedron.end());
    mesh.triangles.assign(kTetrahedronFaces.begin(), kTetrahedronFaces.end());

    std::vector<glm::uvec3> next;
    next.reserve(sphereTriangleCount(level));
    MidpointCache midpoints(mesh.positions);
    for (int n = 0; n < level; ++n) {
        next.clear();
        midpoints.startLevel(mesh.triangles.size() * 3 / 2); // each edge is shared by two triangles
        for (const glm::uvec3& t : mesh.triangles) {
            const std::uint32_t ab = midpoints.midpoint(t.x, t.y);
            const std::uint32_t bc = midpoints.midpoint(t.y, t.z);
            const std::uint32_t ac = midpoints.midpoint(t.x, t.z);
            next.push_back({t.x, ab, ac});
            next.push_back({ab, t.y, bc});
            next.push_back({bc, t.z, ac});
            next.push_back({ab, bc, ac});
        }
        std::swap(mesh.triangles, next);
    }

    mesh.faceNormals.resize(mesh.triangles.size());
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
        mesh.faceNormals[i] = faceNormal(mesh.positions, mesh.triangles[i]);

    if (normals == VertexNormals::Exact) {
        mesh.vertexNormals = mesh.positions; // the unit sphere's normal is its position
    } else {
        // DESIGN §1's definition: the normalized average of the unit normals of the incident faces.
        mesh.vertexNormals.assign(mesh.positions.size(), glm::dvec3(0));
        for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
            for (int k = 0; k < 3; ++k) mesh.vertexNormals[mesh.triangles[i][k]] += mesh.faceNormals[i];
        for (glm::dvec3& n : mesh.vertexNormals) n = glm::normalize(n);
    }
    return mesh;
}

} // namespace

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
