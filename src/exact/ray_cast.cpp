#include "shadelab/exact/ray_cast.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "shadelab/errors.h"
#include "shadelab/exact/patch_cast.h"
#include "shadelab/scene/camera.h"

namespace shadelab {

// viewFromObject's 3×3 is (rotation)·diag(radius·scale). Its determinant is radius³·sx·sy·sz, which a
// generic inverse under/overflows for extreme radii (radius 1e-9 gives a determinant of 1e-27). Dividing by
// the largest entry first keeps it O(1); the inverse is then rescaled back. The normal matrix is scaled the
// same way (normalViewFromObject), by the scene's rule.
ObjectInView prepareObject(const SceneObject& object, const glm::dmat4& viewFromWorld,
                           NormalMatrixRule rule) {
    const glm::dmat4 viewFromObject = viewFromWorld * worldFromObject(object);
    const glm::dmat3 linear(viewFromObject);
    const double k = largestAbsEntry(linear); // > 0: validated radius > 0 and non-zero scale
    const glm::dmat3 unit = linear / k;
    return ObjectInView{glm::inverse(unit) / k,
                        glm::dvec3(viewFromObject[3]),
                        normalViewFromObject(viewFromObject, rule),
                        object.shape,
                        !isClosed(object),
                        nullptr};
}

ObjectInView prepareObjectForCasting(const SceneObject& object, const glm::dmat4& viewFromWorld,
                                     NormalMatrixRule rule) {
    ObjectInView prepared = prepareObject(object, viewFromWorld, rule);
    if (object.shape == Shape::Mesh) {
        if (!object.model)
            throw InputError("mesh \"" + object.mesh + "\": the model is not loaded (loadSceneModels)");
        prepared.meshBvh = meshBvhFor(object.model);
    }
    return prepared;
}

namespace {

// The teapot and meshes: the ray re-centred on its point nearest the object's origin, so that for any ray
// that can hit |origin| is O(1) whatever the distance of the eye (the cancellation happens once, here), and
// the clip volume's z range turned into a range of t.
void intersectSurface(const ObjectInView& object, int index, const glm::dvec3& originView,
                      const glm::dvec3& directionView, const glm::dvec3& o, const glm::dvec3& dUnit,
                      double dLength, double near, double far, RayHit& best) {
    if (!(directionView.z < 0)) return; // both projections cast rays towards −z
    const double tShift = -glm::dot(o, dUnit);
    const double sNear = (near + originView.z) / -directionView.z,
                 sFar = (far + originView.z) / -directionView.z;
    const double sMax = std::min(sFar, best.s);
    const ObjectRay ray{o + tShift * dUnit, dUnit, sNear * dLength - tShift, sMax * dLength - tShift};
    ObjectRayHit hit;
    const bool found = object.shape == Shape::Teapot ? intersectTeapot(ray, hit)
                       : object.meshBvh              ? object.meshBvh->intersect(ray, hit)
                                                     : false;
    if (!found) return;
    const double s = (hit.t + tShift) / dLength;
    if (s < best.s) best = RayHit{s, index, hit.pointObject, hit.normalObject, hit.backFace};
}

} // namespace

void intersectObject(const ObjectInView& object, int index, const glm::dvec3& originView,
                     const glm::dvec3& directionView, double near, double far, RayHit& best) {
    const glm::dvec3 o = object.objectFromView3 * (originView - object.originView);
    const glm::dvec3 d = object.objectFromView3 * directionView;
    const double dLength = glm::length(d);
    if (!(dLength > 0) || !std::isfinite(dLength) || !std::isfinite(glm::dot(o, o))) return;
    const glm::dvec3 dUnit = d / dLength;
    if (object.shape != Shape::Sphere) {
        intersectSurface(object, index, originView, directionView, o, dUnit, dLength, near, far, best);
        return;
    }

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
            const glm::dvec3 pointObject = perpendicular + side * root * dUnit;
            if (s < best.s) best = RayHit{s, index, pointObject, pointObject, false};
            return;
        }
    }
}

SurfacePoint exactSurfacePoint(const ObjectInView& object, const RayHit& hit, const glm::dvec3& originView,
                               const glm::dvec3& directionView, bool orthographic) {
    const glm::dvec3 positionView = originView + hit.s * directionView;
    // A closed object's mesh is seen from outside, so the outward normal is used as is, even where the near
    // plane cuts a sphere open and its inside shows. An open one is lit two-sided: its inside is seen.
    glm::dvec3 normalView =
        safeNormalize(object.normalViewFromObject * hit.normalObject, glm::dvec3(0, 0, 1));
    if (object.twoSided && hit.backFace) normalView = -normalView;
    return SurfacePoint{positionView, normalView, toViewer(positionView, normalView, orthographic)};
}

void PixelRays::ray(double x, double y, glm::dvec3& originView, glm::dvec3& directionView) const {
    const double xView = volume.left + (volume.right - volume.left) * x / width;
    const double yView = volume.top - (volume.top - volume.bottom) * y / height;
    if (orthographic) {
        originView = {xView, yView, 0};
        directionView = {0, 0, -1};
    } else {
        originView = {0, 0, 0};
        directionView = {xView, yView, -volume.near}; // through (x, y) on the near plane
    }
}

} // namespace shadelab
