// The demo's camera (src/app/demo/demo_state.h) against DESIGN §2: O between perspective and orthographic
// keeps the sphere's size on screen and round in any window; the first frame is the scene's own camera; the
// orbit camera's drag and zoom never reach a pole, the inside of an object or past the far plane, and R
// gives the scene's view back; a right-drag orbits a light; random keys, drags and zooms always give a
// valid scene.
#include "app/demo/demo_state.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "demo_test_support.h"
#include "shadelab/scene/camera.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app {
namespace {

using namespace demo_test;

template <int C, int R> bool allFinite(const glm::mat<C, R, double>& m) {
    for (int c = 0; c < C; ++c)
        for (int r = 0; r < R; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

double maxAbsDifference(const glm::dmat4& a, const glm::dmat4& b) {
    double worst = 0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) worst = std::max(worst, std::abs(a[c][r] - b[c][r]));
    return worst;
}

bool sameProjection(const Projection& a, const Projection& b) {
    return a.type == b.type && a.fovyDeg == b.fovyDeg && a.left == b.left && a.right == b.right &&
           a.bottom == b.bottom && a.top == b.top && a.near == b.near && a.far == b.far;
}

double boundingRadius(const SceneObject& o) {
    return o.radius * std::max({std::abs(o.scale.x), std::abs(o.scale.y), std::abs(o.scale.z)});
}

glm::dvec3 ndc(const SceneView& view, const glm::dvec3& world) {
    const glm::dvec4 clip = view.clipFromView * view.viewFromWorld * glm::dvec4(world, 1);
    return glm::dvec3(clip) / clip.w;
}

// The vertical NDC distance from the projected centre of a sphere to its silhouette, computed from the
// geometry: under perspective the silhouette point is where a ray from the eye grazes the sphere.
double projectedRadiusNdc(const Scene& scene, const glm::dvec3& centre, double radius) {
    const SceneView view = sceneView(scene);
    const CameraFrame frame = cameraFrame(scene.eye, scene.target, scene.up);
    glm::dvec3 silhouette;
    if (view.orthographic) {
        silhouette = centre + radius * frame.v;
    } else {
        const glm::dvec3 toCentre = centre - scene.eye;
        const double d = glm::length(toCentre);
        const double sinB = radius / d, cosB = std::sqrt(1 - sinB * sinB);
        const glm::dvec3 forward = toCentre / d;
        const glm::dvec3 up = glm::normalize(frame.v - glm::dot(frame.v, forward) * forward);
        silhouette = scene.eye + std::sqrt(d * d - radius * radius) * (cosB * forward + sinB * up);
    }
    return std::abs(ndc(view, silhouette).y - ndc(view, centre).y);
}

// ---- O: perspective <-> orthographic ----

TEST(DemoProjection, OTogglesOrthographicAndTwiceRestoresExactly) {
    for (const Scene& scene : {Scene{}, threeObjectScene()}) {
        DemoState state(scene);
        const Projection original = state.current().projection;
        EXPECT_TRUE(sameProjection(original, scene.projection))
            << "the first frame uses the scene's projection";
        EXPECT_FALSE(state.orthographic());
        EXPECT_TRUE(state.apply(Command::ToggleProjection));
        EXPECT_TRUE(state.orthographic());
        EXPECT_EQ(state.current().projection.type, ProjectionType::Orthographic);
        EXPECT_EQ(state.current().projection.near, original.near);
        EXPECT_EQ(state.current().projection.far, original.far);
        state.apply(Command::ToggleProjection);
        EXPECT_FALSE(state.orthographic());
        EXPECT_TRUE(sameProjection(state.current().projection, original));
    }
}

// The issue: O keeps the sphere's size on screen. The orthographic box shows the perspective view's height
// at the target, so the sphere's projected radius differs only by the perspective bulge d/√(d²−r²).
TEST(DemoProjection, OKeepsTheSpheresSizeOnScreen) {
    struct Move {
        double dx, dy, wheel;
    };
    for (const Move& move : {Move{0, 0, 0}, Move{140, -60, 0}, Move{-300, 90, -6}, Move{45, 10, 3}}) {
        DemoState state(Scene{});
        state.drag(move.dx, move.dy);
        state.zoom(move.wheel);
        const Scene perspective = state.current();
        state.apply(Command::ToggleProjection);
        const Scene orthographic = state.current();
        ASSERT_EQ(orthographic.projection.type, ProjectionType::Orthographic);
        EXPECT_EQ(orthographic.eye, perspective.eye);
        const double rp = projectedRadiusNdc(perspective, {0, 0, 0}, 1);
        const double ro = projectedRadiusNdc(orthographic, {0, 0, 0}, 1);
        EXPECT_NEAR(ro / rp, 1.0, 0.10) << "perspective " << rp << ", orthographic " << ro << " (drag "
                                        << move.dx << "," << move.dy << ", wheel " << move.wheel << ")";
        // Same half-height at the target: the ratio is exactly the perspective bulge √(d²−r²)/d.
        const double d = glm::length(perspective.eye);
        EXPECT_NEAR(ro / rp, std::sqrt(d * d - 1) / d, 1e-9) << "d = " << d;
    }
}

TEST(DemoProjection, OFromAnOrthographicSceneKeepsTheSpheresSize) {
    Scene scene;
    scene.projection = {ProjectionType::Orthographic, 40, -1.5, 1.5, -1.5, 1.5, 0.5, 20};
    scene.eye = {0, 0, 5};
    DemoState state(scene);
    EXPECT_TRUE(state.orthographic());
    const Scene orthographic = state.current();
    EXPECT_TRUE(sameProjection(orthographic.projection, scene.projection));
    state.apply(Command::ToggleProjection);
    const Scene perspective = state.current();
    ASSERT_EQ(perspective.projection.type, ProjectionType::Perspective);
    EXPECT_NO_THROW(validateScene(perspective));
    const double rp = projectedRadiusNdc(perspective, {0, 0, 0}, 1);
    const double ro = projectedRadiusNdc(orthographic, {0, 0, 0}, 1);
    EXPECT_NEAR(ro / rp, 1.0, 0.10) << "orthographic " << ro << ", perspective " << rp;
    EXPECT_NEAR(ro / rp, std::sqrt(24.0) / 5, 1e-9) << "same half-height at the target distance 5";
    state.apply(Command::ToggleProjection);
    EXPECT_TRUE(sameProjection(state.current().projection, scene.projection));
}

// The window draws current(width, height) at the framebuffer's size. Robustness: a resized
// window must not distort the picture. Perspective recomputes its aspect from the size; the orthographic
// box must too, or the sphere becomes an ellipse.
TEST(DemoProjection, SphereStaysRoundWhenTheWindowAspectDiffersFromTheScenes) {
    for (bool orthographic : {false, true}) {
        Scene scene; // 512×512
        DemoState state(scene);
        if (orthographic) state.apply(Command::ToggleProjection);
        const Scene s = state.current(800, 600); // a window resized to 800×600
        const SceneView view = sceneView(s);
        const CameraFrame frame = cameraFrame(s.eye, s.target, s.up);
        const glm::dvec3 centre = ndc(view, {0, 0, 0});
        // Silhouette points left-right and up-down; at the target distance the bulge is the same both ways.
        const double rx = std::abs(ndc(view, frame.u).x - centre.x) * s.width / 2;
        const double ry = std::abs(ndc(view, frame.v).y - centre.y) * s.height / 2;
        EXPECT_NEAR(rx / ry, 1.0, 0.01) << (orthographic ? "orthographic" : "perspective") << ": " << rx
                                        << " px wide, " << ry << " px high";
    }
}

// ---- R and the orbit camera ----

TEST(DemoCamera, RRestoresTheViewAfterDragsAndZooms) {
    for (const Scene& scene : {Scene{}, threeObjectScene()}) {
        DemoState state(scene);
        const Scene before = state.current();
        state.drag(123, -45);
        state.zoom(3);
        state.drag(1e6, 1e6);
        state.zoom(-7.5);
        state.apply(Command::Flat);
        ASSERT_NE(state.current().eye, before.eye);
        EXPECT_TRUE(state.apply(Command::ResetView));
        const Scene after = state.current();
        EXPECT_EQ(after.eye, before.eye) << str(after.eye) << " vs " << str(before.eye);
        EXPECT_EQ(after.target, before.target);
        EXPECT_EQ(after.up, before.up);
        EXPECT_TRUE(sameProjection(after.projection, before.projection));
        EXPECT_EQ(after.shading, ShadingMode::Flat) << "R resets the view only";
    }
}

// For the default scene (and the showcase), the demo's first frame is exactly `shadelab render`'s view.
TEST(DemoCamera, FirstFrameIsTheScenesCamera) {
    Scene showcase;
    showcase.objects[0].radius = 1.1;
    showcase.objects[0].subdivisions = 3;
    for (const Scene& scene : {Scene{}, showcase, threeObjectScene()}) {
        DemoState state(scene);
        const Scene s = state.current();
        EXPECT_LT(glm::length(s.eye - scene.eye), 1e-12) << str(s.eye) << " vs " << str(scene.eye);
        EXPECT_EQ(s.target, scene.target);
        EXPECT_LT(maxAbsDifference(sceneView(s).viewFromWorld, sceneView(scene).viewFromWorld), 1e-12);
        EXPECT_TRUE(sameProjection(s.projection, scene.projection));
    }
}

// A scene file's camera is part of the scene: `shadelab SCENE.json` should first show what
// `shadelab render SCENE.json` shows. These are valid scenes (DESIGN §4) whose camera the demo changes.
void expectFirstFrameIsTheScenesView(const Scene& scene) {
    validateScene(scene);
    DemoState state(scene);
    const Scene s = state.current();
    const double diff = maxAbsDifference(sceneView(s).viewFromWorld, sceneView(scene).viewFromWorld);
    EXPECT_LT(diff, 1e-9) << "view matrix differs by " << diff << "; eye " << str(s.eye) << " (scene "
                          << str(scene.eye) << "), up " << str(s.up) << " (scene " << str(scene.up) << ")";
}

TEST(DemoCamera, FirstFrameKeepsTheScenesUpVector) {
    Scene scene;
    scene.up = {1, 0, 0}; // a camera rolled by 90°
    expectFirstFrameIsTheScenesView(scene);
}

TEST(DemoCamera, FirstFrameKeepsATopDownCamera) {
    Scene scene;
    scene.eye = {0, 5, 0};
    scene.up = {0, 0, -1};
    expectFirstFrameIsTheScenesView(scene);
}

TEST(DemoCamera, FirstFrameKeepsACameraThatIsAlreadyOutsideEveryObject) {
    Scene scene;
    scene.eye = {0, 0, 4};
    scene.objects[0].center = {3, 0, 0}; // the eye is 5 from its centre; nothing near the near plane
    SceneObject other = scene.objects[0];
    other.center = {-3, 0, 0};
    scene.objects.push_back(other);
    expectFirstFrameIsTheScenesView(scene);
}

TEST(OrbitCamera, EyeIsAtDistanceFromTheTarget) {
    std::mt19937_64 rng(20240603);
    std::uniform_real_distribution<double> any(-50, 50), angle(-3 * std::numbers::pi, 3 * std::numbers::pi),
        elevation(-OrbitCamera::kMaxElevationRad, OrbitCamera::kMaxElevationRad), distance(0.01, 100);
    for (int i = 0; i < 1000; ++i) {
        OrbitCamera c;
        c.target = {any(rng), any(rng), any(rng)};
        c.distance = distance(rng);
        c.azimuthRad = angle(rng);
        c.elevationRad = elevation(rng);
        EXPECT_NEAR(glm::length(c.eye() - c.target), c.distance, 1e-12 * (1 + c.distance));
    }
    OrbitCamera c; // azimuth 0, elevation 0: on +z of the target
    c.target = {1, 2, 3};
    EXPECT_LT(glm::length(c.eye() - glm::dvec3(1, 2, 3 + c.distance)), 1e-15);
}

TEST(OrbitCamera, LookingRoundTripsTheEye) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> any(-20, 20), unit(-1, 1), distance(0.1, 50);
    int tested = 0;
    while (tested < 2000) {
        const glm::dvec3 dir{unit(rng), unit(rng), unit(rng)};
        if (glm::length(dir) < 0.1) continue;
        if (std::abs(glm::normalize(dir).y) > std::sin(OrbitCamera::kMaxElevationRad)) continue; // poles
        const glm::dvec3 target{any(rng), any(rng), any(rng)};
        const glm::dvec3 eye = target + distance(rng) * glm::normalize(dir);
        const OrbitCamera c = OrbitCamera::looking(eye, target);
        EXPECT_LT(glm::length(c.eye() - eye), 1e-12) << str(eye) << " -> " << str(c.eye());
        EXPECT_EQ(c.target, target);
        ++tested;
    }
}

TEST(OrbitCamera, DraggingNeverReachesThePoles) {
    const glm::dvec3 up{0, 1, 0};
    for (double dy : {1e6, -1e6, 1e9, -1e9, 359.0, -359.0}) {
        OrbitCamera c;
        c.drag(0, dy);
        EXPECT_LE(std::abs(c.elevationRad), OrbitCamera::kMaxElevationRad);
        EXPECT_GT(std::abs(c.elevationRad), 80 * kDeg) << "dy " << dy << " should reach the clamp";
        EXPECT_NO_THROW(cameraFrame(c.eye(), c.target, up));
        const glm::dvec3 w = glm::normalize(c.eye() - c.target);
        EXPECT_LT(std::abs(glm::dot(w, up)), std::sin(89.5 * kDeg)) << "dy " << dy;
    }
    // Many small drags past the pole do not accumulate beyond the clamp either.
    OrbitCamera c;
    for (int i = 0; i < 10000; ++i) c.drag(3, 1);
    EXPECT_LE(std::abs(c.elevationRad), OrbitCamera::kMaxElevationRad);
    c.drag(0, -1); // and the first drag back moves away from the pole at once
    EXPECT_LT(c.elevationRad, OrbitCamera::kMaxElevationRad);
    EXPECT_TRUE(std::isfinite(c.azimuthRad));
    EXPECT_LE(std::abs(c.azimuthRad), std::numbers::pi + 1e-12) << "azimuth kept in one turn";
}

TEST(OrbitCamera, CurrentSceneFrameNeverThrowsAfterHugeDrags) {
    for (double dy : {1e6, -1e6}) {
        DemoState state(Scene{});
        state.drag(12345.6, dy);
        const Scene s = state.current();
        EXPECT_NO_THROW(cameraFrame(s.eye, s.target, s.up));
        EXPECT_NO_THROW(sceneView(s));
        EXPECT_NO_THROW(validateScene(s));
    }
}

TEST(OrbitCamera, ZoomScalesTheDistance) {
    OrbitCamera c;
    const double d0 = c.distance;
    c.zoom(1);
    EXPECT_NEAR(c.distance, 0.9 * d0, 1e-12) << "positive steps zoom in";
    c.zoom(-1);
    EXPECT_NEAR(c.distance, d0, 1e-12);
    c.zoom(-2);
    EXPECT_NEAR(c.distance, d0 / 0.81, 1e-12);
    c.zoom(0.5);
    EXPECT_NEAR(c.distance, d0 / 0.81 * std::sqrt(0.9), 1e-12) << "fractional (touchpad) steps";
    const glm::dvec3 az{c.azimuthRad, c.elevationRad, 0};
    EXPECT_EQ(az, glm::dvec3(0, 0, 0)) << "zoom moves along the view direction only";
}

// demo_state.h: "×0.9 per step in, clamped to a sane range". Without a clamp the distance underflows to
// 0 or overflows to ∞ and the wheel then stops working in that direction for good.
TEST(OrbitCamera, ZoomStaysInASaneRange) {
    for (double steps : {1e4, -1e4}) {
        OrbitCamera c;
        c.zoom(steps);
        EXPECT_TRUE(std::isfinite(c.distance) && c.distance > 0) << "zoom(" << steps << "): " << c.distance;
        const double after = c.distance;
        c.zoom(steps > 0 ? -1 : 1);
        EXPECT_NE(c.distance, after) << "zoom(" << steps << ") then one step back does nothing";
    }
}

// Over-zooming must not create a dead zone: one wheel step out after zooming in far must move the eye.
TEST(DemoCamera, OneStepOutAfterOverZoomingInMovesTheEye) {
    DemoState state(Scene{});
    state.zoom(100);
    const double closest = glm::length(state.current().eye - state.current().target);
    state.zoom(-1);
    const double after = glm::length(state.current().eye - state.current().target);
    EXPECT_GT(after, closest) << "the wheel had to be turned back past the 100 steps the view ignored";
    DemoState out(Scene{});
    out.zoom(-100);
    const double farthest = glm::length(out.current().eye - out.current().target);
    out.zoom(1);
    EXPECT_LT(glm::length(out.current().eye - out.current().target), farthest);
}

void expectEyeOutsideObjectsAndObjectsInsideFar(const Scene& s, const std::string& context) {
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
        const double d = glm::length(s.eye - s.objects[i].center), r = boundingRadius(s.objects[i]);
        EXPECT_GT(d, r) << context << ": eye inside object " << i << " (" << d << " from its centre)";
        EXPECT_LE(d + r, s.projection.far) << context << ": object " << i << " reaches past the far plane";
    }
}

TEST(DemoCamera, ZoomKeepsTheEyeOutsideObjectsAndInsideFar) {
    for (const Scene& scene : {Scene{}, threeObjectScene()})
        for (double steps : {1000.0, -1000.0, 30.0, -30.0}) {
            DemoState state(scene);
            state.zoom(steps);
            const Scene s = state.current();
            expectEyeOutsideObjectsAndObjectsInsideFar(s, "zoom(" + std::to_string(steps) + ")");
            EXPECT_NO_THROW(sceneView(s));
        }
}

// A valid scene with a tight far plane (eye 2 from a unit sphere, far 2.6): the eye can still be kept
// outside the sphere (distance in (1.5, 1.6] clears the near plane and keeps the sphere before far).
TEST(DemoCamera, ZoomKeepsTheEyeOutsideTheSphereWithATightFarPlane) {
    Scene scene;
    scene.eye = {0, 0, 2};
    scene.projection.far = 2.6;
    validateScene(scene);
    for (double steps : {1000.0, 1e4}) {
        DemoState state(scene);
        state.zoom(steps);
        const Scene s = state.current();
        EXPECT_GT(glm::length(s.eye - s.objects[0].center), s.objects[0].radius)
            << "zoom(" << steps << "): eye " << str(s.eye);
        EXPECT_NO_THROW(sceneView(s)) << "zoom(" << steps << ")";
    }
}

Scene sceneWithLight(const Light& light) {
    Scene scene;
    scene.lights = {light};
    return scene;
}

// Right-drag orbits a point light around the target: its distance to the target stays, dragging right
// moves it towards the camera's right (+x seen from +z), dragging up raises it.
TEST(DemoLightDrag, PointLightOrbitsTheTargetKeepingItsDistance) {
    Light light = Scene::defaultLight(); // at (3, 3, 5)
    DemoState state{sceneWithLight(light)};
    const double distance = glm::length(light.position);
    state.dragLight(40, 0);
    const glm::dvec3 right = state.drawn().lights[0].position;
    EXPECT_NEAR(glm::length(right), distance, 1e-9);
    EXPECT_GT(right.x, light.position.x);
    EXPECT_NEAR(right.y, light.position.y, 1e-9) << "a horizontal drag keeps the height";
    state.dragLight(0, -40);
    EXPECT_GT(state.drawn().lights[0].position.y, right.y) << "dragging up raises the light";
    EXPECT_NE(windowTitle(state, 0).find("light 1 (point) at ("), std::string::npos) << windowTitle(state, 0);
    // The moved light is part of the scene the screenshot saves.
    EXPECT_EQ(parseScene(sceneToJson(state.drawn())).lights[0].position, state.drawn().lights[0].position);
}

// A spot's direction turns with its position, so it keeps lighting the same side of the target; a
// directional light's direction turns as if its source orbited.
TEST(DemoLightDrag, SpotDirectionTurnsWithItAndDirectionalLightTurns) {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0, 0, 5};
    spot.direction = {0, 0, -1};
    spot.cutoffDeg = 20;
    DemoState state{sceneWithLight(spot)};
    state.dragLight(180, 0); // 90° around +y
    const Light moved = state.drawn().lights[0];
    EXPECT_NEAR(moved.position.x, 5, 1e-9);
    EXPECT_NEAR(moved.position.z, 0, 1e-9);
    EXPECT_NEAR(glm::dot(glm::normalize(moved.direction), glm::dvec3(-1, 0, 0)), 1, 1e-12)
        << "still aimed at the target";

    Light directional;
    directional.type = LightType::Directional;
    directional.direction = {0, 0, -2};
    DemoState sun{sceneWithLight(directional)};
    sun.dragLight(180, 0);
    EXPECT_NEAR(glm::dot(sun.drawn().lights[0].direction, glm::dvec3(-1, 0, 0)), 1, 1e-12);
}

TEST(DemoLightDrag, OnlyAmbientLightSaysThereIsNothingToMove) {
    Light ambient;
    ambient.type = LightType::Ambient;
    ambient.ambient = {0.3, 0.3, 0.3};
    DemoState state{sceneWithLight(ambient)};
    state.dragLight(10, 10);
    EXPECT_EQ(state.lastChange(), "no light to move (only ambient light)");
    EXPECT_EQ(state.drawn().lights[0].ambient, ambient.ambient);
}

// ---- everything at once ----

TEST(DemoStateRandom, RandomCommandsDragsAndZoomsAlwaysGiveAValidScene) {
    Scene orthographic;
    orthographic.projection = {ProjectionType::Orthographic, 40, -1.6, 1.6, -1.2, 1.2, 0.5, 20};
    Scene frustum = threeObjectScene();
    frustum.projection = {ProjectionType::Frustum, 40, -0.2, 0.25, -0.2, 0.2, 0.5, 30};
    frustum.width = 640;
    frustum.height = 480;
    int sceneIndex = 0;
    for (const Scene& scene : {Scene{}, threeObjectScene(), orthographic, frustum}) {
        std::mt19937 rng(1234 + sceneIndex++);
        std::uniform_int_distribution<int> what(0, 9), commandIndex(0, int(std::size(kAllCommands)) - 1);
        std::uniform_real_distribution<double> pixels(-2000, 2000), steps(-30, 30), unit(0, 1);
        DemoState state(scene);
        for (int op = 0; op < 2000; ++op) {
            std::ostringstream context;
            context << "scene " << sceneIndex - 1 << ", op " << op << ": ";
            const int kind = what(rng);
            if (kind < 6) {
                const Command command = kAllCommands[commandIndex(rng)];
                context << "command " << int(command);
                state.apply(command);
            } else if (kind < 8) {
                const double dx = unit(rng) < 0.05 ? 1e6 : pixels(rng),
                             dy = unit(rng) < 0.05 ? -1e6 : pixels(rng);
                context << "drag " << dx << ", " << dy;
                state.drag(dx, dy);
            } else if (kind < 9) {
                const double s = steps(rng);
                context << "zoom " << s;
                state.zoom(s);
            } else {
                state.setMatchHighlight(!state.matchHighlight());
                context << "matchHighlight " << state.matchHighlight();
            }
            const Scene s = state.current();
            ASSERT_NO_THROW(validateScene(s)) << context.str();
            SceneView view;
            ASSERT_NO_THROW(view = sceneView(s)) << context.str();
            ASSERT_TRUE(allFinite(view.viewFromWorld)) << context.str();
            ASSERT_TRUE(allFinite(view.clipFromView)) << context.str();
            ASSERT_NO_THROW(cameraFrame(s.eye, s.target, s.up)) << context.str();
            ASSERT_GE(state.level(), 0);
            ASSERT_LE(state.level(), kMaxSubdivisions);
            for (const SceneObject& o : s.objects) {
                const double d = glm::length(s.eye - o.center), r = boundingRadius(o);
                ASSERT_GT(d, r) << context.str() << ": eye inside an object";
                ASSERT_LE(d + r, s.projection.far) << context.str() << ": object past the far plane";
                ASSERT_GE(o.material.shininess, 1) << context.str();
            }
            ASSERT_EQ(s.objects.size(), scene.objects.size());
        }
    }
}

} // namespace
} // namespace shadelab::app
