// What the extreme tests (extreme_geometry_test, extreme_lighting_test, extreme_camera_test) share. Each
// case states what it expects: a correct picture within a stated error — against the analytic reference
// (interior error, as interiorError), or against the same scene at a normal scale — or a clear InputError
// whose message names the field. Every image, rendered or reference, goes through a float target and is
// scanned for non-finite and out-of-range values before it is compared (checkedRender / checkedReference).
//
// The shaders clamp before writing, and on Mesa clamp(NaN) yields a bound, so the scan alone proves the
// clamp, not finite lighting: a NaN or Inf in the lighting shows as a wrong colour, which the comparison
// with the reference (or the unit-scale scene) catches. Stiff lighting already covered by invariants_test's
// StiffScenes (v = −l, shininess 1 and 1e4 by mean brightness, a light inside or on the sphere, spot cutoff
// 0°/90°, I = 1e6) is not repeated there.
#pragma once

#include <cstddef>
#include <string>

#include "gl/gl_test_support.h"

namespace shadelab::test {

// Every image: no NaN or Inf, every channel (alpha too) within [0, 1].
void expectClean(const ImageF& image, const std::string& what);
// The scene through a float target, its size and values checked (expectClean).
ImageF checkedRender(HeadlessRenderer& renderer, const Scene& scene, const std::string& what);
// The analytic reference, its values checked likewise.
ReferenceImage checkedReference(const Scene& scene, const std::string& what);
std::size_t coveredPixels(const ImageF& image);
std::size_t coveredPixels(const ReferenceImage& reference);
// DESIGN §6 / analytic_test: Phong shading at level 8 is the exact per-point lighting up to the mesh's tiny
// normal error: on the interior, mean < 0.5/255 and max <= 4/255.
void expectPhongLimits(const ImageF& image, const ReferenceImage& reference, const std::string& what,
                       std::size_t minPixels = 200);
// The regression tolerance (references_test): max 1/255 outside an outlier budget of 24 silhouette pixels,
// mean 0.05/255. For a scene that must render the same as its unit-scale or at-the-origin twin.
void expectSameImage(const ImageF& actual, const ImageF& expected, const std::string& what);
// "exact-normals" or "averaged-normals", for test names and messages.
const char* normalsName(VertexNormals normals);
// A lit sphere at level 8 under Phong shading (the case the Phong-at-level-8 limits are for).
Scene phongScene(int size, LightType light = LightType::Point);

} // namespace shadelab::test
