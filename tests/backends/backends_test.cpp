// EGL and OSMesa renders of the same scenes compared with each other (DESIGN §6: on Mesa 22.3 llvmpipe
// both give bit-identical images). Both contexts are made in one process, one after the other, through
// the one loader.
#include <cstdlib>

#include <gtest/gtest.h>

#include "gl/gl_test_support.h"

namespace shadelab::test {
namespace {

TEST(Backends, EglAndOsmesaRenderTheSamePixels) {
#if !SHADELAB_HAVE_OSMESA
    if (std::getenv("CI")) FAIL() << "built without OSMesa: nothing to compare EGL with";
    GTEST_SKIP() << "built without OSMesa";
#endif
    std::vector<Image> egl, osmesa;
    std::vector<Scene> scenes;
    for (ShadingMode mode : kShadingModes) {
        for (LightingModel model : kLightingModels) {
            Scene scene = litSphereScene(96, LightType::Spot);
            scene.lights.push_back(litSphereScene(96, LightType::Point).lights[0]);
            scene.objects[0].subdivisions = 4;
            scene.shading = mode;
            scene.lighting = model;
            scenes.push_back(scene);
        }
    }
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
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const Comparison c = compareImages(osmesa[i], egl[i], Tolerance{0, 0, 0});
        EXPECT_TRUE(c.passed) << toString(scenes[i].shading) << "/" << toString(scenes[i].lighting) << ": "
                              << c.summary();
    }
}

} // namespace
} // namespace shadelab::test
