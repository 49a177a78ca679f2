// A ray cast of a triangle mesh in object space, in double, through a bounding volume hierarchy: the
// reference of a mesh read from a file (scene/model.h). It lights the mesh's own interpolated vertex
// normals per pixel (DESIGN §1, "Meshes from files"): with no analytic surface behind the triangles, it can
// measure shading error (flat, Gouraud, toon against Phong lighting of the same triangles) but no geometric
// error — a coarse mesh is its own truth, silhouette and all.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "shadelab/exact/object_ray.h"
#include "shadelab/geometry/triangle_mesh.h"

namespace shadelab {

struct Model;

class MeshBvh {
public:
    // Keeps a reference to `mesh`: it must outlive the hierarchy (meshBvhFor keeps the model alive).
    explicit MeshBvh(const TriangleMesh& mesh);

    // The nearest triangle on `ray`, its normal the vertex normals interpolated at the hit (barycentric,
    // not normalized; the face normal where they cancel); kept in `hit` when nearer than what it holds.
    bool intersect(const ObjectRay& ray, ObjectRayHit& hit, CastCounters* counters = nullptr) const;

    std::size_t nodeCount() const { return nodes_.size(); }

private:
    struct Node {
        glm::dvec3 lo, hi;
        std::uint32_t first = 0; // a leaf's first entry of order_; an inner node's second child
        std::uint32_t count = 0; // triangles of a leaf; 0 for an inner node (its first child follows it)
    };
    std::uint32_t build(std::uint32_t begin, std::uint32_t end, std::vector<glm::dvec3>& centroids);

    const TriangleMesh& mesh_;
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> order_; // triangle indices, each leaf's a contiguous run
};

// The hierarchy of `model`'s mesh, built once per model however many objects and frames ask (the cache
// holds it while the model lives; thread-safe).
std::shared_ptr<const MeshBvh> meshBvhFor(const std::shared_ptr<const Model>& model);

} // namespace shadelab
