// The exact teapot: a ray cast of Newell's 32 Bézier patches (geometry/teapot.h) in object space, in double.
// Its picture is the teapot's reference (DESIGN §1, "The teapot"; §6).
#pragma once

#include "shadelab/exact/object_ray.h"

namespace shadelab {

// The nearest point of the patches on `ray` (t in [tMin, tMax]) with the analytic normal (patchNormal, the
// cusp rule included); kept in `hit` when nearer than what `hit` holds. Returns whether it kept one.
bool intersectTeapot(const ObjectRay& ray, ObjectRayHit& hit, CastCounters* counters = nullptr);

} // namespace shadelab
