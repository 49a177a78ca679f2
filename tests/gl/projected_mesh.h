// Sphere meshes projected as the rasterizer sees them, and the flat-shading check built on them (DESIGN §3):
// CPU only, shared by the GL invariants (tests/gl/invariants_test.cpp) and the browser test (tests/web/).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "shadelab/geometry/sphere.h"
#include "shadelab/image/image.h"
#include "shadelab/scene/camera.h"
#include "shadelab/scene/scene.h"
#include "shadelab/shading/lighting.h"

namespace shadelab::test {

inline glm::u8vec3 rgbAt(const Image& image, int x, int y) {
    const std::uint8_t* p = image.pixel(x, y);
    return {p[0], p[1], p[2]};
}

// A sphere mesh as the rasterizer sees it: object → clip → window (pixels, rows running down).
struct ProjectedMesh {
    SphereMesh mesh;
    glm::dmat4 viewFromObject, clipFromObject;
    std::vector<Light> lightsView;
    std::vector<glm::dvec4> clip; // per vertex
    int width, height;

    ProjectedMesh(const Scene& scene, int level)
        : mesh(buildSphere(level, scene.vertexNormals)), width(scene.width), height(scene.height) {
        const SceneView view = sceneView(scene);
        viewFromObject = view.viewFromWorld * worldFromObject(scene.objects[0]);
        clipFromObject = view.clipFromView * viewFromObject;
        for (const Light& light : scene.lights)
            lightsView.push_back(transformLight(light, view.viewFromWorld));
        for (const glm::dvec3& p : mesh.positions) clip.push_back(clipFromObject * glm::dvec4(p, 1));
    }
    glm::dvec2 window(unsigned vertex) const {
        const glm::dvec4& c = clip[vertex];
        return {(c.x / c.w + 1) * 0.5 * width, (1 - c.y / c.w) * 0.5 * height};
    }
    // The unclamped lighting of a point given in object space with an object-space normal, as the shaders
    // do it (perspective: local viewer towards the eye).
    glm::dvec3 shadeAt(const glm::dvec3& pointObject, const glm::dvec3& normalObject,
                       const Material& material, ShadeOptions options) const {
        const glm::dvec3 positionView(viewFromObject * glm::dvec4(pointObject, 1));
        const glm::dvec3 normalView = glm::normalize(normalMatrix(viewFromObject) * normalObject);
        return shade({positionView, normalView, glm::normalize(-positionView)}, material, lightsView,
                     options);
    }
};

inline double cross2(glm::dvec2 u, glm::dvec2 v) {
    return u.x * v.y - u.y * v.x;
}

// Calls f(x, y, λ) for every pixel centre at least `margin` pixels inside the window triangle abc, with λ its
// window-space barycentric coordinates. Returns the triangle's signed area ×2 (negative: front-facing, since
// rows run down and the mesh is counter-clockwise seen from outside).
template <typename F>
inline double forEachPixelInside(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, double margin, int width,
                                 int height, F f) {
    const double area = cross2(b - a, c - a);
    if (area == 0) return 0;
    const double heights[3] = {std::abs(area) / glm::length(c - b), std::abs(area) / glm::length(a - c),
                               std::abs(area) / glm::length(b - a)};
    const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x})))),
              x1 = std::min(width - 1, int(std::ceil(std::max({a.x, b.x, c.x})))),
              y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y})))),
              y1 = std::min(height - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const glm::dvec2 p(x + 0.5, y + 0.5);
            const glm::dvec3 lambda(cross2(b - p, c - p) / area, cross2(c - p, a - p) / area,
                                    cross2(a - p, b - p) / area);
            // λ_i times the height over the opposite edge is the distance to that edge.
            if (lambda.x * heights[0] < margin || lambda.y * heights[1] < margin ||
                lambda.z * heights[2] < margin)
                continue;
            f(x, y, lambda);
        }
    }
    return area;
}

inline int maxChannelDelta(glm::u8vec3 a, glm::u8vec3 b) {
    return std::max(
        {std::abs(int(a.x) - int(b.x)), std::abs(int(a.y) - int(b.y)), std::abs(int(a.z) - int(b.z))});
}

inline glm::u8vec3 unorm8(const glm::dvec3& c) {
    return {toUnorm8(c.x), toUnorm8(c.y), toUnorm8(c.z)};
}

// DESIGN §3: flat shading is one colour per triangle, lit once at its centroid with its face normal.
// Project every front-facing triangle of a level-1 sphere (big triangles) and check that all pixel centres
// well inside it carry one colour, and that it is round(255·clamp(shade(centroid, face normal))) within ±1.
// Catches: colour varying inside a triangle (interpolated instead of flat), lighting at a vertex (the
// provoking one, or any) instead of the centroid, the vertex normal instead of the face normal, a wrong
// normal matrix or light transform, and the wrong lighting model in the flat programs.
inline void checkFlatLitAtCentroids(const std::function<Image(const Scene&)>& render) {
    Scene scene = litSphereScene(256, LightType::Point);
    scene.shading = ShadingMode::Flat;
    scene.objects[0].subdivisions = 1;
    const ProjectedMesh pm(scene, 1);
    const Material& material = scene.objects[0].material;
    for (LightingModel model : kLightingModels) {
        SCOPED_TRACE(std::string(toString(model)));
        scene.lighting = model;
        const ShadeOptions options{model, false, scene.toonBands};
        const Image image = render(scene);
        int trianglesChecked = 0, worstDelta = 0;
        int vertexLitWouldFail[3] = {0, 0, 0}; // triangles where lighting at vertex k is outside ±1
        for (std::size_t f = 0; f < pm.mesh.triangles.size(); ++f) {
            const glm::uvec3& t = pm.mesh.triangles[f];
            const glm::dvec3 centroid =
                (pm.mesh.positions[t.x] + pm.mesh.positions[t.y] + pm.mesh.positions[t.z]) / 3.0;
            const glm::u8vec3 expected =
                unorm8(clampColor(pm.shadeAt(centroid, pm.mesh.faceNormals[f], material, options)));
            std::set<std::tuple<int, int, int>> colours;
            int inside = 0, triangleDelta = 0;
            // 2 px margin keeps away from edge rasterization.
            const double area = forEachPixelInside(
                pm.window(t.x), pm.window(t.y), pm.window(t.z), 2, 256, 256, [&](int x, int y, glm::dvec3) {
                    const glm::u8vec3 colour = rgbAt(image, x, y);
                    colours.insert({colour.x, colour.y, colour.z});
                    triangleDelta = std::max(triangleDelta, maxChannelDelta(colour, expected));
                    ++inside;
                });
            if (area > -200 || inside < 20) continue; // back-facing or a sliver at the rim
            ++trianglesChecked;
            worstDelta = std::max(worstDelta, triangleDelta);
            EXPECT_EQ(colours.size(), 1u)
                << "triangle " << f << " has " << colours.size() << " colours over " << inside << " pixels";
            EXPECT_LE(triangleDelta, 1)
                << "triangle " << f << ": interior differs from the centroid lighting " << int(expected.x)
                << "," << int(expected.y) << "," << int(expected.z) << " by up to " << triangleDelta
                << "/255";
            for (int k = 0; k < 3; ++k) {
                const glm::u8vec3 atVertex = unorm8(clampColor(
                    pm.shadeAt(pm.mesh.positions[t[k]], pm.mesh.faceNormals[f], material, options)));
                if (maxChannelDelta(atVertex, expected) > 1) ++vertexLitWouldFail[k];
            }
        }
        std::printf(
            "flat/%s: %d triangles checked, worst delta %d/255; vertex-lit colours off by > 1 in %d, %d, %d "
            "of them (vertex 0, 1, 2)\n",
            toString(model).data(), trianglesChecked, worstDelta, vertexLitWouldFail[0],
            vertexLitWouldFail[1], vertexLitWouldFail[2]);
        // Of the 16 faces about half face the camera; the rim ones are slivers.
        EXPECT_GE(trianglesChecked, 5);
        // The test must tell centroid from vertex lighting: for whichever vertex a wrong program would use,
        // some checked triangle's colour would then be outside the tolerance.
        for (int k = 0; k < 3; ++k) EXPECT_GT(vertexLitWouldFail[k], 0) << "vertex " << k;
    }
}

} // namespace shadelab::test
