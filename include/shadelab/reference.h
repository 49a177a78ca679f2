// The analytic reference: an exact ray-cast of the scene's spheres and ellipsoids in double precision,
// through pixel centres, with the same camera, projection and lighting code (lighting.h) as the renderer.
// It is the ground truth for the image tests and the error report.
#pragma once

#include <vector>

#include "shadelab/image.h"
#include "shadelab/scene.h"

namespace shadelab {

struct ReferenceImage {
    ImageF color;              // linear colour clamped to [0,1], alpha 1 on objects and 0 on background
    std::vector<int> objectId; // per pixel, top row first: index into scene.objects, −1 for background
};

// Exact per-point lighting (the limit of Phong shading; toon bands when scene.shading is toon).
ReferenceImage renderReference(const Scene& scene);

// Pixels whose every neighbour within `radius` (Chebyshev distance) shows the same object in `ids` —
// the "interior" used for error measurement (DESIGN §6: silhouette eroded by 2 px).
std::vector<bool> interiorMask(const std::vector<int>& ids, int width, int height, int radius = 2);

} // namespace shadelab
