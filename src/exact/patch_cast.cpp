// The exact teapot (DESIGN §1, "The teapot"): rays against Newell's Bézier patches in double.
//
// Method. Each patch is cut by de Casteljau subdivision at u, v = ½ into a quadtree of sub-patches, each
// with its own control net: by the convex-hull property a sub-patch lies inside the box of its net, so a
// ray that misses a box misses the whole sub-patch, and the boxes of a level cover the patch. A ray walks
// the trees front to back, skipping boxes it misses or meets beyond the nearest hit so far. In a leaf's box
// it solves F(u, v, t) = P(u, v) − (o + t·d) = 0 by Newton's iteration from the leaf's centre: on a leaf
// 1/32 of the patch wide the surface is nearly flat and the centre lies in its root's basin, so Newton
// converges in a few steps. A root counts when |F| ≤ 1e-10 (object units: the teapot is 2 high), u, v lie
// in [0, 1] within 1e-9 and t lies in the clip range; the nearest one wins. When the start does not lead
// to a root inside the leaf — a ray grazing the silhouette (the Jacobian nearly singular, two roots close
// together), a ray near a cusp — the leaf's net is split again, up to 2⁻⁶ of the leaf, and Newton restarts
// from each sub-box the ray meets, at the last level from the corners too: a ray that meets the surface
// has its root in a box it meets, and a start ever closer to it. At the cusps (the u = 0 rows of the lid's
// knob and of the bottom collapse to a point, ∂P/∂v = 0 there) the 3×3 Jacobian is singular: the step is
// then a damped least-squares one (Levenberg–Marquardt), which still moves u towards the cusp, and
// patchNormal gives ±y there. The hit's normal is patchNormal's (analytic); the teapot is open, so the
// caller turns it towards the viewer on a back face (DESIGN §3).
#include "shadelab/exact/patch_cast.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "shadelab/geometry/teapot.h"

namespace shadelab {
namespace {

constexpr int kTreeDepth = 5;    // 32 × 32 leaves per patch: 43,680 boxes in all
constexpr int kExtraDepth = 6;   // the leaf split again, on demand, down to 1/2048 of the patch
constexpr int kNewtonSteps = 24; // Newton converges in 3–6; the rest is for the linear rate at a graze
constexpr double kConverged = 1e-13, kAccepted = 1e-10; // |F| in object units
constexpr double kDomainSlack = 1e-9;                   // u, v in [0, 1] within this
constexpr double kPatchBoxPad =
    1e-12; // object units: the boxes' rounding, so a ray along a face still meets it

struct Box {
    glm::dvec3 lo, hi;
};

Box boxOf(const TeapotPatch& net) {
    Box box{net[0], net[0]};
    for (const glm::dvec3& p : net) box.lo = glm::min(box.lo, p), box.hi = glm::max(box.hi, p);
    box.lo -= kPatchBoxPad, box.hi += kPatchBoxPad;
    return box;
}

// One de Casteljau split at τ of the cubic p0..p3 (stride apart in `net`) into [0, τ] and [τ, 1].
void splitCubic(const TeapotPatch& net, int first, int stride, double tau, TeapotPatch& low,
                TeapotPatch& high) {
    const glm::dvec3 p0 = net[first], p1 = net[first + stride], p2 = net[first + 2 * stride],
                     p3 = net[first + 3 * stride];
    const glm::dvec3 a = glm::mix(p0, p1, tau), b = glm::mix(p1, p2, tau), c = glm::mix(p2, p3, tau);
    const glm::dvec3 d = glm::mix(a, b, tau), e = glm::mix(b, c, tau), f = glm::mix(d, e, tau);
    low[first] = p0, low[first + stride] = a, low[first + 2 * stride] = d, low[first + 3 * stride] = f;
    high[first] = f, high[first + stride] = e, high[first + 2 * stride] = c, high[first + 3 * stride] = p3;
}

// The net split across u (the rows i of P[4i + j]) or across v (the columns j) at τ.
void splitNet(const TeapotPatch& net, bool acrossU, double tau, TeapotPatch& low, TeapotPatch& high) {
    for (int k = 0; k < 4; ++k)
        acrossU ? splitCubic(net, k, 4, tau, low, high) : splitCubic(net, 4 * k, 1, tau, low, high);
}

// The four quarters of a net, (u low, v low), (u low, v high), (u high, v low), (u high, v high).
std::array<TeapotPatch, 4> quarters(const TeapotPatch& net) {
    TeapotPatch uLow, uHigh;
    splitNet(net, true, 0.5, uLow, uHigh);
    std::array<TeapotPatch, 4> q;
    splitNet(uLow, false, 0.5, q[0], q[1]);
    splitNet(uHigh, false, 0.5, q[2], q[3]);
    return q;
}

// Patch p's quadtree, level l's node (iu, iv) at (4ˡ − 1)/3 + iu·2ˡ + iv.
struct PatchTree {
    std::vector<Box> boxes;
};

std::size_t nodeIndex(int level, int iu, int iv) {
    return ((std::size_t(1) << (2 * level)) - 1) / 3 + (std::size_t(iu) << level) + std::size_t(iv);
}

void fillTree(PatchTree& tree, const TeapotPatch& net, int level, int iu, int iv) {
    tree.boxes[nodeIndex(level, iu, iv)] = boxOf(net);
    if (level == kTreeDepth) return;
    const std::array<TeapotPatch, 4> q = quarters(net);
    for (int k = 0; k < 4; ++k) fillTree(tree, q[std::size_t(k)], level + 1, 2 * iu + k / 2, 2 * iv + k % 2);
}

const std::array<PatchTree, kTeapotPatchCount>& patchTrees() {
    static const std::array<PatchTree, kTeapotPatchCount> trees = [] {
        std::array<PatchTree, kTeapotPatchCount> t;
        for (int p = 0; p < kTeapotPatchCount; ++p) {
            t[std::size_t(p)].boxes.resize(nodeIndex(kTreeDepth + 1, 0, 0));
            fillTree(t[std::size_t(p)], teapotPatches()[std::size_t(p)], 0, 0, 0);
        }
        return t;
    }();
    return trees;
}

// The ray's entry into `box` within [ray.tMin, tMax], if it meets it there.
bool meets(const Box& box, const ObjectRay& ray, double tMax, double& tEntry, CastCounters* counters) {
    if (counters) ++counters->boxTests;
    double t0 = ray.tMin, t1 = tMax;
    for (int k = 0; k < 3; ++k) {
        const double o = ray.originObject[k], d = ray.directionObject[k];
        if (d == 0) {
            if (o < box.lo[k] || o > box.hi[k]) return false;
            continue;
        }
        double a = (box.lo[k] - o) / d, b = (box.hi[k] - o) / d;
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a), t1 = std::min(t1, b);
        if (!(t0 <= t1)) return false;
    }
    tEntry = t0;
    return true;
}

struct Root {
    double u, v, t;
};

// Sorts the first n (≤ 4) items by `before`: insertion, as std::sort on so few would do (gcc 12 warns of
// array bounds inside std::sort on a 4-element array).
template <typename T, typename Before> void sortFew(std::array<T, 4>& items, int n, Before before) {
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && before(items[std::size_t(j)], items[std::size_t(j - 1)]); --j)
            std::swap(items[std::size_t(j)], items[std::size_t(j - 1)]);
}

// Newton's iteration on F(u, v, t) = P(u, v) − (o + t·d) from (u, v), t starting at the ray's point nearest
// P(u, v). Succeeds when |F| falls to kAccepted, whatever (u, v) it ends at.
bool newton(const TeapotPatch& patch, const ObjectRay& ray, double u, double v, Root& root) {
    const glm::dvec3 &o = ray.originObject, &d = ray.directionObject;
    PatchPoint p = evaluatePatch(patch, u, v);
    double t = glm::dot(p.position - o, d);
    glm::dvec3 f = p.position - (o + t * d);
    for (int step = 0; step < kNewtonSteps && !(glm::length(f) <= kConverged); ++step) {
        const glm::dmat3 jacobian(p.du, p.dv, -d);
        const double det = glm::determinant(jacobian);
        glm::dvec3 delta;
        if (std::abs(det) > 1e-12 * glm::length(p.du) * glm::length(p.dv)) {
            delta = glm::inverse(jacobian) * -f;
        } else { // singular at a cusp (∂P/∂v = 0) or a graze: a damped least-squares step
            const glm::dmat3 jt = glm::transpose(jacobian);
            glm::dmat3 normal = jt * jacobian;
            const double damping = 1e-12 * (normal[0][0] + normal[1][1] + normal[2][2]) + 1e-300;
            for (int k = 0; k < 3; ++k) normal[k][k] += damping;
            delta = glm::inverse(normal) * (jt * -f);
        }
        u += delta.x, v += delta.y, t += delta.z;
        // Far outside [0, 1] the polynomial is no longer the patch: the start was in no root's basin.
        if (!(u > -1 && u < 2 && v > -1 && v < 2) || !std::isfinite(t)) return false;
        p = evaluatePatch(patch, u, v);
        f = p.position - (o + t * d);
    }
    if (!(glm::length(f) <= kAccepted)) return false;
    root = {u, v, t};
    return true;
}

struct Search {
    const ObjectRay& ray;
    ObjectRayHit& hit;
    CastCounters* counters;
    bool found = false;

    // Keeps `root` of patch `patch` when it is on the patch, in the clip range and nearer than the hit.
    void consider(const TeapotPatch& patch, const Root& root) {
        const double lo = -kDomainSlack, hi = 1 + kDomainSlack;
        if (!(root.u >= lo && root.u <= hi && root.v >= lo && root.v <= hi)) return;
        if (!(root.t >= ray.tMin && root.t <= ray.tMax && root.t < hit.t)) return;
        const double u = std::clamp(root.u, 0.0, 1.0), v = std::clamp(root.v, 0.0, 1.0);
        const glm::dvec3 normal = patchNormal(patch, u, v);
        hit = ObjectRayHit{root.t, evaluatePatch(patch, u, v).position, normal,
                           glm::dot(normal, ray.directionObject) > 0};
        found = true;
    }

    // Newton from (u, v); true when it found a root of the region [u0, u0 + size] × [v0, v0 + size] in
    // front of the near plane (the region is then settled).
    bool solveFrom(const TeapotPatch& patch, double u, double v, double u0, double v0, double size) {
        if (counters) ++counters->surfaceTests;
        Root root;
        if (!newton(patch, ray, u, v, root)) return false;
        consider(patch, root);
        const double m = kDomainSlack;
        return root.u >= u0 - m && root.u <= u0 + size + m && root.v >= v0 - m && root.v <= v0 + size + m &&
               root.t >= ray.tMin;
    }

    // A region of `patch` whose box the ray meets, with its control net.
    void solveRegion(const TeapotPatch& patch, const TeapotPatch& net, double u0, double v0, double size,
                     int depthLeft) {
        if (!solveFrom(patch, u0 + size / 2, v0 + size / 2, u0, v0, size))
            refine(patch, net, u0, v0, size, depthLeft);
    }

    // A region whose centre start failed: its corners at the last level, else its quarters the ray meets.
    void refine(const TeapotPatch& patch, const TeapotPatch& net, double u0, double v0, double size,
                int depthLeft) {
        if (depthLeft == 0) {
            for (int k = 0; k < 4; ++k)
                if (solveFrom(patch, u0 + size * double(k >> 1), v0 + size * double(k & 1), u0, v0, size))
                    return;
            return;
        }
        const std::array<TeapotPatch, 4> q = quarters(net);
        std::array<std::pair<double, int>, 4> order;
        int n = 0;
        for (int k = 0; k < 4; ++k) {
            double entry;
            if (meets(boxOf(q[std::size_t(k)]), ray, std::min(ray.tMax, hit.t), entry, counters))
                order[std::size_t(n++)] = {entry, k};
        }
        sortFew(order, n, [](const auto& a, const auto& b) { return a.first < b.first; });
        const double half = size / 2;
        for (int i = 0; i < n; ++i) {
            const auto [entry, k] = order[std::size_t(i)];
            if (entry > hit.t) break;
            solveRegion(patch, q[std::size_t(k)], u0 + half * double(k >> 1), v0 + half * double(k & 1), half,
                        depthLeft - 1);
        }
    }

    // The leaf's own net, cut out of the patch (only for the rays whose Newton start fails there).
    static TeapotPatch subNet(const TeapotPatch& patch, double u0, double v0, double size) {
        TeapotPatch low, high, scratch, net = patch;
        for (const bool acrossU : {true, false}) {
            const double a = acrossU ? u0 : v0, b = a + size;
            splitNet(net, acrossU, b, low, scratch);                             // [0, b]
            if (a > 0) splitNet(low, acrossU, a / b, scratch, high), low = high; // [a, b]
            net = low;
        }
        return net;
    }

    void solveLeaf(const TeapotPatch& patch, int iu, int iv) {
        const double size = 1.0 / (1 << kTreeDepth), u0 = iu * size, v0 = iv * size;
        if (!solveFrom(patch, u0 + size / 2, v0 + size / 2, u0, v0, size))
            refine(patch, subNet(patch, u0, v0, size), u0, v0, size, kExtraDepth);
    }
};

struct Node {
    double entry;
    int patch, level, iu, iv;
};

// Every control point lies within this distance of the object origin, so by the convex-hull property the
// whole teapot does (≈ 2.32 object units).
double controlPointRadius() {
    static const double radius = [] {
        double r = 0;
        for (const TeapotPatch& patch : teapotPatches())
            for (const glm::dvec3& p : patch) r = std::max(r, glm::length(p));
        return r * (1 + 1e-12);
    }();
    return radius;
}

} // namespace

bool intersectTeapot(const ObjectRay& ray, ObjectRayHit& hit, CastCounters* counters) {
    // The teapot lies in the ball of its control points: most rays of a picture end here.
    const double r = controlPointRadius();
    const glm::dvec3 nearest =
        ray.originObject + glm::dot(-ray.originObject, ray.directionObject) * ray.directionObject;
    if (!(glm::dot(nearest, nearest) <= r * r)) return false;

    const auto& trees = patchTrees();
    Search search{ray, hit, counters};
    thread_local std::vector<Node> stack; // the reference's threads each reuse theirs, ray after ray
    stack.clear();
    for (int p = 0; p < kTeapotPatchCount; ++p) {
        double entry;
        if (meets(trees[std::size_t(p)].boxes[0], ray, std::min(ray.tMax, hit.t), entry, counters))
            stack.push_back({entry, p, 0, 0, 0});
    }
    // Farthest first on the stack, so the nearest is taken next.
    std::sort(stack.begin(), stack.end(), [](const Node& a, const Node& b) { return a.entry > b.entry; });
    while (!stack.empty()) {
        const Node node = stack.back();
        stack.pop_back();
        if (node.entry > hit.t) continue;
        const TeapotPatch& patch = teapotPatches()[std::size_t(node.patch)];
        if (node.level == kTreeDepth) {
            search.solveLeaf(patch, node.iu, node.iv);
            continue;
        }
        std::array<Node, 4> children;
        int n = 0;
        for (int k = 0; k < 4; ++k) {
            const int level = node.level + 1, iu = 2 * node.iu + k / 2, iv = 2 * node.iv + k % 2;
            double entry;
            if (meets(trees[std::size_t(node.patch)].boxes[nodeIndex(level, iu, iv)], ray,
                      std::min(ray.tMax, hit.t), entry, counters))
                children[std::size_t(n++)] = {entry, node.patch, level, iu, iv};
        }
        sortFew(children, n, [](const Node& a, const Node& b) { return a.entry > b.entry; });
        stack.insert(stack.end(), children.begin(), children.begin() + n);
    }
    return search.found;
}

} // namespace shadelab
