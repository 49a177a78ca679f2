// The unit sphere built by subdividing a tetrahedron (DESIGN §1). Pure CPU data, built in double;
// uploading it is the GL layer's job.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "shadelab/geometry/triangle_mesh.h"

namespace shadelab {

inline constexpr int kMaxSubdivisions = 10;

enum class VertexNormals { Averaged, Exact };
inline constexpr const char* toString(VertexNormals normals) {
    return normals == VertexNormals::Averaged ? "averaged" : "exact";
}

// Shared vertices on the unit sphere; vertex normals of the requested kind.
struct SphereMesh : TriangleMesh {
    int level = 0;
};

// Counts for level n: V = 2·4ⁿ + 2 shared vertices, F = 4ⁿ⁺¹ triangles.
std::size_t sphereVertexCount(int level);
std::size_t sphereTriangleCount(int level);

// Peak bytes buildSphere and the GPU-ready arrays (mesh_layout.h) need for a level (used in the error for
// too-high levels; sphere_limits.cpp).
std::size_t sphereMemoryBytes(int level);

// The one check of a level wherever it comes from: buildSphere, a scene file's "subdivisions", the
// --subdivisions flag (scene_values.h). Throws InputError "<field>: must be between 0 and 10, got -1"; above
// the maximum the message names the memory the level would need.
void checkSubdivisionLevel(int level, std::string_view field = "subdivisions");

SphereMesh buildSphere(int level, VertexNormals normals = VertexNormals::Averaged);

namespace detail {
// A build that ran out of memory: RuntimeError naming the level, its triangles, the memory it needs and
// the ways out (sphere_limits.cpp, which has the estimate).
[[noreturn]] void failSphereBuild(int level);
} // namespace detail

// Builds spheres into arrays it keeps: building again (another level, or the same one in a benchmark)
// writes into memory already mapped instead of asking the kernel for fresh pages. The same mesh as
// buildSphere, bit for bit.
class SphereBuilder {
public:
    SphereBuilder();
    ~SphereBuilder();
    SphereBuilder(SphereBuilder&&) noexcept;
    SphereBuilder& operator=(SphereBuilder&&) noexcept;
    // Throws as buildSphere does; the reference stays valid until the next build or take.
    const SphereMesh& build(int level, VertexNormals normals = VertexNormals::Averaged);
    SphereMesh take() { return std::move(mesh_); }

private:
    struct Scratch;
    void buildInto(int level, VertexNormals normals);
    SphereMesh mesh_;
    std::unique_ptr<Scratch> scratch_;
};

} // namespace shadelab
