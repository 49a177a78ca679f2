#include "shadelab/reference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <thread>

#include "shadelab/errors.h"
#include "shadelab/lighting.h"

namespace shadelab {
namespace {

// One object, prepared for casting view-space rays at it.
struct ObjectInView {
    glm::dmat3 objectFromView3;      // inverse of viewFromObject's upper 3×3
    glm::dvec3 originView;           // viewFromObject's translation: the centre in view space
    glm::dmat3 normalViewFromObject; // normalMatrix(viewFromObject), rescaled to O(1)
};

double maxAbsEntry(const glm::dmat3& m) {
    double k = 0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) k = std::max(k, std::abs(m[c][r]));
    return k;
}

// viewFromObject's 3×3 is (rotation)·diag(radius·scale). Its determinant is radius³·sx·sy·sz, which a
// generic inverse or the cofactor matrix under/overflows for extreme radii (radius 1e-9 gives cofactors
// of 1e-18, which safeNormalize treats as zero). Dividing by the largest entry first keeps both O(1): the
// inverse is then rescaled back, and the normal matrix only needs its direction (it is renormalized).
ObjectInView prepare(const SceneObject& object, const glm::dmat4& viewFromWorld) {
    const glm::dmat4 viewFromObject = viewFromWorld * worldFromObject(object);
    const glm::dmat3 linear(viewFromObject);
    const double k = maxAbsEntry(linear); // > 0: validated radius > 0 and non-zero scale
    const glm::dmat3 unit = linear / k;
    return ObjectInView{glm::inverse(unit) / k, glm::dvec3(viewFromObject[3]),
                        normalMatrix(glm::dmat4(unit))};
}

struct Hit {
    double s = std::numeric_limits<double>::infinity(); // ray parameter: point = origin + s·direction
    int object = -1;
    glm::dvec3 pointObject{0, 0, 1}; // on the unit sphere: also the object-space normal
};

// Intersects the view-space ray origin + s·direction with `object` and keeps the hit in `best` when it lies
// inside the clip volume (view z in [−far, −near]) and is nearer than the hit already there.
void intersect(const ObjectInView& object, int index, const glm::dvec3& originView,
               const glm::dvec3& directionView, double near, double far, Hit& best) {
    const glm::dvec3 o = object.objectFromView3 * (originView - object.originView);
    const glm::dvec3 d = object.objectFromView3 * directionView;
    const double dLength = glm::length(d);
    if (!(dLength > 0) || !std::isfinite(dLength) || !std::isfinite(glm::dot(o, o))) return;
    const glm::dvec3 dUnit = d / dLength;

    // |o + t·dUnit|² = 1 with a = 1: t² + 2b·t + c = 0. The discriminant b² − c loses everything to
    // cancellation when |o| ≫ 1 (a tiny sphere seen from afar), so it is taken as 1 − |o⊥|², the distance of
    // the ray from the centre (Ray Tracing Gems, ch. 7). The roots come from q = −(b + sign(b)·√disc), which
    // never subtracts nearly equal numbers: t = q and t = c/q.
    const double b = glm::dot(o, dUnit);
    const glm::dvec3 perpendicular = o - b * dUnit;
    const double disc = 1 - glm::dot(perpendicular, perpendicular);
    if (!(disc >= 0)) return;
    const double c = glm::dot(o, o) - 1;
    const double root = std::sqrt(disc);
    const double q = -(b + std::copysign(root, b));
    double t0 = q, t1 = q != 0 ? c / q : 0; // q = 0 only for a ray grazing the sphere at t = 0
    if (t0 > t1) std::swap(t0, t1);

    // The hit points themselves are taken from the point of the ray nearest the centre, ∓√disc along it,
    // not from o + t·dUnit, which would lose the normal to the rounding of |o| when |o| ≫ 1.
    for (auto [t, side] : {std::pair{t0, -1.0}, std::pair{t1, 1.0}}) {
        const double s = t / dLength;
        const double zView = originView.z + s * directionView.z;
        // Both projections cast rays towards −z, so the first root inside the volume is the nearer one.
        if (zView <= -near && zView >= -far) {
            if (s < best.s) best = Hit{s, index, perpendicular + side * root * dUnit};
            return;
        }
    }
}

// Exactly one place decides which pixel sees which point: pixel centres, top row first.
struct PixelRays {
    ViewVolume volume;
    bool orthographic;
    int width, height;

    void ray(int i, int j, glm::dvec3& originView, glm::dvec3& directionView) const {
        const double x = volume.left + (volume.right - volume.left) * (i + 0.5) / width;
        const double y = volume.top - (volume.top - volume.bottom) * (j + 0.5) / height;
        if (orthographic) {
            originView = {x, y, 0};
            directionView = {0, 0, -1};
        } else {
            originView = {0, 0, 0};
            directionView = {x, y, -volume.near}; // through (x, y) on the near plane
        }
    }
};

void writePixel(float* pixel, const glm::dvec3& color, float alpha) {
    pixel[0] = float(color.x);
    pixel[1] = float(color.y);
    pixel[2] = float(color.z);
    pixel[3] = alpha;
}

} // namespace

ReferenceImage renderReference(const Scene& scene) {
    validateScene(scene);
    const SceneView view = sceneView(scene);
    // With the far plane at infinity the rasterizer clips nothing behind; neither does the reference.
    const double far = scene.depth == DepthMode::ReversedInfinite ? std::numeric_limits<double>::infinity()
                                                                  : view.volume.far;

    std::vector<ObjectInView> objects;
    objects.reserve(scene.objects.size());
    for (const SceneObject& object : scene.objects) objects.push_back(prepare(object, view.viewFromWorld));
    std::vector<Light> lightsView;
    lightsView.reserve(scene.lights.size());
    for (const Light& light : scene.lights) lightsView.push_back(transformLight(light, view.viewFromWorld));
    const ShadeOptions options{scene.lighting, scene.shading == ShadingMode::Toon, scene.toonBands};
    const PixelRays rays{view.volume, view.orthographic, scene.width, scene.height};
    const glm::dvec3 background = clampColor(scene.background);

    ReferenceImage out{ImageF(scene.width, scene.height),
                       std::vector<int>(std::size_t(scene.width) * std::size_t(scene.height), -1)};

    auto renderRow = [&](int j) {
        for (int i = 0; i < scene.width; ++i) {
            glm::dvec3 originView, directionView;
            rays.ray(i, j, originView, directionView);
            Hit hit;
            for (std::size_t k = 0; k < objects.size(); ++k)
                intersect(objects[k], int(k), originView, directionView, view.volume.near, far, hit);

            float* pixel = out.color.pixel(i, j);
            if (hit.object < 0) {
                writePixel(pixel, background, 0);
                continue;
            }
            const ObjectInView& object = objects[std::size_t(hit.object)];
            const glm::dvec3 positionView = originView + hit.s * directionView;
            // The mesh is seen from outside, so the outward normal is used as is, even where the near plane
            // cuts a sphere open and its inside shows.
            const glm::dvec3 normalView =
                safeNormalize(object.normalViewFromObject * hit.pointObject, glm::dvec3(0, 0, 1));
            // Local viewer (DESIGN §3), the same rule as the GLSL: towards the eye under perspective; under
            // orthographic projection the eye is at infinity, so back along the parallel rays, +z.
            const glm::dvec3 toViewer =
                rays.orthographic ? glm::dvec3(0, 0, 1) : safeNormalize(-positionView, glm::dvec3(0, 0, 1));
            const glm::dvec3 color =
                clampColor(shade(SurfacePoint{positionView, normalView, toViewer},
                                 scene.objects[std::size_t(hit.object)].material, lightsView, options));
            writePixel(pixel, color, 1);
            out.objectId[std::size_t(j) * std::size_t(scene.width) + std::size_t(i)] = hit.object;
        }
    };

    // Rows are dealt out round-robin (cheap load balance: the objects sit mid-image); each thread writes
    // only its own rows, so the result does not depend on the thread count.
    const int threadCount =
        std::clamp(int(std::thread::hardware_concurrency()), 1, std::max(1, scene.height));
    {
        std::vector<std::jthread> threads;
        threads.reserve(std::size_t(threadCount));
        for (int first = 0; first < threadCount; ++first)
            threads.emplace_back([&, first] {
                for (int j = first; j < scene.height; j += threadCount) renderRow(j);
            });
    } // jthreads join here
    return out;
}

std::vector<bool> interiorMask(const std::vector<int>& ids, int width, int height, int radius) {
    if (width < 0 || height < 0 || ids.size() != std::size_t(width) * std::size_t(height))
        throw InputError("interiorMask: " + std::to_string(ids.size()) + " ids for a " +
                         std::to_string(width) + "×" + std::to_string(height) + " image");
    if (radius < 0) throw InputError("interiorMask: radius must be >= 0, got " + std::to_string(radius));
    const auto at = [width](int x, int y) { return std::size_t(y) * std::size_t(width) + std::size_t(x); };

    // Erosion by a (2r+1)² square is separable, done with runs in O(w·h) whatever the radius. Outside the
    // image counts as a different id, so pixels within `radius` of the border are never interior.
    // Pass 1: row[p] — the 2r+1 pixels centred on p in its row exist and all carry p's id (>= 0).
    std::vector<bool> row(ids.size(), false);
    for (int y = 0; y < height; ++y) {
        for (int start = 0; start < width;) {
            int end = start + 1; // the run of equal ids is [start, end)
            while (end < width && ids[at(end, y)] == ids[at(start, y)]) ++end;
            if (ids[at(start, y)] >= 0)
                for (int x = start + radius; x < end - radius; ++x) row[at(x, y)] = true;
            start = end;
        }
    }
    // Pass 2: interior — the 2r+1 pixels centred on p in its column all pass pass 1 with p's id.
    std::vector<bool> interior(ids.size(), false);
    for (int x = 0; x < width; ++x) {
        for (int start = 0; start < height;) {
            const int id = ids[at(x, start)];
            const bool passes = row[at(x, start)];
            int end = start + 1;
            while (end < height && row[at(x, end)] == passes && (!passes || ids[at(x, end)] == id)) ++end;
            if (passes)
                for (int y = start + radius; y < end - radius; ++y) interior[at(x, y)] = true;
            start = end;
        }
    }
    return interior;
}

} // namespace shadelab
