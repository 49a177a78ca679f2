// Renders of the same scenes through different contexts compared with each other, pixel for pixel: EGL
// and OSMesa (DESIGN §6: on Mesa 22.3 llvmpipe both give bit-identical images), and desktop OpenGL 3.3
// core against OpenGL ES 3.0 (DESIGN §7: one renderer, one set of GLSL sources). The contexts are made in
// one process through the one loader.
#include <cstdlib>

#include <gtest/gtest.h>

#include "gl/gl_test_support.h"
#include "tolerances.h"

namespace shadelab::test {
namespace {

std::string describe(const Scene& scene) {
    return std::string(toString(scene.shading)) + "/" + std::string(toString(scene.lighting)) + "/" +
           std::string(toString(scene.depth)) + "/" + std::string(toString(scene.projection.type));
}

void expectSamePixels(const std::vector<Scene>& scenes, const std::vector<Image>& a,
                      const std::vector<Image>& b) {
    ASSERT_EQ(a.size(), scenes.size());
    ASSERT_EQ(b.size(), scenes.size());
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const Comparison c = compareImages(a[i], b[i], kIdentical);
        EXPECT_TRUE(c.passed) << describe(scenes[i]) << ": " << c.summary();
    }
}

TEST(Backends, EglAndOsmesaRenderTheSamePixels) {
#if !SHADELAB_HAVE_OSMESA
    if (std::getenv("CI")) FAIL() << "built without OSMesa: nothing to compare EGL with";
    GTEST_SKIP() << "built without OSMesa";
#endif
    const std::vector<Scene> scenes = modeScenes(96, 4);
    std::vector<Image> egl, osmesa;
    for (Backend backend : {Backend::Egl, Backend::Osmesa}) {
        std::unique_ptr<HeadlessRenderer> renderer;
        try {
            renderer = std::make_unique<HeadlessRenderer>(backend);
        } catch (const std::exception& e) {
            if (std::getenv("CI")) FAIL() << e.what();
            GTEST_SKIP() << e.what();
        }
        for (const Scene& scene : scenes)
            (backend == Backend::Egl ? egl : osmesa).push_back(renderer->render(scene));
    }
    expectSamePixels(scenes, osmesa, egl);
}

// Both contexts alive at once and drawn in turn, so each draw must reload the other API's entry points:
// every mode, lighting model, depth mode and projection gives the same pixels on both (llvmpipe compiles
// GLSL 3.30 and GLSL ES 3.00 with highp alike), and the first OpenGL picture is unchanged after the ES one.
TEST(Backends, OpenGlAndOpenGlEsRenderTheSamePixels) {
    std::vector<Scene> scenes = modeScenes(96, 4);
    for (DepthMode depth : {DepthMode::Reversed, DepthMode::ReversedInfinite})
        for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Phong}) {
            Scene scene = litSphereScene(96, LightType::Directional);
            scene.shading = mode;
            scene.depth = depth;
            scenes.push_back(scene);
        }
    Scene orthographic = litSphereScene(96, LightType::Point);
    orthographic.projection = {ProjectionType::Orthographic, 40, -1.4, 1.4, -1.4, 1.4, 0.5, 20};
    scenes.push_back(orthographic);

    std::unique_ptr<HeadlessRenderer> gl, gles;
    try {
        gl = std::make_unique<HeadlessRenderer>(ContextRequest{Backend::Egl, Api::Gl, std::nullopt});
        gles = std::make_unique<HeadlessRenderer>(ContextRequest{Backend::Egl, Api::Gles, std::nullopt});
    } catch (const std::exception& e) {
        if (std::getenv("CI")) FAIL() << e.what();
        GTEST_SKIP() << e.what();
    }
    EXPECT_NE(gles->rendererString().find("OpenGL ES"), std::string::npos) << gles->rendererString();
    EXPECT_EQ(gl->rendererString().find("OpenGL ES"), std::string::npos) << gl->rendererString();
    std::vector<Image> first, es, again;
    for (const Scene& scene : scenes) {
        first.push_back(gl->render(scene));
        es.push_back(gles->render(scene));
        again.push_back(gl->render(scene));
    }
    expectSamePixels(scenes, first, es);
    expectSamePixels(scenes, first, again);
}

} // namespace
} // namespace shadelab::test
