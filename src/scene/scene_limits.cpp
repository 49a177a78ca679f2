// The limits of a scene as a whole (DESIGN §4, docs/ci-engineers.md "Limits"), beside the per-value ranges of
// scene_check.cpp: the work it asks for (triangles per frame, the reference's ray tests), the standard-depth
// range, and where its objects and lights lie from the eye in 32-bit float.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "scene/scene_internal.h"
#include "shadelab/geometry/teapot.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/auto_level.h"
#include "shadelab/scene/camera.h"

namespace shadelab::detail {

namespace {

// |point - eye| without overflowing on the way (scaled by the largest component, as unitDirection does),
// and in words: "lies 2e+31 from the eye [0, 0, 4]".
std::string distanceFromEye(const glm::dvec3& point, const Scene& scene, double& distance) {
    const glm::dvec3 d = point - scene.eye;
    const double k = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    distance = k == 0 ? 0 : std::isfinite(k) ? k * glm::length(d / k) : k;
    return "lies " + (std::isfinite(distance) ? formatNumber(distance) : std::string("beyond double range")) +
           " from the eye " + formatVec(scene.eye);
}

// The smallest semi-axis of `object`, and which scale component makes it.
int thinnestAxis(const SceneObject& object) {
    const glm::dvec3 s = glm::abs(object.scale);
    return s.x <= s.y && s.x <= s.z ? 0 : s.y <= s.z ? 1 : 2;
}

// An object within float's reach of the eye, in the eye's units and in its own (kMaxRayCastReach).
void checkObjectPlacement(const Scene& scene, const SceneObject& object, const std::string& path) {
    double distance = 0;
    const std::string where = distanceFromEye(object.center, scene, distance);
    if (!(distance <= kMaxFloatExtent))
        fail(keyPath(path, "center"), where + ", beyond " + formatNumber(kMaxFloatExtent) +
                                          " (view-space positions are 32-bit float on the GPU), got " +
                                          formatVec(object.center) + "; move it or the eye");
    const int axis = thinnestAxis(object);
    const double semiAxis = object.radius * std::abs(object.scale[axis]);
    const double extent =
        object.radius * boundingRadius(object) *
        std::max({std::abs(object.scale.x), std::abs(object.scale.y), std::abs(object.scale.z)});
    // An orthographic ray's direction is the unit vector, 1/semiAxis long in the object's units.
    const bool orthographic = scene.projection.type == ProjectionType::Orthographic;
    const double reach = orthographic ? std::max(distance + extent, 1.0) : distance + extent;
    if (reach / semiAxis > kMaxRayCastReach)
        fail(indexPath(keyPath(path, "scale"), axis),
             "got " + formatNumber(object.scale[axis]) + ", which makes the semi-axis radius x scale[" +
                 std::to_string(axis) + "] " + formatNumber(semiAxis) + " while the object reaches " +
                 formatNumber(reach) + " from the eye: " + formatNumber(reach / semiAxis) +
                 " of those semi-axes, and exact shading squares that in 32-bit float (at most " +
                 formatNumber(kMaxRayCastReach) + "): make the semi-axis at least " +
                 formatNumber(reach / kMaxRayCastReach) + " or bring the eye closer");
}

} // namespace

// Eye-relative values, so checked once the camera, the objects and the lights are all known: the view-space
// positions the GPU receives (DESIGN §2 composes them in double, camera-relative) must be float too.
void checkPlacement(const Scene& scene) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        checkObjectPlacement(scene, scene.objects[i], indexPath("objects", i));
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        if (!hasPosition(light.type)) continue;
        double distance = 0;
        const std::string where = distanceFromEye(light.position, scene, distance);
        if (!(distance <= kMaxFloatExtent))
            fail(keyPath(indexPath("lights", i), "position"),
                 where + ", beyond " + formatNumber(kMaxFloatExtent) +
                     " (view-space positions are 32-bit float on the GPU), got " + formatVec(light.position) +
                     "; move it closer (a light that far is a directional light)");
    }
}

} // namespace shadelab::detail

namespace shadelab {

using namespace detail;

namespace {

// The triangles one object draws at `level`. A mesh object's model, which its count needs, is read by
// loadSceneModels (scene/model.h) after parsing; a split's @level beyond the teapot's is checkSplitLevels'.
double trianglesDrawn(const SceneObject& object, std::size_t index, int level) {
    if (object.shape == Shape::Mesh && !object.model)
        fail(keyPath(indexPath("objects", index), "mesh"),
             quotedValue(object.mesh) +
                 " is not loaded, so the triangles it draws cannot be counted; read the scene's models "
                 "(loadSceneModels) before drawing it");
    if (object.shape == Shape::Teapot) level = std::clamp(level, 0, kMaxTeapotLevel);
    return double(triangleCount(object, level));
}

// The reference's cost of one ray against one object, in ray-sphere tests (each ~20 ns): 1 for the sphere (a
// quadratic). Measured on 512×512 (src/exact: median of 3, 2 threads): a teapot ray walks ~62 patch boxes
// and runs ~2.3 Newton solves, 160–220 sphere tests' time, counted as 256; a mesh ray walks ~48 boxes and
// ~8 triangles of a 1 M-triangle tree, 85–110 sphere tests' time, counted as 6·⌈log₂ T⌉ (120 at 1 M).
double rayTestsPerPixel(const SceneObject& object, std::size_t index, int level) {
    if (object.shape == Shape::Sphere) return 1;
    if (object.shape == Shape::Teapot) return 256;
    const auto triangles = static_cast<std::uint64_t>(trianglesDrawn(object, index, level));
    return 6 * double(std::max<std::uint64_t>(1, std::bit_width(triangles > 0 ? triangles - 1 : 0)));
}

// The work a scene asks for, bounded before any of it is done (docs/ci-engineers.md "Limits"): the triangles
// drawn per frame, and the ray-object tests of the analytic reference (pixels × objects, a teapot or mesh
// weighted by its hierarchy), which render and reference share as one notion of a valid scene.
void checkWork(const Scene& scene) {
    // A split view draws every object once per side, each side at its own level where it sets one.
    const bool split = scene.view.kind == ViewKind::Split;
    double triangles = 0, testsPerPixel = 0;
    bool onlySpheres = true;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        onlySpheres = onlySpheres && object.shape == Shape::Sphere;
        const int level = subdivisionLevel(scene, object);
        testsPerPixel += rayTestsPerPixel(object, i, level);
        if (!split) {
            triangles += trianglesDrawn(object, i, level);
            continue;
        }
        for (const SplitSide* side : {&scene.view.left, &scene.view.right})
            triangles += trianglesDrawn(object, i, side->level.value_or(level));
    }
    if (triangles > double(kMaxTrianglesPerFrame))
        fail(split ? "view" : "objects",
             "the scene draws " + formatNumber(triangles) + " triangles per frame (each " +
                 (onlySpheres ? "object 4^(level+1)"
                              : "sphere 4^(level+1), teapot 64 x 4^level, mesh its file's") +
                 (split ? ", once per side of the split" : "") + "); at most " +
                 std::to_string(kMaxTrianglesPerFrame) + " are allowed: lower the subdivisions" +
                 (split ? " (the sides' @levels included)" : "") + " or draw fewer objects");
    const double rayTests = double(scene.width) * scene.height * testsPerPixel;
    if (rayTests > double(kMaxReferenceRayTests))
        fail("objects", "the analytic reference would test " + formatNumber(rayTests) +
                            " rays against objects (width x height x objects" +
                            (onlySpheres ? "" : ", a teapot 256 times, a mesh 6 x log2(its triangles)") +
                            "); at most " + std::to_string(kMaxReferenceRayTests) +
                            " are allowed: use a smaller image or fewer objects");
}

// Standard depth (DESIGN's [-1, 1] mapping, near → +1, far → −1) puts a point at distance d ≫ near at
// NDC z ≈ −1 + 2·near/d, so its depth (z + 1)/2 ≈ near/d: past d ≈ 3e7·near that is below half a 24-bit
// step (3e-8) and rounds to 0, the clear value, which GL_GREATER never passes, and whole objects vanish
// (measured: the default sphere at d = 3 loses a third of its pixels with near 1e-7 and vanishes with near
// 1e-10, while the reversed modes draw it whole). Refuse before that, with a margin.
void checkStandardDepthRange(const Scene& scene) {
    if (scene.depth != DepthMode::Standard || scene.projection.type != ProjectionType::Perspective) return;
    const double near = scene.projection.near;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        const double extent = std::abs(o.radius) * boundingRadius(o) *
                              std::max({std::abs(o.scale.x), std::abs(o.scale.y), std::abs(o.scale.z)});
        const double farthest = std::min(glm::length(o.center - scene.eye) + extent, scene.projection.far);
        if (farthest / near > kMaxStandardDepthRatio)
            fail("projection.near",
                 "with \"depth\": \"standard\", " + indexPath("objects", i) + " reaches " +
                     formatNumber(farthest / near) +
                     " x near from the eye; the depth buffer rounds points beyond " +
                     formatNumber(kMaxStandardDepthRatio) +
                     " x near to depth 0, the far plane's and the clear value, which the depth test never "
                     "passes: raise near to at least " +
                     formatNumber(farthest / kMaxStandardDepthRatio) + " or use \"depth\": \"reversed\"");
    }
}

} // namespace

void checkSceneLimits(const Scene& scene) {
    checkWork(scene);
    checkStandardDepthRange(scene);
}

} // namespace shadelab
