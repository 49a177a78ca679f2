// The point tracer (shadelab/diagram/point_stages.h) against the lecture's stages computed independently: a
// pixel picked by the probe's ray cast traces back to that pixel; a point at the near plane lands on NDC
// z = +1 and one at the far plane on −1; w = −z_camera under WebGL's matrix, z_camera under the unnegated
// one, which clips the point.
#include <cmath>

#include <gtest/gtest.h>

#include "shadelab/diagram/point_stages.h"
#include "shadelab/errors.h"
#include "shadelab/exact/probe.h"

namespace shadelab {
namespace {

// A sheared, rotated camera on an ellipsoid off the axis: no stage is the identity of another.
Scene tracedScene() {
    Scene scene;
    scene.width = 160;
    scene.height = 100;
    scene.eye = {2.5, 1.5, 3.5};
    scene.target = {0.2, -0.1, 0.3};
    scene.up = {0.2, 1, 0};
    scene.objects[0].center = {0.3, -0.2, 0.1};
    scene.objects[0].radius = 0.9;
    scene.objects[0].scale = {1.4, 0.7, 1.1};
    return scene;
}

TEST(PointStages, APickedPixelTracesBackToItself) {
    const Scene scene = tracedScene();
    int traced = 0;
    for (double x = 50.5; x < 120; x += 7)
        for (double y = 20.5; y < 80; y += 9) {
            const auto point = pickSurfacePoint(scene, x, y);
            if (!point) continue;
            const PointStages stages = tracePoint(scene, point->object, point->directionObject);
            ASSERT_FALSE(stages.behindEye);
            EXPECT_TRUE(stages.insideVolume);
            EXPECT_NEAR(stages.window.x, x, 1e-6) << "at pixel " << x << ", " << y;
            EXPECT_NEAR(stages.window.y, y, 1e-6) << "at pixel " << x << ", " << y;
            ++traced;
        }
    EXPECT_GT(traced, 20) << "the sample must hit the object";
}

TEST(PointStages, EachStageIsTheLecturesMatrixOfTheOneBefore) {
    const Scene scene = tracedScene();
    const glm::dvec3 p = glm::normalize(glm::dvec3(0.3, 0.5, 0.8));
    const PointStages stages = tracePoint(scene, 0, p);
    // α = M·p: centre + radius·scale·p, written out.
    const SceneObject& object = scene.objects[0];
    const glm::dvec3 world = object.center + object.radius * object.scale * p;
    EXPECT_NEAR(glm::length(stages.world - world), 0, 1e-12);
    // β = M_cam·α: the coordinates of α − e on u, v, w (the frame's columns, orthonormal).
    const glm::dvec3 w = glm::normalize(scene.eye - scene.target);
    const glm::dvec3 u = glm::normalize(glm::cross(scene.up, w)), v = glm::cross(w, u);
    const glm::dvec3 d = world - scene.eye;
    EXPECT_NEAR(stages.camera.x, glm::dot(d, u), 1e-12);
    EXPECT_NEAR(stages.camera.y, glm::dot(d, v), 1e-12);
    EXPECT_NEAR(stages.camera.z, glm::dot(d, w), 1e-12);
    // WebGL's matrix: w' = −z (the lecture's last row 0 0 −1 0), positive in front of the eye.
    EXPECT_NEAR(stages.clip.w, -stages.camera.z, 1e-12);
    // NDC x from the lecture's first row: −2n/(r−l)·x + (r+l)/(r−l)·z, divided by w; the fovy volume is
    // symmetric (r = −l), so x_ndc = (2n/(r−l))·x/(−z) = x / (−z·tan(fovy/2)·aspect).
    const double t = std::tan(glm::radians(scene.projection.fovyDeg) / 2);
    const double aspect = double(scene.width) / scene.height;
    EXPECT_NEAR(stages.ndc.x, stages.camera.x / (-stages.camera.z * t * aspect), 1e-12);
    EXPECT_NEAR(stages.ndc.y, stages.camera.y / (-stages.camera.z * t), 1e-12);
}

TEST(PointStages, NearMapsToPlusOneFarToMinusOneAndTheUnnegatedMatrixClips) {
    Scene scene;
    scene.projection.near = 3.0; // the unit sphere's front point (0, 0, 1) is 3 in front of the eye
    scene.projection.far = 5.0;  // and its back point (0, 0, −1) is 5 in front
    const PointStages front = tracePoint(scene, 0, {0, 0, 1}), back = tracePoint(scene, 0, {0, 0, -1});
    EXPECT_NEAR(front.ndc.z, 1.0, 1e-12);
    EXPECT_NEAR(front.window.z, 1.0, 1e-12);
    EXPECT_NEAR(back.ndc.z, -1.0, 1e-12);
    EXPECT_NEAR(back.window.z, 0.0, 1e-12);
    EXPECT_NEAR(front.window.x, scene.width / 2.0, 1e-9);
    scene.perspectiveMatrix = PerspectiveMatrix::Unnegated;
    const PointStages unnegated = tracePoint(scene, 0, {0, 0, 1});
    EXPECT_NEAR(unnegated.clip.w, -3.0, 1e-12) << "w' = z < 0 in front of the camera";
    EXPECT_TRUE(unnegated.behindEye) << "WebGL clips negative w";
    EXPECT_THROW(tracePoint(scene, 1, {0, 0, 1}), InputError);
}

} // namespace
} // namespace shadelab
