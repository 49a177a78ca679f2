// Casting view-space rays at the scene's exact objects, in double: spheres and ellipsoids (a quadric), the
// teapot (its Bézier patches, patch_cast.h) and meshes read from files (their triangles, mesh_cast.h). The
// analytic reference casts one through every pixel centre, the demo's probe one through the pixel a user
// clicks.
#pragma once

#include <limits>
#include <memory>

#include <glm/glm.hpp>

#include "shadelab/exact/mesh_cast.h"
#include "shadelab/scene/scene.h"
#include "shadelab/shading/lighting.h"

namespace shadelab {

// One object, prepared for casting view-space rays at it.
struct ObjectInView {
    glm::dmat3 objectFromView3;      // inverse of viewFromObject's upper 3×3
    glm::dvec3 originView;           // viewFromObject's translation: the centre in view space
    glm::dmat3 normalViewFromObject; // normalViewFromObject(viewFromObject, rule): O(1)
    Shape shape = Shape::Sphere;
    bool twoSided = false;                  // !isClosed(object): a back face is lit turned over (DESIGN §3)
    std::shared_ptr<const MeshBvh> meshBvh; // Shape::Mesh: only from prepareObjectForCasting
};
// The transforms alone (what the GPU's exact shading needs): cheap, whatever the shape.
ObjectInView prepareObject(const SceneObject& object, const glm::dmat4& viewFromWorld, NormalMatrixRule rule);
// The same with what a CPU ray cast needs beside: a mesh object's hierarchy (meshBvhFor, built once per
// model). Throws InputError for a mesh object whose model is not loaded.
ObjectInView prepareObjectForCasting(const SceneObject& object, const glm::dmat4& viewFromWorld,
                                     NormalMatrixRule rule);

struct RayHit {
    double s = std::numeric_limits<double>::infinity(); // ray parameter: point = origin + s·direction
    int object = -1;
    glm::dvec3 pointObject{0, 0, 1};  // the hit in object space (a sphere's: on the unit sphere)
    glm::dvec3 normalObject{0, 0, 1}; // outward, object space, not necessarily unit (a sphere's: pointObject)
    bool backFace = false;            // the ray meets the surface from inside (a sphere's: never reported)
};

// Intersects the view-space ray origin + s·direction with `object` and keeps the hit in `best` when it lies
// inside the clip volume (view z in [−far, −near]) and is nearer than the hit already there. A mesh object
// needs prepareObjectForCasting's hierarchy (without it, it is never hit).
void intersectObject(const ObjectInView& object, int index, const glm::dvec3& originView,
                     const glm::dvec3& directionView, double near, double far, RayHit& best);

// The point `hit` found on the ray, with its normal (the exact quadric's, the patch's analytic one, a mesh's
// interpolated one) by the object's normal matrix — turned towards the viewer on a back face of a two-sided
// object (DESIGN §3) — and DESIGN §3's viewer rule, in view space.
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
