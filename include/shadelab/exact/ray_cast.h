// Casting view-space rays at the scene's exact spheres and ellipsoids, in double: the analytic reference
// casts one through every pixel centre, the demo's probe one through the pixel a user clicks.
#pragma once

#include <limits>

#include <glm/glm.hpp>

#include "shadelab/scene/scene.h"
#include "shadelab/shading/lighting.h"

namespace shadelab {

// One object, prepared for casting view-space rays at it.
struct ObjectInView {
    glm::dmat3 objectFromView3;      // inverse of viewFromObject's upper 3×3
    glm::dvec3 originView;           // viewFromObject's translation: the centre in view space
    glm::dmat3 normalViewFromObject; // normalViewFromObject(viewFromObject, rule): O(1)
};
ObjectInView prepareObject(const SceneObject& object, const glm::dmat4& viewFromWorld, NormalMatrixRule rule);

struct RayHit {
    double s = std::numeric_limits<double>::infinity(); // ray parameter: point = origin + s·direction
    int object = -1;
    glm::dvec3 pointObject{0, 0, 1}; // on the unit sphere: also the object-space normal
};

// Intersects the view-space ray origin + s·direction with `object` and keeps the hit in `best` when it lies
// inside the clip volume (view z in [−far, −near]) and is nearer than the hit already there.
void intersectObject(const ObjectInView& object, int index, const glm::dvec3& originView,
                     const glm::dvec3& directionView, double near, double far, RayHit& best);

// The point `hit` found on the ray, with the exact quadric normal and DESIGN §3's viewer rule, in view space.
SurfacePoint exactSurfacePoint(const ObjectInView& object, const RayHit& hit, const glm::dvec3& originView,
                               const glm::dvec3& directionView, bool orthographic);

// Exactly one place decides which point of the view a pixel position sees. (x, y) are pixel coordinates
// from the top left corner of a width × height image: pixel (i, j)'s centre is (i + 0.5, j + 0.5).
struct PixelRays {
    ViewVolume volume;
    bool orthographic;
    int width, height;

    void ray(double x, double y, glm::dvec3& originView, glm::dvec3& directionView) const;
};

} // namespace shadelab
