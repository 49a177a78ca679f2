// Extreme cameras and image sizes (gl/extreme_support.h): degenerate cameras and view volumes refused by
// name, the eye inside the sphere, tiny and wide fields of view, a one-pixel image, the largest size.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "gl/allocation_watch.h"
#include "gl/extreme_support.h"
#include "input_error.h"
#include "shadelab/errors.h"

namespace shadelab::test {
namespace {

// Under each lighting model, the scene covers every pixel of the render and of the reference, and the
// render meets the Phong-at-level-8 limits over at least `minPixels` interior pixels.
void expectFilledWithinPhongLimits(HeadlessRenderer& renderer, Scene scene, const std::string& what,
                                   std::size_t minPixels) {
    const std::size_t all = std::size_t(scene.width) * std::size_t(scene.height);
    for (LightingModel model : kLightingModels) {
        scene.lighting = model;
        const std::string named = what + " " + std::string(toString(model));
        const ImageF image = checkedRender(renderer, scene, named);
        const ReferenceImage reference = checkedReference(scene, named);
        EXPECT_EQ(coveredPixels(image), all) << named;
        EXPECT_EQ(coveredPixels(reference), all) << named;
        expectPhongLimits(image, reference, named, minPixels);
    }
}

struct BadCamera {
    const char* name;
    std::function<void(Scene&)> change;
    std::vector<const char*> named; // every one must appear in the message
};

const BadCamera kBadCameras[] = {
    {"up_parallel_to_view",
     [](Scene& s) {
         s.up = {0, 0, 1};
     },
     {"camera", "up"}},
    {"up_antiparallel_to_view",
     [](Scene& s) {
         s.up = {0, 0, -3};
     },
     {"camera", "up"}},
    {"up_parallel_within_1e_12",
     [](Scene& s) {
         s.up = {1e-12, 0, 1};
     },
     {"camera", "up"}},
    {"up_parallel_far_from_origin",
     [](Scene& s) {
         s.eye = {1e6, 1e6, 1e6 + 4};
         s.target = {1e6, 1e6, 1e6};
         s.up = {0, 0, 1};
     },
     {"camera", "up"}},
    {"up_zero",
     [](Scene& s) {
         s.up = {0, 0, 0};
     },
     {"camera", "up"}},
    {"eye_equals_target",
     [](Scene& s) {
         s.eye = s.target = {1, 2, 3};
     },
     {"camera", "eye", "target"}},
    {"eye_equals_target_far_from_origin",
     [](Scene& s) {
         s.eye = s.target = {1e6, -1e6, 1e6};
     },
     {"camera", "eye", "target"}},
    {"near_zero", [](Scene& s) { s.projection.near = 0; }, {"projection.near"}},
    {"near_negative", [](Scene& s) { s.projection.near = -1; }, {"projection.near"}},
    {"near_equals_far",
     [](Scene& s) {
         s.projection.near = 5;
         s.projection.far = 5;
     },
     {"projection.far", "near"}},
    {"near_beyond_far",
     [](Scene& s) {
         s.projection.near = 10;
         s.projection.far = 5;
     },
     {"projection.far", "near"}},
    {"frustum_left_equals_right",
     [](Scene& s) { s.projection = {ProjectionType::Frustum, 40, 0.3, 0.3, -0.2, 0.2, 0.5, 20}; },
     {"projection.right", "left"}},
    {"frustum_bottom_equals_top",
     [](Scene& s) { s.projection = {ProjectionType::Frustum, 40, -0.2, 0.2, 0.1, 0.1, 0.5, 20}; },
     {"projection.top", "bottom"}},
    {"orthographic_left_equals_right",
     [](Scene& s) { s.projection = {ProjectionType::Orthographic, 40, -1, -1, -1, 1, 0.5, 20}; },
     {"projection.right", "left"}},
    {"orthographic_near_zero",
     [](Scene& s) { s.projection = {ProjectionType::Orthographic, 40, -1, 1, -1, 1, 0, 20}; },
     {"projection.near"}},
    {"fovy_zero", [](Scene& s) { s.projection.fovyDeg = 0; }, {"projection.fovy_deg"}},
    {"fovy_180", [](Scene& s) { s.projection.fovyDeg = 180; }, {"projection.fovy_deg"}},
};

// A degenerate camera or view volume is an InputError naming the field, from validateScene, from sceneView
// (never a NaN matrix), and from HeadlessRenderer::render / renderFloat; the renderer stays usable. (One test
// for all cases: each is cheap, and a process per case would cost a context each.)
TEST(Camera, DegenerateCamerasAreInputErrorsNamingTheField) {
    SHADELAB_REQUIRE_GL(renderer);
    const Scene good = phongScene(32);
    const ImageF goodBefore = checkedRender(*renderer, good, "before the errors");
    for (const BadCamera& bad : kBadCameras) {
        SCOPED_TRACE(bad.name);
        Scene scene = good;
        scene.objects[0].subdivisions = 4;
        bad.change(scene);
        const std::string messages[] = {
            inputErrorOf([&] { validateScene(scene); }),
            inputErrorOf([&] { (void)sceneView(scene); }),
            inputErrorOf([&] { (void)renderer->render(scene); }),
            inputErrorOf([&] { (void)renderer->renderFloat(scene); }),
        };
        const char* via[] = {"validateScene", "sceneView", "render", "renderFloat"};
        std::printf("  %s: \"%s\"\n", bad.name, messages[0].c_str());
        for (int i = 0; i < 4; ++i) {
            EXPECT_FALSE(messages[i].empty()) << via[i] << " accepted " << bad.name;
            for (const char* field : bad.named)
                EXPECT_NE(messages[i].find(field), std::string::npos)
                    << via[i] << ": \"" << messages[i] << "\" does not name " << field;
        }
    }
    // The renderer is still usable, and unchanged by the refusals.
    EXPECT_EQ(checkedRender(*renderer, good, "after the errors").rgba, goodBefore.rgba);
}

template <int C, int R> bool allFinite(const glm::mat<C, R, double>& m) {
    for (int c = 0; c < C; ++c)
        for (int r = 0; r < R; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// The eye inside the sphere (at its centre and off-centre), looking at the far wall, which a light outside
// behind it illuminates through the outward normal (DESIGN §3: the mesh's outward normal is used as seen;
// no culling, so the inside shows). Expected: every pixel covered, the Phong-at-level-8 limits of the
// reference on the interior.
TEST(Camera, EyeInsideTheSphereShowsItsInside) {
    SHADELAB_REQUIRE_GL(renderer);
    for (const glm::dvec3& eye : {glm::dvec3(0, 0, 0), glm::dvec3(0.2, -0.1, 0.5)}) {
        Scene scene = phongScene(128);
        scene.eye = eye;
        scene.target = {0, 0, -1};
        scene.projection.near = 0.05;
        scene.lights[0].position = {0.5, 0.8, -5};
        char what[96];
        std::snprintf(what, sizeof what, "eye (%g, %g, %g) inside", eye.x, eye.y, eye.z);
        expectFilledWithinPhongLimits(*renderer, scene, what, 10000);
    }
}

// fovy 0.001°: 64 px span 7e-5 units of the surface, so the sphere fills the view. Aimed at the pole (a mesh
// vertex) and at a point in the middle of a face's span. Expected: finite matrices, every pixel covered in
// both, the Phong-at-level-8 limits of the reference.
TEST(Camera, TinyFieldOfViewFillsTheViewLikeTheReference) {
    SHADELAB_REQUIRE_GL(renderer);
    for (const glm::dvec3& target : {glm::dvec3(0, 0, 0), glm::dvec3(0.3, 0.2, std::sqrt(1 - 0.13))}) {
        Scene scene = phongScene(64);
        scene.projection.fovyDeg = 0.001;
        scene.target = target;
        const SceneView view = sceneView(scene);
        EXPECT_TRUE(allFinite(view.clipFromView) && allFinite(view.viewFromWorld));
        char what[96];
        std::snprintf(what, sizeof what, "fovy 0.001 target (%g, %g, %g)", target.x, target.y, target.z);
        expectFilledWithinPhongLimits(*renderer, scene, what, 3000);
    }
}

// fovy 179°: tan(89.5°) = 115, so the middle of the image shows only directions within ~89° of the axis at
// a fraction of a pixel per degree, and the border the last half degree. Two views: the sphere on the axis 4
// away (a fraction of a pixel: finite, coverage that of the reference within 4 pixels), and the eye 2 from
// the centre looking past it (target = eye + (1, 0, 0), near 1e-3), where the sphere's side, 60°..89.5° off
// the axis, is stretched into a wedge across half the image: the Phong-at-level-8 limits of the reference.
TEST(Camera, WideFieldOfViewMatchesTheReference) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = phongScene(256);
    scene.projection.fovyDeg = 179;
    EXPECT_TRUE(allFinite(sceneView(scene).clipFromView));
    {
        const ImageF image = checkedRender(*renderer, scene, "fovy 179 on axis");
        const ReferenceImage reference = checkedReference(scene, "fovy 179 on axis");
        std::printf("  fovy 179 on axis: %zu pixels covered, reference %zu\n", coveredPixels(image),
                    coveredPixels(reference));
        EXPECT_LE(std::max(coveredPixels(image), coveredPixels(reference)) -
                      std::min(coveredPixels(image), coveredPixels(reference)),
                  4u);
    }
    scene.eye = {0, 0, 2};
    scene.target = {1, 0, 2};
    scene.projection.near = 1e-3;
    EXPECT_TRUE(allFinite(sceneView(scene).clipFromView));
    for (LightingModel model : kLightingModels) {
        scene.lighting = model;
        const std::string what = "fovy 179, looking past the sphere, " + std::string(toString(model));
        const ImageF image = checkedRender(*renderer, scene, what);
        const ReferenceImage reference = checkedReference(scene, what);
        std::printf("  %s: %zu pixels covered, reference %zu\n", what.c_str(), coveredPixels(image),
                    coveredPixels(reference));
        expectPhongLimits(image, reference, what, 5000);
    }
}

// A 1×1 image: one finite pixel, equal to the reference's within 4/255 (its centre sees the pole, a mesh
// vertex), in every shading mode; and a 1×1 image of the background.
TEST(Camera, OnePixelImage) {
    SHADELAB_REQUIRE_GL(renderer);
    for (ShadingMode mode : kShadingModes) {
        Scene scene = phongScene(1);
        scene.shading = mode;
        const std::string what = "1x1 " + std::string(toString(mode));
        const ImageF image = checkedRender(*renderer, scene, what);
        const ReferenceImage reference = checkedReference(scene, what);
        double worst = 0;
        for (int c = 0; c < 4; ++c)
            worst = std::max(worst, 255.0 * std::abs(double(image.rgba[c]) - reference.color.rgba[c]));
        std::printf("  %s: (%.4f, %.4f, %.4f, %.0f), reference (%.4f, %.4f, %.4f, %.0f): %.3f/255\n",
                    what.c_str(), image.rgba[0], image.rgba[1], image.rgba[2], image.rgba[3],
                    reference.color.rgba[0], reference.color.rgba[1], reference.color.rgba[2],
                    reference.color.rgba[3], worst);
        // Flat shading lights the whole facet at its centroid; at level 8 that is ~0.004 rad from the pole.
        EXPECT_LE(worst, 4.0) << what;
    }
    Scene empty = phongScene(1);
    empty.background = {0.25, 0.5, 0.75};
    empty.target = {5, 0, 0};
    const ImageF image = checkedRender(*renderer, empty, "1x1 background");
    EXPECT_EQ(image.rgba[0], 0.25f);
    EXPECT_EQ(image.rgba[1], 0.5f);
    EXPECT_EQ(image.rgba[2], 0.75f);
    EXPECT_EQ(image.rgba[3], 0.0f);
}

// The largest size: the context's limit is min(GL_MAX_RENDERBUFFER_SIZE, GL_MAX_VIEWPORT_DIMS) and the scene
// format's is kMaxImageSize (16384). A full square at the limit would need gigabytes, so strips of 8192×8,
// limit×8 and 8×limit are rendered (level 8): finite; covering what the reference covers within 1% + 8 px
// (the mesh's silhouette lies inside the exact one by up to R_px·δ₈, 2.7 px at the ends of the 8×16384
// strip, where R_px ≈ 11000); and within the Phong-at-level-8 limits on whatever interior there is (none on
// the 5-px sphere of the wide strips). One pixel beyond the limit is an InputError naming the size — from
// validateScene (image.width / image.height) where the limit is 16384, and from the renderer (the size)
// before any GL storage is made.
TEST(Camera, LargestImageSizeRendersAndOneBeyondIsAnInputError) {
    SHADELAB_REQUIRE_GL(renderer);
    (void)checkedRender(*renderer, phongScene(8), "warm-up"); // makes the context current
    GLint maxRenderbuffer = 0, maxViewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
    const int contextLimit = std::min({maxRenderbuffer, maxViewport[0], maxViewport[1]});
    const int limit = std::min(contextLimit, kMaxImageSize);
    std::printf("  GL_MAX_RENDERBUFFER_SIZE %d, GL_MAX_VIEWPORT_DIMS %dx%d, kMaxImageSize %d\n",
                maxRenderbuffer, maxViewport[0], maxViewport[1], kMaxImageSize);
    ASSERT_GE(limit, 8192);

    for (const auto& [w, h] : {std::pair{8192, 8}, std::pair{limit, 8}, std::pair{8, limit}}) {
        Scene scene = phongScene(8);
        scene.width = w;
        scene.height = h;
        const std::string what = std::to_string(w) + "x" + std::to_string(h);
        const auto start = std::chrono::steady_clock::now();
        const ImageF image = checkedRender(*renderer, scene, what);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const ReferenceImage reference = checkedReference(scene, what);
        const std::size_t covered = coveredPixels(image), expected = coveredPixels(reference);
        const InteriorError e = interiorError(image, reference);
        std::printf("  %s: %.2f s, %zu pixels covered, reference %zu; interior mean %.3f/255, max %.3f/255 "
                    "over %zu pixels\n",
                    what.c_str(), seconds, covered, expected, e.mean, e.max, e.pixels);
        EXPECT_GT(expected, 0u) << what;
        EXPECT_LE(std::max(covered, expected) - std::min(covered, expected), expected / 100 + 8) << what;
        EXPECT_LT(e.mean, 0.5) << what;
        EXPECT_LE(e.max, 4.0) << what;
    }

    Scene tooWide = phongScene(8);
    tooWide.width = limit + 1;
    Scene tooTall = phongScene(8);
    tooTall.height = limit + 1;
    for (const Scene& scene : {tooWide, tooTall}) {
        const std::string size = std::to_string(scene.width) + "x" + std::to_string(scene.height);
        const std::string field = scene.width > limit ? "image.width" : "image.height";
        if (limit == kMaxImageSize) {
            const std::string message = inputErrorOf([&] { validateScene(scene); });
            std::printf("  %s via validateScene: \"%s\"\n", size.c_str(), message.c_str());
            EXPECT_NE(message.find(field), std::string::npos) << message;
            EXPECT_NE(message.find(std::to_string(limit + 1)), std::string::npos) << message;
        }
        resetLargestAllocation();
        const std::string message = inputErrorOf([&] { (void)renderer->renderFloat(scene); });
        std::printf("  %s via renderFloat: \"%s\" (largest allocation %zu B)\n", size.c_str(),
                    message.c_str(), largestAllocation());
        // The renderer validates the scene first, so it names the field and the value, like validateScene.
        EXPECT_NE(message.find(field), std::string::npos) << message;
        EXPECT_NE(message.find(std::to_string(limit + 1)), std::string::npos) << message;
        EXPECT_LT(largestAllocation(), std::size_t(1) << 20);
    }
}

} // namespace
} // namespace shadelab::test
