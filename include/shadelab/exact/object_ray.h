// What the ray casts of the teapot and of a mesh share: a ray in an object's own coordinates and the hit it
// finds there. The caller (ray_cast.cpp) moves the view-space ray into object space, re-centres its origin
// on the point nearest the object's origin (so that |origin| is O(1) for any ray that can hit) and maps the
// clip volume to a range of t.
#pragma once

#include <cstdint>
#include <limits>

#include <glm/glm.hpp>

namespace shadelab {

// originObject + t·directionObject, |directionObject| = 1, for t in [tMin, tMax].
struct ObjectRay {
    glm::dvec3 originObject, directionObject;
    double tMin = 0, tMax = std::numeric_limits<double>::infinity();
};

struct ObjectRayHit {
    double t = std::numeric_limits<double>::infinity();
    glm::dvec3 pointObject{0.0};
    glm::dvec3 normalObject{0, 0, 1}; // outward (the patch's analytic one, or the interpolated vertex normal)
    bool backFace = false;            // the ray meets the surface from its inside (DESIGN §3, open surfaces)
};

// The work a cast did, for the reference's cost model (scene.h kMaxReferenceRayTests): bounding boxes
// tested, and surface tests (a Newton solve on a patch, a ray-triangle test on a mesh).
struct CastCounters {
    std::uint64_t boxTests = 0, surfaceTests = 0;
};

} // namespace shadelab
