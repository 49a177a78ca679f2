#include "shadelab/scene/outside_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <tuple>

#include "shadelab/errors.h"
#include "shadelab/scene/camera.h"

namespace shadelab {
namespace {

constexpr double kDegree = std::numbers::pi / 180;
constexpr double kObserverFovyDeg = 40;

// The view volume is the same set of points whichever matrix draws it: the −1 cancels in the divide, and
// reversed-Z only renumbers depth. Its corners come from the standard WebGL matrix (DESIGN §2), whose NDC
// cube is [−1, 1]³.
Scene standardVolume(const Scene& scene) {
    Scene standard = scene;
    standard.depth = DepthMode::Standard;
    standard.perspectiveMatrix = PerspectiveMatrix::WebGl;
    return standard;
}

// Where the objects reach along the view direction, from the eye: the deepest object point's distance.
double objectsReach(const Scene& scene, const CameraFrame& frame) {
    double reach = 0;
    for (const SceneObject& o : scene.objects) {
        const double extent =
            o.radius * std::max({std::abs(o.scale.x), std::abs(o.scale.y), std::abs(o.scale.z)});
        reach = std::max(reach, -glm::dot(o.center - frame.eye, frame.w) + extent);
    }
    return reach;
}

// The points the observer frames: e, the near plane, the volume as deep as the objects reach (and to the
// far plane when that is at most twice as deep), the objects' boxes, the lights' positions; with the
// unnegated matrix, the point reflection of the volume through e too.
std::vector<glm::dvec3> framedPoints(const Scene& scene) {
    const CameraFrame frame = cameraFrame(scene.eye, scene.target, scene.up);
    const auto corners = viewVolumeCornersWorld(scene);
    const double near = scene.projection.near, far = scene.projection.far;
    const double depth = std::max(objectsReach(scene, frame), glm::length(scene.eye - scene.target));
    const double shown = far <= 2 * depth ? far : std::clamp(1.2 * depth, near, far);
    std::vector<glm::dvec3> points{scene.eye};
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::dvec3 nearCorner = corners[i + 4], farCorner = corners[i];
        // Along the edge from near to far, linear in view depth for both projections.
        const glm::dvec3 deep = nearCorner + (farCorner - nearCorner) * ((shown - near) / (far - near));
        points.insert(points.end(), {nearCorner, deep});
    }
    if (leavesOutTheMinusOne(scene)) {
        const std::size_t count = points.size();
        for (std::size_t i = 1; i < count; ++i) points.push_back(2.0 * scene.eye - points[i]);
    }
    for (const SceneObject& o : scene.objects) {
        const glm::dvec3 half = o.radius * glm::abs(o.scale);
        for (int i = 0; i < 8; ++i)
            points.push_back(o.center + glm::dvec3(i & 1 ? half.x : -half.x, i & 2 ? half.y : -half.y,
                                                   i & 4 ? half.z : -half.z));
    }
    for (const Light& light : scene.lights)
        if (light.type == LightType::Point || light.type == LightType::Spot) points.push_back(light.position);
    return points;
}

void addLine(std::vector<LineVertex>& lines, const glm::dvec3& a, const glm::dvec3& b, glm::vec3 color) {
    lines.push_back({glm::vec3(a), color});
    lines.push_back({glm::vec3(b), color});
}

// Two unit vectors perpendicular to `axis` and to each other.
std::pair<glm::dvec3, glm::dvec3> perpendiculars(const glm::dvec3& axis) {
    const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 a = glm::normalize(glm::cross(axis, helper));
    return {a, glm::cross(axis, a)};
}

void addCircle(std::vector<LineVertex>& lines, const glm::dvec3& centre, const glm::dvec3& a,
               const glm::dvec3& b, double radius, glm::vec3 color) {
    constexpr int kSegments = 32;
    for (int i = 0; i < kSegments; ++i) {
        const double t0 = 2 * std::numbers::pi * i / kSegments,
                     t1 = 2 * std::numbers::pi * (i + 1) / kSegments;
        addLine(lines, centre + radius * (std::cos(t0) * a + std::sin(t0) * b),
                centre + radius * (std::cos(t1) * a + std::sin(t1) * b), color);
    }
}

void addArrow(std::vector<LineVertex>& lines, const glm::dvec3& from, const glm::dvec3& to, glm::vec3 color) {
    addLine(lines, from, to, color);
    const glm::dvec3 along = to - from;
    const auto [a, b] = perpendiculars(glm::normalize(along));
    for (const glm::dvec3& side : {a, -a, b, -b})
        addLine(lines, to, to - 0.2 * along + 0.08 * glm::length(along) * side, color);
}

// A light's colour as a marker: its diffuse colour at full brightness (white for a black one).
glm::vec3 markerColor(const Light& light) {
    const double brightest = std::max({light.diffuse.x, light.diffuse.y, light.diffuse.z});
    return brightest > 0 ? glm::vec3(light.diffuse / brightest) : glm::vec3(1);
}

void addLightMarker(OutsideDrawing& drawing, const Light& light, const Scene& scene, double size) {
    const glm::vec3 color = markerColor(light);
    switch (light.type) {
    case LightType::Ambient:
        return; // everywhere and from nowhere
    case LightType::Point:
        // A small wire sphere: three great circles.
        addCircle(drawing.lines, light.position, {1, 0, 0}, {0, 1, 0}, size, color);
        addCircle(drawing.lines, light.position, {0, 1, 0}, {0, 0, 1}, size, color);
        addCircle(drawing.lines, light.position, {0, 0, 1}, {1, 0, 0}, size, color);
        drawing.labels.push_back({light.position + glm::dvec3(size, size, 0), "point light"});
        return;
    case LightType::Directional: {
        // Three parallel arrows travelling in the light's direction, ending beside the target.
        const glm::dvec3 d = glm::normalize(light.direction);
        const auto [a, b] = perpendiculars(d);
        const double length = 4 * size;
        for (const glm::dvec3& offset : {glm::dvec3(0), 2 * size * a, -2 * size * a}) {
            const glm::dvec3 tip = scene.target - 3 * size * d + offset + 0.5 * size * b;
            addArrow(drawing.lines, tip - length * d, tip, color);
        }
        drawing.labels.push_back({scene.target - (3 * size + length) * d, "directional light"});
        return;
    }
    case LightType::Spot: {
        // The cone at the cutoff angle, as long as the way to the target (a cutoff past 80° is drawn at
        // 80°: the cone is then a near-flat disc).
        const glm::dvec3 d = glm::normalize(light.direction);
        const auto [a, b] = perpendiculars(d);
        const double length = std::max(glm::length(scene.target - light.position), 2 * size);
        const double radius = length * std::tan(std::min(light.cutoffDeg, 80.0) * kDegree);
        const glm::dvec3 base = light.position + length * d;
        addCircle(drawing.lines, base, a, b, radius, color);
        for (int i = 0; i < 8; ++i) {
            const double t = 2 * std::numbers::pi * i / 8;
            addLine(drawing.lines, light.position, base + radius * (std::cos(t) * a + std::sin(t) * b),
                    color);
        }
        char text[64];
        std::snprintf(text, sizeof text, "spot light, cutoff %g deg", light.cutoffDeg);
        drawing.labels.push_back({light.position, text});
        return;
    }
    }
}

} // namespace

std::array<glm::dvec3, 8> viewVolumeCornersWorld(const Scene& scene) {
    const SceneView view = sceneView(standardVolume(scene));
    const glm::dmat4 worldFromClip = glm::inverse(view.clipFromView * view.viewFromWorld);
    std::array<glm::dvec3, 8> corners;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 p = worldFromClip * glm::dvec4(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1, 1);
        corners[std::size_t(i)] = glm::dvec3(p) / p.w;
    }
    return corners;
}

// Where an observer stands: `zoom` times the distance at which a sphere of `framedRadius` fits the
// narrower of its two fields of view, away from `centre` in the direction view_observer gives in the axes
// (right, up, back); the plain view, the WebGL matrix and standard depth. The caller sets its depth range.
struct Standpoint {
    Scene observer;
    glm::dvec3 direction;
    double distance;
};
Standpoint standpoint(const Scene& scene, const glm::dvec3& centre, double framedRadius,
                      const glm::dvec3& right, const glm::dvec3& up, const glm::dvec3& back) {
    const Observer& o = scene.view.observer;
    const double azimuth = o.azimuthDeg * kDegree, elevation = o.elevationDeg * kDegree;
    const glm::dvec3 direction =
        std::cos(elevation) * (std::sin(azimuth) * right + std::cos(azimuth) * back) +
        std::sin(elevation) * up;
    const double halfY = 0.5 * kObserverFovyDeg * kDegree;
    const double halfX = std::atan(std::tan(halfY) * scene.width / scene.height);
    const double distance = o.zoom * framedRadius / std::sin(std::min(halfX, halfY));
    Scene observer = scene;
    observer.eye = centre + distance * direction;
    observer.target = centre;
    observer.up = up;
    observer.view = View{};
    observer.perspectiveMatrix = PerspectiveMatrix::WebGl;
    observer.depth = DepthMode::Standard;
    return {observer, direction, distance};
}

Scene observerScene(const Scene& scene) {
    const CameraFrame frame = cameraFrame(scene.eye, scene.target, scene.up);
    const std::vector<glm::dvec3> points = framedPoints(scene);
    glm::dvec3 low = points[0], high = points[0];
    for (const glm::dvec3& p : points) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    const glm::dvec3 centre = 0.5 * (low + high);
    double radius = 0;
    for (const glm::dvec3& p : points) radius = std::max(radius, glm::length(p - centre));

    auto [observer, direction, distance] = standpoint(scene, centre, radius, frame.u, frame.v, frame.w);
    // Depth from just short of the framed sphere (or a thousandth of the distance, zoomed into it) to the
    // real far plane's corners, which are drawn even when not framed, but at most a million near distances:
    // a far plane at 1e6 must not push the near plane past the objects.
    double deepest = distance + radius;
    for (const glm::dvec3& corner : viewVolumeCornersWorld(scene))
        deepest = std::max(deepest, glm::dot(centre - corner, direction) + distance);
    const double near = std::max(distance - 1.05 * radius, distance * 1e-3);
    observer.projection = {ProjectionType::Perspective,         kObserverFovyDeg, -1, 1, -1, 1, near,
                           std::min(1.05 * deepest, 1e6 * near)};
    return observer;
}

void checkOutsideView(const Scene& scene) {
    const View& view = scene.view;
    const bool split = view.kind == ViewKind::Split;
    const bool outside =
        view.kind == ViewKind::Outside ||
        (split && (view.left.view == ViewKind::Outside || view.right.view == ViewKind::Outside));
    if (!outside) return;
    Scene sized = scene; // a split side is half the picture wide, which changes the observer's framing
    if (split) sized.width = std::max(1, scene.width / 2);
    try {
        (void)sceneView(observerScene(sized));
    } catch (const InputError& e) {
        throw InputError("view: the outside view's observer frames the eye, the view volume and every object "
                         "and light, and its own camera leaves 32-bit float range (" +
                         std::string(e.what()) +
                         "); bring the objects and lights nearer the camera, or choose another view");
    }
}

Scene ndcObserverScene(const Scene& scene) {
    const double radius = std::sqrt(3.0); // the cube's circumscribed sphere
    auto [observer, direction, distance] =
        standpoint(scene, {0, 0, 0}, 1.05 * radius, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
    observer.projection = {ProjectionType::Perspective,
                           kObserverFovyDeg,
                           -1,
                           1,
                           -1,
                           1,
                           std::max(distance - 1.1 * radius, distance * 1e-3),
                           distance + 1.1 * radius};
    return observer;
}

OutsideDrawing ndcCubeDrawing() {
    OutsideDrawing drawing;
    std::array<glm::dvec3, 8> corners;
    for (int i = 0; i < 8; ++i) corners[std::size_t(i)] = {i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1};
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
            addLine(drawing.lines, corners[std::size_t(i)], corners[std::size_t(i ^ bit)], kCubeEdgeColor);
    for (const auto& [indices, color] : {std::pair{std::array{4, 5, 7, 6}, kNearFaceColor},
                                         std::pair{std::array{0, 1, 3, 2}, kFarFaceColor}})
        for (int k : {0, 1, 2, 0, 2, 3})
            drawing.faces.push_back({glm::vec3(corners[std::size_t(indices[std::size_t(k)])]), color});
    // At corners, clear of the objects in the middle.
    drawing.labels.push_back({corners[4], "near: z = +1", true});
    drawing.labels.push_back({corners[1], "far: z = -1"});
    drawing.labels.push_back({corners[6], "(-1, 1, 1)", true});
    drawing.labels.push_back({corners[3], "(1, 1, -1)"});
    return drawing;
}

std::vector<LineVertex> lightMarkers(const Scene& scene) {
    OutsideDrawing drawing;
    for (const Light& light : scene.lights)
        addLightMarker(drawing, light, scene, 0.08 * glm::length(scene.eye - scene.target));
    return drawing.lines;
}

OutsideDrawing outsideDrawing(const Scene& scene) {
    OutsideDrawing drawing;
    const CameraFrame frame = cameraFrame(scene.eye, scene.target, scene.up);
    const auto corners = viewVolumeCornersWorld(scene);
    const bool unnegated = leavesOutTheMinusOne(scene);
    const bool orthographic = scene.projection.type == ProjectionType::Orthographic;
    const glm::vec3 volumeColor = unnegated ? kClippedVolumeColor : kVolumeEdgeColor;
    // Each edge from both of its corners: a GL line leaves out its last pixel (the diamond-exit rule), and
    // a corner where edges only end would be drawn by none of them.
    auto addVolume = [&](const std::array<glm::dvec3, 8>& c, glm::vec3 color) {
        for (int i = 0; i < 8; ++i)
            for (int bit : {1, 2, 4})
                addLine(drawing.lines, c[std::size_t(i)], c[std::size_t(i ^ bit)], color);
    };
    addVolume(corners, volumeColor);
    // A perspective volume is a pyramid cut at near: its apex is the eye. The lines towards the apex stop
    // 2 % short of the near corners: where two lines meet, which one the depth test keeps depends on the
    // rasterizer's rounding (SwiftShader kept these over the volume's edges), and the corner is the volume's.
    if (!orthographic)
        for (int i = 4; i < 8; ++i)
            addLine(drawing.lines, frame.eye, frame.eye + 0.98 * (corners[std::size_t(i)] - frame.eye),
                    0.5f * volumeColor);
    for (const auto& [indices, color] : {std::pair{std::array{4, 5, 7, 6}, kNearFaceColor},
                                         std::pair{std::array{0, 1, 3, 2}, kFarFaceColor}})
        for (int k : {0, 1, 2, 0, 2, 3})
            drawing.faces.push_back({glm::vec3(corners[std::size_t(indices[std::size_t(k)])]), color});
    const glm::dvec3 nearCentre = 0.25 * (corners[4] + corners[5] + corners[6] + corners[7]);
    const glm::dvec3 farCentre = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
    // At the lower corners, clear of the objects inside the volume and of the lights above.
    drawing.labels.push_back({corners[4], "near: z = n, NDC z = +1", true});
    drawing.labels.push_back({corners[1], "far: z = f, NDC z = -1"});
    if (unnegated) {
        std::array<glm::dvec3, 8> mirrored;
        for (std::size_t i = 0; i < 8; ++i) mirrored[i] = 2.0 * frame.eye - corners[i];
        addVolume(mirrored, kBehindEyeColor);
        drawing.labels.push_back({0.5 * (nearCentre + farCentre), "w < 0 here: all clipped"});
        drawing.labels.push_back(
            {2.0 * frame.eye - 0.5 * (nearCentre + farCentre), "w > 0 here, behind the eye"});
    }

    // The eye and the camera frame from it.
    const double axis = 0.3 * glm::length(scene.eye - scene.target);
    for (const auto& [vector, color, name] :
         {std::tuple{frame.u, kAxisUColor, "u"}, std::tuple{frame.v, kAxisVColor, "v"},
          std::tuple{frame.w, kAxisWColor, "w"}}) {
        addArrow(drawing.lines, frame.eye, frame.eye + axis * vector, color);
        drawing.labels.push_back({frame.eye + 1.1 * axis * vector, name});
    }
    drawing.labels.push_back({frame.eye - 0.15 * axis * (frame.u + frame.v), "e"});

    for (const Light& light : scene.lights)
        addLightMarker(drawing, light, scene, 0.08 * glm::length(scene.eye - scene.target));
    return drawing;
}

} // namespace shadelab
