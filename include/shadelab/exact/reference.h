// The analytic reference: an exact ray-cast of the scene's spheres and ellipsoids and of the teapot's Bézier
// patches in double precision, through pixel centres, with the same camera, projection and lighting code
// (lighting.h) as the renderer. It is the ground truth for the image tests and the error report. A mesh read
// from a file has no exact surface: its reference is its own triangles lit per pixel with their
// interpolated normals (mesh_cast.h), which measures shading error only.
#pragma once

#include <vector>

#include "shadelab/image/image.h"
#include "shadelab/scene/scene.h"

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
inline void setTrueNormals(Scene& scene) {
    scene.normalMatrix = NormalMatrixRule::InverseTranspose;
}
inline Scene withTrueNormals(Scene scene) {
    setTrueNormals(scene);
    return scene;
}

// Pixels whose every neighbour within `radius` (Chebyshev distance) shows the same object in `ids` —
// the "interior" used for error measurement (DESIGN §6: silhouette eroded by 2 px).
std::vector<bool> interiorMask(const std::vector<int>& ids, int width, int height, int radius = 2);

// The one measure of a picture's error against the reference (DESIGN §6), for `shadelab report`, the
// error view's figures on the CPU, and the tests: |Δ| per colour channel, in 8-bit units, over the pixels
// interior to the same object in both (sharedInterior). A NaN channel makes max NaN: it is never hidden.
struct InteriorError {
    double mean = 0, max = 0;
    std::size_t pixels = 0;
};
InteriorError interiorError(const ImageF& rendered, const ReferenceImage& reference, int erode = 2);
// The pixels interiorError measures: interior (interiorMask, eroded by `erode` px) to the same object in
// the reference and in the render, whose coverage is its alpha (> 0.5) and whose objects are the
// reference's where both cover. Throws InputError when the two sizes differ.
std::vector<bool> sharedInterior(const ImageF& rendered, const ReferenceImage& reference, int erode = 2);
// Per interior pixel, in row order: the largest of its three channels' errors.
std::vector<double> interiorPixelErrors(const ImageF& rendered, const ReferenceImage& reference,
                                        int erode = 2);

} // namespace shadelab
