// The teapot and model objects drawn by the scene draw (src/gl/scene_draw.cpp): every shading mode covers
// pixels with no NaN; open surfaces are lit two-sided (DESIGN §3 "Open surfaces"); the GPU exact teapot
// (shaders/exact_patch.*.glsl) agrees in the interior with a fine mesh's Phong picture; a model's exact
// shading is Phong of its own normals, and writes its object id for the error view.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <set>
#include <string>

#include "gl/allocation_watch.h"
#include "gl/gl_test_support.h"
#include "gl/scene_draw.h" // private (src/gl/)
#include "shadelab/diagram/overlay.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/gl/loader.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/gl/view_figures.h"
#include "shadelab/scene/model.h"
#include "shadelab/scene/view.h"

namespace shadelab::test {
namespace {

// The teapot, seen from the front, above and to the side, lit by a point light.
Scene teapotScene(int size, ShadingMode shading, int level = 3) {
    Scene scene = litSphereScene(size, LightType::Point);
    scene.shading = shading;
    scene.eye = {1.6, 2.0, 3.4};
    SceneObject teapot;
    teapot.shape = Shape::Teapot;
    teapot.radius = 0.75;
    teapot.subdivisions = level;
    scene.objects = {teapot};
    return scene;
}

struct Coverage {
    std::size_t covered = 0, nonFinite = 0;
    double meanCovered = 0; // the mean of the covered pixels' channels
};

Coverage coverage(const ImageF& image) {
    Coverage c;
    double sum = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.pixel(x, y);
            for (int k = 0; k < 4; ++k) c.nonFinite += !std::isfinite(p[k]);
            if (p[3] > 0.5f) {
                ++c.covered;
                sum += (p[0] + p[1] + p[2]) / 3.0;
            }
        }
    c.meanCovered = c.covered ? sum / double(c.covered) : 0;
    return c;
}

constexpr ShadingMode kAllModes[] = {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong,
                                     ShadingMode::Toon, ShadingMode::Exact};

TEST(TeapotDraw, EveryModeCoversPixelsWithoutNaN) {
    SHADELAB_REQUIRE_GL(renderer);
    for (const ShadingMode mode : kAllModes) {
        const Coverage c = coverage(renderer->renderFloat(teapotScene(96, mode)));
        EXPECT_EQ(c.nonFinite, 0u) << toString(mode);
        // The teapot fills about a fifth of the picture (measured: ~2,100 of 9,216 pixels).
        EXPECT_GT(c.covered, 1500u) << toString(mode);
        EXPECT_GT(c.meanCovered, 0.15) << toString(mode) << ": lit, not only ambient";
    }
}

// The eye inside the teapot's body, a light beside it: every face it sees is a back face, whose outward
// normal points away from the eye and the light. Turned towards the viewer it is lit; culled, or lit with
// the outward normal, it would be background or the ambient 0.1 alone.
Scene insideTheTeapot(ShadingMode shading) {
    Scene scene = teapotScene(64, shading, 4);
    scene.eye = {0.05, 0.05, 0.05};
    scene.target = {1, -0.2, 0};
    scene.lights[0].position = {0, 0.1, 0};
    scene.lights[0].attenuation = {1, 0, 0};
    scene.objects[0].radius = 1;
    return scene;
}

TEST(TeapotDraw, BackFacesAreLitTowardsTheViewer) {
    SHADELAB_REQUIRE_GL(renderer);
    for (const ShadingMode mode : kAllModes) {
        const Coverage c = coverage(renderer->renderFloat(insideTheTeapot(mode)));
        EXPECT_EQ(c.nonFinite, 0u) << toString(mode);
        EXPECT_EQ(c.covered, 64u * 64u) << toString(mode) << ": the inner wall fills the view";
        EXPECT_GT(c.meanCovered, 0.3) << toString(mode) << ": the inner wall is lit, not only ambient (0.1)";
    }
}

// A mirrored teapot (scale x −1): its faces turn clockwise, and front must still mean the outside.
TEST(TeapotDraw, MirroredBackFacesAreLitTowardsTheViewer) {
    SHADELAB_REQUIRE_GL(renderer);
    for (const ShadingMode mode : kAllModes) {
        Scene scene = insideTheTeapot(mode);
        scene.objects[0].scale = {-1, 1, 1};
        const Coverage c = coverage(renderer->renderFloat(scene));
        EXPECT_GT(c.meanCovered, 0.3) << toString(mode);
    }
}

// The GPU exact teapot against the CPU reference (src/exact/patch_cast.cpp, in double), from three sides:
// the interior (eroded 2 px) within float's rounding, and no pixel the reference covers left as background
// (the proxy is pushed out to cover the surface).
TEST(TeapotDraw, ExactTeapotAgreesWithTheReference) {
    SHADELAB_REQUIRE_GL(renderer);
    const int size = 256;
    for (const glm::dvec3 eye :
         {glm::dvec3(1.6, 2.0, 3.4), glm::dvec3(0.4, 4.2, 1.2), glm::dvec3(-3.6, 0.3, 1.0)}) {
        Scene scene = teapotScene(size, ShadingMode::Exact);
        scene.eye = eye;
        const ImageF exact = renderer->renderFloat(scene);
        const ReferenceImage reference = renderReference(scene);
        const InteriorError e = interiorError(exact, reference);
        const std::size_t over = interiorPixelsOver(exact, reference, 2.0);
        std::size_t missing = 0, extra = 0;
        for (std::size_t i = 0; i < reference.objectId.size(); ++i) {
            const bool covered = exact.rgba[4 * i + 3] > 0.5f;
            missing += reference.objectId[i] >= 0 && !covered;
            extra += reference.objectId[i] < 0 && covered;
        }
        std::printf(
            "exact teapot from (%g, %g, %g) at %dx%d against the reference: interior mean %.4f/255, "
            "max %.3f/255 over %zu pixels, %zu of them over 2/255; %zu covered pixels left as background, "
            "%zu extra\n",
            eye.x, eye.y, eye.z, size, size, e.mean, e.max, e.pixels, over, missing, extra);
        EXPECT_GT(e.pixels, std::size_t(size * size / 10));
        // Float against double: within 2/255 but for a few pixels (measured: 1, 3 and 0 of ~18,000) — a
        // highlight's steep exponent (2.7/255), and from above rays into the gap under the lid that meet a
        // crease where the float iteration picks the other surface.
        EXPECT_LE(over, 4u);
        EXPECT_LE(e.mean, 0.05);
        // Rays grazing the silhouette, where the float iteration converges and the double one does not, or
        // the reverse (measured: 0 missing; 0, 5 and 3 extra along outlines of ~1,000 pixels).
        EXPECT_LE(missing, 4u);
        EXPECT_LE(extra, 8u);
    }
}

// A model of the sphere with exact normals, drawn as a mesh object.
Scene modelScene(ShadingMode shading) {
    Scene scene = litSphereScene(96, LightType::Point);
    scene.shading = shading;
    auto model = std::make_shared<Model>();
    model->path = "sphere.obj";
    model->mesh = buildSphere(3, VertexNormals::Exact);
    SceneObject object;
    object.shape = Shape::Mesh;
    object.mesh = "sphere.obj";
    object.model = model;
    object.radius = 0.8;
    scene.objects = {object};
    return scene;
}

TEST(TeapotDraw, ModelExactShadingIsPhongOfItsNormals) {
    SHADELAB_REQUIRE_GL(renderer);
    const ImageF exact = renderer->renderFloat(modelScene(ShadingMode::Exact));
    const ImageF phong = renderer->renderFloat(modelScene(ShadingMode::Phong));
    EXPECT_GT(coverage(phong).covered, 2000u);
    EXPECT_EQ(exact.rgba, phong.rgba);
}

// The error view's compare pass reads each object's index + 1 from the exact render's alpha: a model's
// exact shading writes it too.
TEST(TeapotDraw, ModelExactShadingWritesObjectIds) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = modelScene(ShadingMode::Exact);
    scene.objects.push_back(scene.objects[0]);
    scene.objects[0].center = {-0.6, 0, 0};
    scene.objects[1].center = {0.6, 0, 0};
    scene.objects[0].radius = scene.objects[1].radius = 0.45;
    std::set<float> alphas;
    (void)renderer->render(scene, [&](gl::Renderer&) {
        if (!gl::capabilities().floatColorTargets) GTEST_SKIP() << "no float colour targets in this context";
        const gl::RenderTarget target(scene.width, scene.height, gl::ColorFormat::Rgba32F,
                                      gl::depthFormatFor(scene.depth));
        gl::SceneDraw sceneDraw;
        gl::DrawOptions ids;
        ids.exactObjectIds = true;
        target.bind();
        sceneDraw.draw(scene, {0, scene.width, scene.height}, ids);
        const ImageF image = target.readFloat();
        for (std::size_t i = 3; i < image.rgba.size(); i += 4)
            if (image.rgba[i] > 0) alphas.insert(image.rgba[i]);
    });
    EXPECT_EQ(alphas, (std::set<float>{1.0f, 2.0f}));
}

// The error view measures a mode against exact shading: for the teapot, Phong at level 3 against the ray
// cast patches (a real error, falling with the level); for a model, Phong against Phong of its own normals
// (none: the reference of a mesh is its own interpolated normals, DESIGN §1).
TEST(TeapotDraw, ErrorViewMeasuresTeapotsAndModels) {
    SHADELAB_REQUIRE_GL(renderer);
    const ViewParse parsed = parseView("error");
    ASSERT_TRUE(parsed.view.has_value()) << parsed.error;
    double previousMean = 1e9;
    for (const int level : {2, 4}) {
        Scene teapot = teapotScene(128, ShadingMode::Phong, level);
        teapot.view = *parsed.view;
        (void)renderer->render(teapot);
        const gl::ViewFigures& f = renderer->viewFigures();
        EXPECT_GT(f.interiorPixels, 2000u) << "level " << level;
        EXPECT_TRUE(std::isfinite(f.interiorMean) && std::isfinite(f.interiorMax)) << "level " << level;
        EXPECT_LT(f.interiorMean, previousMean) << "level " << level;
        previousMean = f.interiorMean;
    }
    Scene model = modelScene(ShadingMode::Phong);
    model.view = *parsed.view;
    (void)renderer->render(model);
    EXPECT_GT(renderer->viewFigures().interiorPixels, 1000u);
    EXPECT_EQ(renderer->viewFigures().interiorMax, 0.0);
}

// Pixels of the overlay's colours (diagram/overlay.h) within 0.02 in every channel: lines, since no lit
// surface of these materials has them.
std::size_t pixelsOfColor(const ImageF& image, glm::vec3 color) {
    std::size_t count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.pixel(x, y);
            count += std::abs(p[0] - color.x) < 0.02f && std::abs(p[1] - color.y) < 0.02f &&
                     std::abs(p[2] - color.z) < 0.02f;
        }
    return count;
}

// The wireframe and normals overlays draw the teapot's and a model's lines (diagram/mesh_overlay.h) over
// the surface, in every mode: the edges in their grey, and with normals the vertex normals' cyan and the
// face normals' orange, none of which the plain picture has.
TEST(TeapotDraw, OverlaysDrawTheTeapotsAndAModelsLines) {
    SHADELAB_REQUIRE_GL(renderer);
    for (const bool teapot : {true, false})
        for (const ShadingMode mode : {ShadingMode::Phong, ShadingMode::Exact}) {
            Scene scene = teapot ? teapotScene(128, mode, 2) : modelScene(mode);
            const std::string what = std::string(teapot ? "teapot " : "model ") + std::string(toString(mode));
            const ImageF plain = renderer->renderFloat(scene);
            EXPECT_EQ(pixelsOfColor(plain, kEdgeColor), 0u) << what;
            scene.overlay = Overlay::Wireframe;
            const ImageF wireframe = renderer->renderFloat(scene);
            // Measured (egl, gles): 2,457 edge pixels on the level-2 teapot at 128² in Phong, 1,412 in exact
            // shading (where the mesh's edges, chords inside the true surface, sink under it), 748 on the
            // level-3 sphere model at 96².
            EXPECT_GT(pixelsOfColor(wireframe, kEdgeColor), 300u) << what;
            EXPECT_EQ(coverage(wireframe).nonFinite, 0u) << what;
            scene.overlay = Overlay::Normals;
            const ImageF normals = renderer->renderFloat(scene);
            std::printf("%s: %zu edge pixels; with normals %zu vertex-normal and %zu face-normal pixels\n",
                        what.c_str(), pixelsOfColor(wireframe, kEdgeColor),
                        pixelsOfColor(normals, kVertexNormalColor), pixelsOfColor(normals, kFaceNormalColor));
            EXPECT_GT(pixelsOfColor(normals, kVertexNormalColor), 100u) << what;
            EXPECT_GT(pixelsOfColor(normals, kFaceNormalColor), 100u) << what;
        }
}

// The overlay's lines are kept by SceneDraw (keyed by shape, model, level, overlay, scale and rule): a
// steady frame of a teapot and a model with their overlay allocates nothing (as frame_allocation_test holds
// the sphere's).
TEST(TeapotDraw, SteadyOverlayFramesAllocateNothing) {
    SHADELAB_REQUIRE_GL(renderer);
    for (const Overlay overlay : {Overlay::Wireframe, Overlay::Normals})
        for (const ShadingMode mode : {ShadingMode::Phong, ShadingMode::Exact}) {
            Scene scene = modelScene(mode);
            SceneObject teapot = teapotScene(96, mode).objects[0];
            teapot.subdivisions = kAutoSubdivisions;
            teapot.center = {0.5, 0, 0};
            teapot.scale = {1, 0.6, 1}; // the normals follow M
            scene.objects.push_back(teapot);
            scene.objects[0].center = {-0.6, 0, 0};
            scene.objects[0].radius = 0.4;
            scene.overlay = overlay;
            scene.normalMatrix = NormalMatrixRule::Model;
            long counts[2] = {-1, -1};
            renderer->render(scene, [&](gl::Renderer& drawing) {
                drawing.render(scene, scene.width, scene.height); // builds the plan and the lines
                for (long& count : counts) {
                    const long before = allocationCount();
                    drawing.render(scene, scene.width, scene.height);
                    count = allocationCount() - before;
                }
            });
            EXPECT_EQ(counts[0], 0) << toString(overlay) << " " << toString(mode);
            EXPECT_EQ(counts[1], 0) << toString(overlay) << " " << toString(mode);
        }
}

} // namespace
} // namespace shadelab::test
