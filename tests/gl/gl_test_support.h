// What every GL test needs: the backend under test (SHADELAB_TEST_BACKEND, set per CTest registration),
// one headless renderer per test process, and scenes built in code.
#pragma once

#include <cstdlib>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "shadelab/context/headless.h"
#include "shadelab/exact/reference.h"
#include "shadelab/gl/program.h"

namespace shadelab::test {

// SHADELAB_TEST_BACKEND: egl (desktop OpenGL), osmesa, or gles (EGL, OpenGL ES 3.0).
ContextRequest contextUnderTest();

// The process's renderer, or nullptr with the reason in `why` when no context can be made.
HeadlessRenderer* glRenderer(std::string& why);

// Interior error against the analytic reference: shadelab::interiorError (reference.h), the measure
// `shadelab report` uses.

// Pixels whose coverage differs between the render and the reference, per pixel of the reference's
// silhouette (covered pixels with an uncovered 4-neighbour): the mean distance in pixels between the two
// silhouettes, for a silhouette that moved as a whole.
double silhouetteShiftPx(const ImageF& image, const ReferenceImage& reference);
// Interior pixels (as interiorError counts them) with some colour channel off by more than `limit255`.
std::size_t interiorPixelsOver(const ImageF& rendered, const ReferenceImage& reference, double limit255);

// Each specialization with the name test messages give it.
inline constexpr std::pair<gl::Specialization, const char*> kSpecializationLabels[] = {
    {gl::Specialization::None, "uber"},
    {gl::Specialization::Lights, "specialized"},
    {gl::Specialization::Values, "values"},
};

// A sphere scene of size×size with one light of the given type, lit from the upper right front.
Scene litSphereScene(int size, LightType light);

// litSphereScene(size, point light) with every length multiplied by r: the radius, eye, target, near, far
// and light position, and the attenuation's b/r and c/r² so that att is unchanged. The same picture as r = 1.
Scene scaledSphereScene(int size, double r);

// Every shading mode × lighting model of a size×size sphere at `level`, under a spot and a point light: the
// scenes two renderers are compared on pixel for pixel (backends, and the browser against native).
std::vector<Scene> modeScenes(int size, int level);

// The scenes every API is held to against the analytic reference (tests/gl/analytic_test.cpp, and the
// browser test): each light type, off-centre frustum, orthographic, an ellipsoid, two overlapping spheres.
struct AnalyticCase {
    const char* name;
    std::function<Scene()> scene;
};

// Test names and failure messages show the case by its name, not as bytes.
inline void PrintTo(const AnalyticCase& c, std::ostream* os) {
    *os << c.name;
}
const std::vector<AnalyticCase>& analyticCases();
const AnalyticCase& analyticCase(std::string_view name); // one of them by name; throws std::logic_error

// DESIGN §2's clip-from-view matrix of the scene's projection through GLM alone (frustumRH_NO,
// perspectiveRH_NO or orthoRH_NO times diag(1, 1, −1, 1): near → NDC z = +1), for checks independent of
// camera.cpp.
glm::dmat4 webGlClipFromView(const Scene& scene);

// The outside view of `scene` (view "outside", at the picture's size): checks that each corner of the view
// volume, computed independently as inverse(M_proj·M_cam) of the NDC cube's corners (glm::lookAt and GLM's
// frustum, perspective or ortho matrix times diag(1, 1, −1, 1), DESIGN §2) and projected by the observer's
// camera (observerScene's eye, target, up and projection, through the same GLM functions), is drawn
// within 1 px: the volume's edge colour at the corner and 4 px along each incident edge, and not 3 px past
// the corner along an edge's extension. Returns what failed, one line each; empty when all is well.
std::vector<std::string> outsideCornerMisses(const Image& image, const Scene& scene);

} // namespace shadelab::test

// Without a GL context a test skips with the reason, except in CI (CI set), where it fails.
#define SHADELAB_REQUIRE_GL(renderer)                                                                        \
    std::string renderer##Why;                                                                               \
    HeadlessRenderer* renderer = ::shadelab::test::glRenderer(renderer##Why);                                \
    if (!renderer) {                                                                                         \
        if (std::getenv("CI")) FAIL() << "no GL context in CI: " << renderer##Why;                           \
        GTEST_SKIP() << "no GL context: " << renderer##Why;                                                  \
    }
