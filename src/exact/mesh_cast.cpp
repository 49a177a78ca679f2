// A mesh's reference ray cast (mesh_cast.h): a bounding volume hierarchy over the triangles, split at the
// median centroid along the longest axis (a balanced tree, built in O(n log n) once per model), and
// Möller–Trumbore's ray-triangle test in double.
//
// Shared edges leave no pinholes: a triangle is accepted with barycentric coordinates down to −1e-9 (and
// their sum up to 1 + 1e-9), so neighbours overlap by 1e-9 of their size along the edge they share — far
// more than double's rounding of the coordinates (≈ 1e-15 of the size for a ray not grazing the triangle's
// plane) and far less than any pixel. A ray through an edge meets both triangles at the same t; either is
// the hit. The boxes are padded by 1e-9 of their extent for the same reason.
#include "shadelab/exact/mesh_cast.h"

#include <algorithm>
#include <mutex>
#include <numeric>

#include "shadelab/scene/model.h"

namespace shadelab {
namespace {

constexpr std::uint32_t kLeafTriangles = 4;
constexpr double kBarycentricSlack = 1e-9;
constexpr double kTriangleBoxPad = 1e-9; // of the box's extent

bool meets(const glm::dvec3& lo, const glm::dvec3& hi, const ObjectRay& ray, const glm::dvec3& inverse,
           double tMax, double& tEntry) {
    double t0 = ray.tMin, t1 = tMax;
    for (int k = 0; k < 3; ++k) {
        if (ray.directionObject[k] == 0) {
            if (ray.originObject[k] < lo[k] || ray.originObject[k] > hi[k]) return false;
            continue;
        }
        double a = (lo[k] - ray.originObject[k]) * inverse[k], b = (hi[k] - ray.originObject[k]) * inverse[k];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a), t1 = std::min(t1, b);
        if (!(t0 <= t1)) return false;
    }
    tEntry = t0;
    return true;
}

} // namespace

MeshBvh::MeshBvh(const TriangleMesh& mesh) : mesh_(mesh) {
    const std::size_t n = mesh.triangles.size();
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0u);
    std::vector<glm::dvec3> centroids(n);
    for (std::size_t t = 0; t < n; ++t) {
        const glm::uvec3 tri = mesh.triangles[t];
        centroids[t] = (mesh.positions[tri.x] + mesh.positions[tri.y] + mesh.positions[tri.z]) / 3.0;
    }
    nodes_.reserve(2 * (n / kLeafTriangles + 1));
    if (n > 0) build(0, std::uint32_t(n), centroids);
}

std::uint32_t MeshBvh::build(std::uint32_t begin, std::uint32_t end, std::vector<glm::dvec3>& centroids) {
    const auto index = std::uint32_t(nodes_.size());
    nodes_.emplace_back();
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    glm::dvec3 cLo = lo, cHi = hi;
    for (std::uint32_t i = begin; i < end; ++i) {
        const glm::uvec3 tri = mesh_.triangles[order_[i]];
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3& p = mesh_.positions[tri[k]];
            lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
        cLo = glm::min(cLo, centroids[order_[i]]), cHi = glm::max(cHi, centroids[order_[i]]);
    }
    const glm::dvec3 pad = kTriangleBoxPad * (hi - lo) + 1e-300;
    nodes_[index].lo = lo - pad, nodes_[index].hi = hi + pad;
    const glm::dvec3 extent = cHi - cLo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    if (end - begin <= kLeafTriangles || !(extent[axis] > 0)) {
        nodes_[index].first = begin, nodes_[index].count = end - begin;
        return index;
    }
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(
        order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
        [&](std::uint32_t a, std::uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
    build(begin, middle, centroids); // the first child follows its parent
    const std::uint32_t second = build(middle, end, centroids);
    nodes_[index].first = second;
    return index;
}

bool MeshBvh::intersect(const ObjectRay& ray, ObjectRayHit& hit, CastCounters* counters) const {
    if (nodes_.empty()) return false;
    const glm::dvec3 &o = ray.originObject, &d = ray.directionObject;
    const glm::dvec3 inverse = 1.0 / d; // ±inf where d has a 0 component: meets() tests those apart
    bool found = false;
    std::uint32_t bestTriangle = 0;
    double bestB1 = 0, bestB2 = 0, bestDet = 0;

    std::pair<std::uint32_t, double> stack[64];
    int size = 0;
    double entry;
    if (counters) ++counters->boxTests;
    if (meets(nodes_[0].lo, nodes_[0].hi, ray, inverse, std::min(ray.tMax, hit.t), entry))
        stack[size++] = {0u, entry};
    while (size > 0) {
        const auto [index, nodeEntry] = stack[--size];
        if (nodeEntry > hit.t) continue;
        const Node& node = nodes_[index];
        if (node.count == 0) {
            const std::uint32_t children[2] = {index + 1, node.first};
            std::pair<std::uint32_t, double> met[2];
            int n = 0;
            for (const std::uint32_t child : children) {
                if (counters) ++counters->boxTests;
                if (meets(nodes_[child].lo, nodes_[child].hi, ray, inverse, std::min(ray.tMax, hit.t), entry))
                    met[n++] = {child, entry};
            }
            if (n == 2 && met[0].second < met[1].second) std::swap(met[0], met[1]); // the nearer on top
            for (int i = 0; i < n; ++i) stack[size++] = met[i];
            continue;
        }
        for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
            if (counters) ++counters->surfaceTests;
            const glm::uvec3 tri = mesh_.triangles[order_[i]];
            const glm::dvec3 &a = mesh_.positions[tri.x], &b = mesh_.positions[tri.y],
                             &c = mesh_.positions[tri.z];
            const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
            const double det = glm::dot(e1, p); // = −d·(e1 × e2): > 0 when the ray meets the front
            if (det == 0 || !std::isfinite(det)) continue;
            const glm::dvec3 s = o - a, q = glm::cross(s, e1);
            const double b1 = glm::dot(s, p) / det, b2 = glm::dot(d, q) / det;
            if (!(b1 >= -kBarycentricSlack && b2 >= -kBarycentricSlack && b1 + b2 <= 1 + kBarycentricSlack))
                continue;
            const double t = glm::dot(e2, q) / det;
            if (!(t >= ray.tMin && t <= ray.tMax && t < hit.t)) continue;
            hit.t = t;
            found = true;
            bestTriangle = order_[i], bestB1 = b1, bestB2 = b2, bestDet = det;
        }
    }
    if (!found) return false;

    const glm::uvec3 tri = mesh_.triangles[bestTriangle];
    const glm::dvec3 &a = mesh_.positions[tri.x], &b = mesh_.positions[tri.y], &c = mesh_.positions[tri.z];
    hit.pointObject = (1 - bestB1 - bestB2) * a + bestB1 * b + bestB2 * c;
    const glm::dvec3 face = glm::cross(b - a, c - a);
    glm::dvec3 normal = face;
    if (mesh_.vertexNormals.size() == mesh_.positions.size()) {
        normal = (1 - bestB1 - bestB2) * mesh_.vertexNormals[tri.x] + bestB1 * mesh_.vertexNormals[tri.y] +
                 bestB2 * mesh_.vertexNormals[tri.z];
        if (!(glm::length(normal) > 1e-12)) normal = face; // opposite vertex normals cancel
    }
    hit.normalObject = normal;
    hit.backFace = bestDet < 0; // the triangle's winding, as gl_FrontFacing decides it
    return true;
}

std::shared_ptr<const MeshBvh> meshBvhFor(const std::shared_ptr<const Model>& model) {
    struct Entry {
        std::weak_ptr<const Model> model;
        std::shared_ptr<const MeshBvh> bvh;
    };
    static std::mutex mutex;
    static std::vector<Entry> cache;
    const std::lock_guard lock(mutex);
    // A model no scene holds any more frees its hierarchy; a new model at the same address is not it.
    std::erase_if(cache, [](const Entry& e) { return e.model.expired(); });
    std::shared_ptr<const MeshBvh> bvh;
    for (const Entry& e : cache)
        if (e.model.lock() == model) bvh = e.bvh;
    if (!bvh) {
        bvh = std::make_shared<const MeshBvh>(model->mesh);
        cache.push_back({model, bvh});
    }
    // The hierarchy reads the model's mesh: what is handed out keeps the model alive too.
    auto both =
        std::make_shared<std::pair<std::shared_ptr<const Model>, std::shared_ptr<const MeshBvh>>>(model, bvh);
    return {both, both->second.get()};
}

} // namespace shadelab
