#include "shadelab/diagram/outside_view.h"

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
