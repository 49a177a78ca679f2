// A point followed through the pipeline, as the lecture writes each stage: object coordinates p, world
// coordinates α = M·p, camera coordinates β = M_cam·α, clip coordinates M_proj·β, NDC after the divide by w,
// and the window (pixels and depth). The demo's probe shows it for the probed point (the point tracer).
#pragma once

#include <cstddef>

#include <glm/glm.hpp>

#include "shadelab/scene/scene.h"

namespace shadelab {

struct PointStages {
    glm::dvec3 object{0.0}; // p: the object's own coordinates (its unit sphere)
    glm::dvec3 world{0.0};  // α = M·p, M = worldFromObject
    glm::dvec3 camera{0.0}; // β = M_cam·α
    glm::dvec4 clip{0.0};   // M_proj·β (w > 0 in front of the camera with WebGL's matrix)
    glm::dvec3 ndc{0.0};    // clip.xyz / clip.w; in [−1, 1]³ inside the view volume (near → z = +1)
    // x, y: pixels from the picture's top-left corner (pixel (i, j)'s centre is (i + 0.5, j + 0.5), as the
    // probe picks them); z: the depth buffer's value, (z_ndc + 1)/2, or z_ndc under reversed-Z's [0, 1]
    // range.
    glm::dvec3 window{0.0};
    bool behindEye = false;    // clip.w <= 0: the clipper drops it, and NDC and window mean nothing
    bool insideVolume = false; // NDC in [−1, 1]³ (z in [0, 1] for reversed-Z): inside the view volume
};

// The stages of `pointObject` on object `object` of `scene` (at scene.width × scene.height). Throws
// InputError for an object the scene does not have, as sceneView does for a degenerate camera.
PointStages tracePoint(const Scene& scene, std::size_t object, const glm::dvec3& pointObject);

} // namespace shadelab
