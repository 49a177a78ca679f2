// The scene draw (src/gl/scene_draw.h) takes what it writes as an option of each draw, never as a mode
// left behind (the way Magnum's PhongGL takes its ObjectId flag): a draw with the error view's object ids
// or the NDC view's observer leaves the next plain draw as a new SceneDraw would make it.
#include <set>

#include "gl/gl_test_support.h"
#include "gl/scene_draw.h" // private (src/gl/)
#include "shadelab/gl/loader.h"
#include "shadelab/gl/render_target.h"

namespace shadelab::test {
namespace {

// Two spheres side by side in exact shading, the second of another material.
Scene twoExactSpheres() {
    Scene scene = litSphereScene(96, LightType::Point);
    scene.shading = ShadingMode::Exact;
    scene.objects = {SceneObject{}, SceneObject{}};
    for (std::size_t i = 0; i < 2; ++i) {
        scene.objects[i].center = {i == 0 ? -0.6 : 0.6, 0, 0};
        scene.objects[i].radius = 0.45;
    }
    scene.objects[1].material.diffuse = {0.2, 0.7, 0.3};
    return scene;
}

// The distinct alpha values of the covered pixels (the clear leaves alpha 0).
std::set<float> coveredAlphas(const ImageF& image) {
    std::set<float> alphas;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (const float a = image.pixel(x, y)[3]; a > 0) alphas.insert(a);
    return alphas;
}

// `draws` called with a SceneDraw and a float target of the scene's size bound, inside the test context.
template <typename Draws> void withFloatTarget(HeadlessRenderer& renderer, const Scene& scene, Draws draws) {
    (void)renderer.render(scene, [&](gl::Renderer&) {
        if (!gl::capabilities().floatColorTargets) GTEST_SKIP() << "no float colour targets in this context";
        const gl::RenderTarget target(scene.width, scene.height, gl::ColorFormat::Rgba32F,
                                      gl::depthFormatFor(scene.depth));
        gl::SceneDraw sceneDraw;
        draws(sceneDraw, target);
    });
}

TEST(SceneDraw, ObjectIdsAreAnOptionOfOneDraw) {
    SHADELAB_REQUIRE_GL(renderer);
    const Scene scene = twoExactSpheres();
    const gl::Viewport viewport{0, scene.width, scene.height};
    gl::DrawOptions ids;
    ids.exactObjectIds = true;
    withFloatTarget(*renderer, scene, [&](gl::SceneDraw& sceneDraw, const gl::RenderTarget& target) {
        target.bind();
        sceneDraw.draw(scene, viewport, ids);
        EXPECT_EQ(coveredAlphas(target.readFloat()), (std::set<float>{1.0f, 2.0f}))
            << "each object's index + 1";
        target.bind();
        sceneDraw.draw(scene, viewport, {});
        EXPECT_EQ(coveredAlphas(target.readFloat()), (std::set<float>{1.0f})) << "the next draw, without ids";
        target.bind();
        sceneDraw.draw(scene, viewport, ids);
        EXPECT_EQ(coveredAlphas(target.readFloat()), (std::set<float>{1.0f, 2.0f})) << "and with them again";
    });
}

TEST(SceneDraw, TheNdcObserverIsAnOptionOfOneDraw) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = twoExactSpheres();
    scene.shading = ShadingMode::Phong; // the NDC view draws meshes
    scene.overlay = Overlay::Wireframe; // drawn through the observer too
    const gl::Viewport viewport{0, scene.width, scene.height};
    gl::DrawOptions observed;
    // An observer of the NDC cube from the side: the plain picture and the observed one differ.
    Scene observer = scene;
    observer.eye = {4, 1, 2};
    observer.target = {0, 0, 0};
    const SceneView observerView = sceneView(observer);
    observed.observerClipFromNdc = observerView.clipFromView * observerView.viewFromWorld;
    withFloatTarget(*renderer, scene, [&](gl::SceneDraw& sceneDraw, const gl::RenderTarget& target) {
        target.bind();
        sceneDraw.draw(scene, viewport, {});
        const ImageF plain = target.readFloat();
        target.bind();
        sceneDraw.draw(scene, viewport, observed);
        const ImageF seen = target.readFloat();
        EXPECT_NE(seen.rgba, plain.rgba) << "the observer's picture is another picture";
        target.bind();
        sceneDraw.draw(scene, viewport, {});
        EXPECT_EQ(target.readFloat().rgba, plain.rgba) << "a plain draw after the observed one";
    });
}

} // namespace
} // namespace shadelab::test
