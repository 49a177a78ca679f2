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

// Exact per-point lighting (the limit of Phong shading; toon bands when scene.shading is toon), with the
// scene's normal matrix rule: the wrong picture of "normal_matrix": "model" has its own exact oracle.
ReferenceImage renderReference(const Scene& scene);

// The scene a picture's error is measured against: the scene with normals by (M⁻¹)ᵀ, the truth, whatever
// its rule. The error, split and profile views' exact and `shadelab report` use it, so with normals by M
// they show what the wrong matrix costs (DESIGN §2).
inline Scene withTrueNormals(Scene scene) {
    scene.normalMatrix = NormalMatrixRule::InverseTranspose;
    return scene;
}

// Pixels whose every neighbour within `radius` (Chebyshev distance) shows the same object in `ids` —
// the "interior" used for error measurement (DESIGN §6: silhouette eroded by 2 px).
std::vector<bool> interiorMask(const std::vector<int>& ids, int width, int height, int radius = 2);

} // namespace shadelab
