// The ranges of DESIGN §4 (the message pieces are scene_messages.cpp, the whole-scene limits
// scene_limits.cpp). One set of check* functions serves both parseScene (per entity, as it is read) and
// validateScene (after flags or code change a scene), so the two can never disagree about what a valid scene
// is; the checks a flag shares are public (scene_values.h).
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "scene/scene_internal.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/auto_level.h"
#include "shadelab/scene/camera.h"
#include "shadelab/scene/observer.h"

namespace shadelab::detail {

// ---- range checks ----

void checkFinite(double value, std::string_view path) {
    if (!std::isfinite(value)) fail(path, "must be finite, got " + formatNumber(value));
}

void checkIntRange(int value, IntRange range, std::string_view path) {
    if (value < range.lo || value > range.hi) failOutOfRange(range, std::to_string(value), path);
}

namespace {

// A perspective's vertical field of view stays below a half turn (tan(fovy/2) is infinite there), a spot's
// cutoff at most a quarter turn (DESIGN §4: 0 ≤ cutoff_deg ≤ 90).
constexpr double kFovyDegBelow = 180, kMaxCutoffDeg = 90;

void checkGreater(double value, double min, std::string_view path) {
    checkFinite(value, path);
    if (!(value > min)) fail(path, "must be > " + formatNumber(min) + ", got " + formatNumber(value));
}

void checkAtLeast(double value, double min, std::string_view path) {
    checkFinite(value, path);
    if (!(value >= min)) fail(path, "must be >= " + formatNumber(min) + ", got " + formatNumber(value));
}

void checkFiniteVec(const glm::dvec3& v, std::string_view path) {
    for (int i = 0; i < 3; ++i) checkFinite(v[i], indexPath(path, i));
}

void checkColor(const glm::dvec3& color, std::string_view path) {
    for (int i = 0; i < 3; ++i) checkAtLeast(color[i], 0, indexPath(path, i));
}

void checkNonZeroVec(const glm::dvec3& v, std::string_view path) {
    checkFiniteVec(v, path);
    if (v == glm::dvec3(0)) fail(path, "must be non-zero, got " + formatVec(v));
}

void checkDistinct(double value, double other, std::string_view otherName, std::string_view path) {
    checkFinite(value, path);
    if (value == other)
        fail(path, "must differ from " + std::string(otherName) + " (" + formatNumber(other) + "), got " +
                       formatNumber(value));
}

// The values that feed the GPU's matrices and uniforms reach it as 32-bit float (DESIGN §2: composed in
// double, uploaded as float; normal range 1.2e-38..3.4e38, and the entries are products and quotients of
// these values): outside kMinFloatExtent..kMaxFloatExtent in magnitude one became 0 or Inf there and drew
// nothing. Refuse what float cannot carry instead of drawing a wrong picture; a scene that needs more can
// change its units.
bool carriedByFloat(double magnitude) {
    return magnitude >= kMinFloatExtent && magnitude <= kMaxFloatExtent;
}

std::string floatRange() {
    return "between " + formatNumber(kMinFloatExtent) + " and " + formatNumber(kMaxFloatExtent);
}

// `value` itself; 0 passes (a plane through the eye, a missing attenuation term) where no other check has
// refused it already.
void checkCarriedByFloat(double value, std::string_view path, std::string_view carrier,
                         bool zeroAllowed = true) {
    if (value != 0 && !carriedByFloat(std::abs(value)))
        fail(path, std::string(zeroAllowed ? "must be 0 or " : "must be ") + floatRange() +
                       " in magnitude (" + std::string(carrier) + " 32-bit float on the GPU), got " +
                       formatNumber(value) + "; change the scene's units");
}

// A difference the projection divides by (right - left, top - bottom, far - near), named by its first
// field: the message gives the field's own value and the difference.
void checkDifferenceCarriedByFloat(double value, double other, std::string_view name,
                                   std::string_view otherName, std::string_view path) {
    const double difference = value - other;
    if (!carriedByFloat(std::abs(difference)))
        fail(path,
             "got " + formatNumber(value) + ", which makes " + std::string(name) + " - " +
                 std::string(otherName) + " " + formatNumber(difference) +
                 "; the projection divides by that difference in 32-bit float on the GPU, so it must be " +
                 floatRange() + " in magnitude: change the scene's units");
}

void checkMaterial(const Material& m, const std::string& path) {
    checkColor(m.ambient, keyPath(path, "ambient"));
    checkColor(m.diffuse, keyPath(path, "diffuse"));
    checkColor(m.specular, keyPath(path, "specular"));
    // pow(0, 0) is undefined in GLSL (DESIGN §3).
    checkAtLeast(m.shininess, 1, keyPath(path, "shininess"));
}

void checkAttenuation(const glm::dvec3& a, const std::string& path) {
    for (int i = 0; i < 3; ++i) {
        checkAtLeast(a[i], 0, indexPath(path, i));
        // A tiny term becomes 0 in the float uniform and the light grows unbounded; a huge one becomes Inf,
        // which gives att = 0 as the reference's ~0 does
        // (egl.Lighting.HugeQuadraticAttenuationLooksAmbientOnly).
        if (a[i] != 0 && a[i] < kMinFloatExtent)
            fail(indexPath(path, i), "must be 0 or at least " + formatNumber(kMinFloatExtent) +
                                         " (attenuation is 32-bit float on the GPU), got " +
                                         formatNumber(a[i]) + "; use 0 for no such term");
    }
    if (!(a.x + a.y + a.z > 0)) fail(path, "components must have a positive sum, got " + formatVec(a));
}

} // namespace

void checkViewAt(double at) {
    checkFinite(at, "view_at");
    if (!(at >= 0 && at <= 1))
        fail("view_at", "must be between 0 and 1 (a fraction of the picture), got " + formatNumber(at));
}

void checkObserver(const Observer& observer) {
    checkFinite(observer.azimuthDeg, "view_observer[0]");
    checkFinite(observer.elevationDeg, "view_observer[1]");
    if (!(std::abs(observer.elevationDeg) <= kMaxObserverElevationDeg))
        fail("view_observer[1]", "the observer's elevation must be between " +
                                     formatNumber(-kMaxObserverElevationDeg) + " and " +
                                     formatNumber(kMaxObserverElevationDeg) + " degrees, got " +
                                     formatNumber(observer.elevationDeg));
    if (!(observer.zoom >= kMinObserverZoom && observer.zoom <= kMaxObserverZoom))
        fail("view_observer[2]", "the observer's zoom must be between " + formatNumber(kMinObserverZoom) +
                                     " and " + formatNumber(kMaxObserverZoom) +
                                     " (1: everything framed), got " + formatNumber(observer.zoom));
}

void checkSceneSize(const Scene& scene) {
    shadelab::checkImageSize(scene.width, "image.width");
    shadelab::checkImageSize(scene.height, "image.height");
}

void checkImage(const Scene& scene) {
    checkSceneSize(scene);
    checkColor(scene.background, "image.background");
}

void checkCamera(const Scene& scene) {
    checkFiniteVec(scene.eye, "camera.eye");
    checkFiniteVec(scene.target, "camera.target");
    checkFiniteVec(scene.up, "camera.up");
    try {
        cameraFrame(scene.eye, scene.target, scene.up);
    } catch (const InputError& e) {
        failWithin("camera", e);
    }
}

namespace {

// The window of a frustum or an orthographic projection: its planes, its widths and, for a frustum, the
// matrix's 2·near/width (the cotangent of half the field of view).
void checkWindow(const Projection& p) {
    checkCarriedByFloat(p.left, "projection.left", "the projection is");
    checkCarriedByFloat(p.right, "projection.right", "the projection is");
    checkCarriedByFloat(p.bottom, "projection.bottom", "the projection is");
    checkCarriedByFloat(p.top, "projection.top", "the projection is");
    checkDifferenceCarriedByFloat(p.right, p.left, "right", "left", "projection.right");
    checkDifferenceCarriedByFloat(p.top, p.bottom, "top", "bottom", "projection.top");
    if (p.type != ProjectionType::Frustum) return;
    // 2·near/(value − other) in float; the message names `value`'s field.
    auto checkSlope = [&](double value, double other, std::string_view name, std::string_view otherName) {
        const double slope = 2 * p.near / std::abs(value - other);
        if (!carriedByFloat(slope))
            fail("projection." + std::string(name),
                 "got " + formatNumber(value) + ", which with " + std::string(otherName) + " " +
                     formatNumber(other) + " and near " + formatNumber(p.near) +
                     " makes the frustum matrix's 2 near / (" + std::string(name) + " - " +
                     std::string(otherName) + ") " + formatNumber(slope) +
                     ", which 32-bit float cannot carry (" + floatRange() + "): " +
                     (slope > 1 ? "widen the window or lower near" : "narrow the window or raise near"));
    };
    checkSlope(p.right, p.left, "right", "left");
    checkSlope(p.top, p.bottom, "top", "bottom");
}

} // namespace

void checkProjection(const Projection& p) {
    if (p.type == ProjectionType::Perspective) {
        checkGreater(p.fovyDeg, 0, "projection.fovy_deg");
        if (!(p.fovyDeg < kFovyDegBelow))
            fail("projection.fovy_deg",
                 "must be < " + formatNumber(kFovyDegBelow) + ", got " + formatNumber(p.fovyDeg));
        // The projection holds cot(fovy/2) in 32-bit float and scales depth by it: narrower views lose the
        // picture (4.9e-324 made the window zero-wide). 1e-6 degrees keeps it near 1e8.
        if (p.fovyDeg < kMinFovyDeg)
            fail("projection.fovy_deg",
                 "must be at least " + formatNumber(kMinFovyDeg) +
                     " degrees (a narrower view does not fit 32-bit float matrices), got " +
                     formatNumber(p.fovyDeg));
    } else {
        checkFinite(p.left, "projection.left");
        checkDistinct(p.right, p.left, "left", "projection.right");
        checkFinite(p.bottom, "projection.bottom");
        checkDistinct(p.top, p.bottom, "bottom", "projection.top");
    }
    checkGreater(p.near, 0, "projection.near");
    checkFinite(p.far, "projection.far");
    if (!(p.far > p.near))
        fail("projection.far", "must be > near (" + formatNumber(p.near) + "), got " + formatNumber(p.far));
    checkCarriedByFloat(p.near, "projection.near", "the projection is", false);
    checkCarriedByFloat(p.far, "projection.far", "the projection is", false);
    checkDifferenceCarriedByFloat(p.far, p.near, "far", "near", "projection.far");
    if (p.type != ProjectionType::Perspective) checkWindow(p);
}

void checkObject(const SceneObject& object, const std::string& path) {
    checkFiniteVec(object.center, keyPath(path, "center"));
    checkGreater(object.radius, 0, keyPath(path, "radius"));
    std::string scalePath = keyPath(path, "scale");
    checkFiniteVec(object.scale, scalePath);
    // Negative components mirror (allowed); zero flattens the ellipsoid and its normal matrix.
    checkCarriedByFloat(object.radius, keyPath(path, "radius"), "the model matrix is", false);
    for (int i = 0; i < 3; ++i) {
        const std::string componentPath = indexPath(scalePath, i);
        if (object.scale[i] == 0) fail(componentPath, "must be non-zero, got 0");
        // The model matrix holds radius·scale: each semi-axis of the ellipsoid.
        const double semiAxis = object.radius * std::abs(object.scale[i]);
        if (!carriedByFloat(semiAxis))
            fail(componentPath, "got " + formatNumber(object.scale[i]) +
                                    ", which makes the semi-axis radius x " + "scale[" + std::to_string(i) +
                                    "] " + formatNumber(semiAxis) +
                                    "; the model matrix is 32-bit float on the GPU, so it must be " +
                                    floatRange() + ": change the scene's units");
    }
    if (object.shape == Shape::Mesh)
        checkMeshPath(object.mesh, keyPath(path, "mesh")); // a mesh object's level is unused
    else
        checkSubdivisions(object.shape, object.subdivisions, keyPath(path, "subdivisions"));
    checkMaterial(object.material, keyPath(path, "material"));
}

void checkObjectCount(std::size_t count) {
    if (count > kMaxObjects)
        fail("objects", "at most " + std::to_string(kMaxObjects) + " objects are supported, got " +
                            std::to_string(count) + "; draw fewer objects");
}

void checkLightCount(std::size_t count) {
    if (count > static_cast<std::size_t>(kMaxLights))
        fail("lights",
             "at most " + std::to_string(kMaxLights) + " lights are supported, got " + std::to_string(count));
}

bool hasPosition(LightType type) {
    return type == LightType::Point || type == LightType::Spot;
}
bool hasDirection(LightType type) {
    return type == LightType::Directional || type == LightType::Spot;
}

// Only the fields the light's type uses are checked: the others are ignored by the lighting code.
void checkLight(const Light& light, const std::string& path) {
    checkColor(light.ambient, keyPath(path, "ambient"));
    checkColor(light.diffuse, keyPath(path, "diffuse"));
    checkColor(light.specular, keyPath(path, "specular"));
    if (hasPosition(light.type)) {
        checkFiniteVec(light.position, keyPath(path, "position"));
        checkAttenuation(light.attenuation, keyPath(path, "attenuation"));
    }
    if (hasDirection(light.type)) checkNonZeroVec(light.direction, keyPath(path, "direction"));
    if (light.type == LightType::Spot) {
        std::string cutoffPath = keyPath(path, "cutoff_deg");
        checkAtLeast(light.cutoffDeg, 0, cutoffPath);
        if (!(light.cutoffDeg <= kMaxCutoffDeg))
            fail(cutoffPath,
                 "must be <= " + formatNumber(kMaxCutoffDeg) + ", got " + formatNumber(light.cutoffDeg));
        checkAtLeast(light.exponent, 0, keyPath(path, "exponent"));
    }
}

} // namespace shadelab::detail

namespace shadelab {

using namespace detail;

std::string toString(IntRange range) {
    return std::to_string(range.lo) + ".." + std::to_string(range.hi);
}

void checkImageSize(int pixels, std::string_view field) {
    checkIntRange(pixels, kImageSizeRange, field);
}

void checkTolerancePx(double pixels, std::string_view field) {
    checkGreater(pixels, 0, field);
}

View parseViewOrThrow(std::string_view text, std::string_view field) {
    ViewParse parsed = parseView(text);
    if (!parsed.view) fail(field, quotedValue(text) + ": " + parsed.error);
    return *parsed.view;
}

void failNotFinite(std::string_view field, std::string_view written) {
    const std::string shown = written.size() > kMaxQuotedChars
                                  ? std::string(written.substr(0, kMaxQuotedChars)) + "..."
                                  : std::string(written);
    fail(field, "must be finite, got " + shown);
}

void validateScene(const Scene& scene) {
    validateSceneValues(scene);
    checkSceneLimits(scene);
}

void validateSceneValues(const Scene& scene) {
    checkImage(scene);
    checkIntRange(scene.toonBands, kToonBandRange, "toon_bands");
    checkTolerancePx(scene.tolerancePx, "tolerance_px");
    checkCamera(scene);
    checkProjection(scene.projection);
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        checkObject(scene.objects[i], indexPath("objects", i));
    checkLightCount(scene.lights.size());
    for (std::size_t i = 0; i < scene.lights.size(); ++i) checkLight(scene.lights[i], indexPath("lights", i));
    checkPlacement(scene);
    checkSplitLevels(scene);
    if (scene.view.at) checkViewAt(*scene.view.at);
    checkObserver(scene.view.observer);
    // The NDC view transforms the mesh; exact shading has none (also as a split's side).
    auto exactNdc = [&](const SplitSide& side) {
        return side.view == ViewKind::Ndc && side.shading.value_or(scene.shading) == ShadingMode::Exact;
    };
    const View& view = scene.view;
    if ((view.kind == ViewKind::Ndc && scene.shading == ShadingMode::Exact) ||
        (view.kind == ViewKind::Split && (exactNdc(view.left) || exactNdc(view.right))))
        fail("view",
             "ndc draws the mesh through M_proj·M_cam, and exact shading ray-casts the sphere without "
             "one; choose flat, gouraud, phong or toon shading for the NDC view");
    (void)sceneView(scene); // the derived matrices must be finite too
    checkOutsideView(scene);
    checkObjectCount(scene.objects.size());
}

} // namespace shadelab
