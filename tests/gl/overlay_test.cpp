// The teaching instruments on the GPU: the overlay's lines (Scene::overlay) drawn by the renderer over the
// shaded surface, and the probe's prediction of a pixel (shadelab/exact/probe.h) against the pixel drawn.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "gl/gl_test_support.h"
#include "gl/projected_mesh.h"
#include "shadelab/exact/probe.h"
#include "shadelab/scene/auto_level.h"

namespace shadelab::test {
namespace {

Scene overlayScene(Overlay overlay) {
    Scene scene = litSphereScene(128, LightType::Point);
    scene.objects[0].subdivisions = 2;
    scene.overlay = overlay;
    return scene;
}

// Coverage (alpha) of the plain render, grown by `grow` pixels.
std::vector<bool> coverage(const Image& image, int grow) {
    std::vector<bool> covered(std::size_t(image.width) * std::size_t(image.height), false);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            bool any = false;
            for (int dy = -grow; dy <= grow && !any; ++dy)
                for (int dx = -grow; dx <= grow && !any; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    any = xx >= 0 && yy >= 0 && xx < image.width && yy < image.height &&
                          image.rgba[(std::size_t(yy) * std::size_t(image.width) + std::size_t(xx)) * 4 + 3] >
                              0;
                }
            covered[std::size_t(y) * std::size_t(image.width) + std::size_t(x)] = any;
        }
    return covered;
}

struct Changed {
    std::size_t inside = 0, outside = 0;
};
Changed changedPixels(const Image& plain, const Image& over, const std::vector<bool>& covered) {
    Changed c;
    for (std::size_t i = 0; i < covered.size(); ++i) {
        bool differs = false;
        for (int k = 0; k < 3; ++k)
            differs |= plain.rgba[i * 4 + std::size_t(k)] != over.rgba[i * 4 + std::size_t(k)];
        if (differs) ++(covered[i] ? c.inside : c.outside);
    }
    return c;
}

// The wireframe lies on the object: the front edges show (level 2: 96 edges), nothing changes off it, and
// the edges behind the sphere are hidden by the depth test, so the pixels it changes are far fewer than
// with the depth test off (which the probe's lines use).
TEST(Overlay, WireframeDrawsTheFrontEdgesOnTheObjectOnly) {
    SHADELAB_REQUIRE_GL(renderer);
    const Image plain = renderer->render(overlayScene(Overlay::None));
    const Image wire = renderer->render(overlayScene(Overlay::Wireframe));
    const Changed c = changedPixels(plain, wire, coverage(plain, 1));
    std::printf("wireframe changed %zu pixels on the object, %zu off it\n", c.inside, c.outside);
    EXPECT_GT(c.inside, 600u);
    EXPECT_EQ(c.outside, 0u);
    // Where a line is drawn the pixel is the edge colour (0.85 → 217).
    std::size_t edgeColoured = 0;
    for (std::size_t i = 0; i < plain.rgba.size(); i += 4)
        edgeColoured += wire.rgba[i] == 217 && wire.rgba[i + 1] == 217 && wire.rgba[i + 2] == 217;
    EXPECT_GT(edgeColoured, c.inside / 2);
}

// The lights' markers in the camera's picture: a point light in view is drawn as its wire sphere in its
// colour around where the camera projects it, and nothing else of the picture changes.
TEST(Overlay, LightsDrawAPointLightWhereTheCameraSeesIt) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene;
    scene.width = scene.height = 200;
    Light light = Scene::defaultLight();
    light.position = {0.5, 0.45, 2.0}; // in view, in front of the sphere
    light.diffuse = {1, 1, 0.5};
    scene.lights = {light};
    const Image plain = renderer->render(scene);
    scene.overlay = Overlay::Lights;
    const Image marked = renderer->render(scene);
    // The marker's radius is 0.08 of the eye's distance to the target (outside_view.cpp): 0.32.
    const glm::dvec4 clip = webGlClipFromView(scene) * glm::lookAt(scene.eye, scene.target, scene.up) *
                            glm::dvec4(light.position, 1);
    const glm::dvec2 centre((clip.x / clip.w + 1) / 2 * scene.width,
                            (1 - clip.y / clip.w) / 2 * scene.height);
    const double radiusPx =
        0.32 / (-(glm::lookAt(scene.eye, scene.target, scene.up) * glm::dvec4(light.position, 1)).z) /
        std::tan(glm::radians(20.0)) * scene.height / 2;
    std::size_t marker = 0, changedFar = 0;
    for (int y = 0; y < scene.height; ++y)
        for (int x = 0; x < scene.width; ++x) {
            const std::uint8_t* m = marked.pixel(x, y);
            const bool changed = !std::equal(m, m + 4, plain.pixel(x, y));
            const double distance = glm::length(glm::dvec2(x + 0.5, y + 0.5) - centre);
            if (changed && distance > radiusPx * 1.2 + 1.5) ++changedFar;
            marker += m[0] == 255 && m[1] == 255 && m[2] == 128 && distance <= radiusPx * 1.2 + 1.5;
        }
    EXPECT_GT(marker, 40u) << "the wire sphere around (" << centre.x << ", " << centre.y << "), radius "
                           << radiusPx << " px";
    EXPECT_EQ(changedFar, 0u) << "pixels changed away from the marker";
}

TEST(Overlay, NormalsStickOutOfTheSilhouette) {
    SHADELAB_REQUIRE_GL(renderer);
    const Image plain = renderer->render(overlayScene(Overlay::None));
    const Image normals = renderer->render(overlayScene(Overlay::Normals));
    const Image wire = renderer->render(overlayScene(Overlay::Wireframe));
    const Changed c = changedPixels(plain, normals, coverage(plain, 2));
    std::printf("normals changed %zu pixels on the object, %zu off it\n", c.inside, c.outside);
    EXPECT_GT(c.outside, 50u) << "the normals at the rim point out of the picture's sphere";
    EXPECT_GT(c.inside, changedPixels(plain, wire, coverage(plain, 2)).inside);
}

// The normals drawn are the ones the shading uses: on the lecture's ellipsoid (scenes/normal_matrix.json)
// under the ambient term alone, which no normal changes, the pictures with normals by (M⁻¹)ᵀ and by M
// differ only by the overlay, and they do differ (the lines were M·n under both rules).
TEST(Overlay, NormalsFollowTheNormalMatrix) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = overlayScene(Overlay::Normals);
    scene.objects[0].scale = {1.8, 0.45, 0.9};
    scene.term = LightingTerm::Ambient;
    Scene byM = scene;
    byM.normalMatrix = NormalMatrixRule::Model;
    Scene plain = scene, plainByM = byM;
    plain.overlay = plainByM.overlay = Overlay::None;
    const Image plainImage = renderer->render(plain);
    ASSERT_EQ(changedPixels(plainImage, renderer->render(plainByM), coverage(plainImage, 0)).inside, 0u)
        << "the ambient term is the same under both rules";
    const Changed c = changedPixels(renderer->render(scene), renderer->render(byM), coverage(plainImage, 8));
    std::printf("normals by (M^-1)^T and by M differ in %zu pixels on the object, %zu off it\n", c.inside,
                c.outside);
    EXPECT_GT(c.inside + c.outside, 200u);
}

// A mirrored ellipsoid (its faces turn clockwise, its normal matrix flips) keeps its edges on it.
TEST(Overlay, MirroredEllipsoidKeepsTheEdgesOnTheObject) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = overlayScene(Overlay::Wireframe);
    scene.objects[0].scale = {-1.2, 0.8, 1};
    Scene plainScene = scene;
    plainScene.overlay = Overlay::None;
    const Image plain = renderer->render(plainScene);
    const Changed c = changedPixels(plain, renderer->render(scene), coverage(plain, 1));
    EXPECT_GT(c.inside, 600u);
    EXPECT_EQ(c.outside, 0u);
}

// The probe predicts what the renderer draws: for flat, Gouraud and Phong shading at level 3, the mode's
// colour at the surface point a pixel sees is that pixel, within the float/8-bit rounding (flat, away
// from triangle edges) or within what the radial and the view ray's mesh points differ by (Gouraud, Phong):
// the probe's mesh point lies radially under the exact point, the pixel's on the view ray.
// With one term shown (the demo's K) as with the whole sum.
TEST(Probe, PredictsTheRenderedPixel) {
    SHADELAB_REQUIRE_GL(renderer);
    for (const LightingTerm term : {LightingTerm::All, LightingTerm::Diffuse})
        for (const ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
            Scene scene = litSphereScene(128, LightType::Point);
            scene.shading = mode;
            scene.term = term;
            scene.objects[0].subdivisions = 3;
            const Image image = renderer->render(scene);
            const SphereMesh mesh = buildSphere(3, scene.vertexNormals);
            double worst = 0;
            int probed = 0;
            // Within 0.7 of the sphere's radius on screen (44 px): nearer the rim the view ray and the radial
            // ray from the centre meet the coarse mesh in different triangles, and its silhouette lies inside
            // the exact sphere's.
            for (int j = 34; j < 95; j += 3)
                for (int i = 34; i < 95; i += 3) {
                    if (std::hypot(i + 0.5 - 64, j + 0.5 - 64) > 0.7 * 44) continue;
                    const auto point = pickSurfacePoint(scene, i + 0.5, j + 0.5);
                    if (!point) continue;
                    const ProbeReport probe = probeSurface(scene, *point, mesh);
                    if (std::min({probe.barycentric.x, probe.barycentric.y, probe.barycentric.z}) < 0.08)
                        continue;
                    const glm::u8vec3 pixel = rgbAt(image, i, j);
                    if (std::getenv("PROBE_DEBUG"))
                        std::printf("%d,%d probe %.1f %.1f %.1f pixel %d %d %d\n", i, j,
                                    probe.mode.color.x * 255, probe.mode.color.y * 255,
                                    probe.mode.color.z * 255, pixel.x, pixel.y, pixel.z);
                    // Flat: the pixel itself. Otherwise the probe's point is within a pixel of the pixel's
                    // own point, so its value lies within the 3 × 3 neighbourhood's range (the highlight
                    // changes by up to ~15/255 per pixel at level 3).
                    const int reach = mode == ShadingMode::Flat ? 0 : 1;
                    for (int k = 0; k < 3; ++k) {
                        double low = 255, high = 0;
                        for (int dy = -reach; dy <= reach; ++dy)
                            for (int dx = -reach; dx <= reach; ++dx) {
                                const double v = rgbAt(image, i + dx, j + dy)[k];
                                low = std::min(low, v);
                                high = std::max(high, v);
                            }
                        const double value = probe.mode.color[k] * 255;
                        worst = std::max(worst, std::max(low - value, value - high));
                    }
                    ++probed;
                }
            std::printf("%s, %s: %d points, largest distance of the probe from the pixels' range %.2f/255\n",
                        std::string(toString(mode)).c_str(), std::string(toString(term)).c_str(), probed,
                        worst);
            EXPECT_GT(probed, 60);
            EXPECT_LT(worst, 1.01) << toString(mode) << ", " << toString(term); // float against double, 8-bit
        }
}

} // namespace
} // namespace shadelab::test
