// The scene's "perspective_matrix" (DESIGN §2): the WebGL matrix, the lecture's perspective matrix times −1,
// or the unnegated one, which gives every point in front of the eye w < 0: the clipper removes everything, in
// every shading mode (exact shading's ray cast makes the same w > 0 test), and the reference agrees. An
// orthographic matrix has no −1 to leave out.
#include <algorithm>
#include <cstdio>

#include "gl/gl_test_support.h"

namespace shadelab::test {
namespace {

std::size_t coveredPixels(const Image& image) {
    std::size_t covered = 0;
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) covered += image.rgba[i] != 0;
    return covered;
}

TEST(PerspectiveMatrix, UnnegatedDrawsNoObjectPixelWhereWebGlDrawsThePicture) {
    SHADELAB_REQUIRE_GL(renderer);
    for (const char* name : {"perspective_point", "off_centre_frustum"}) {
        Scene scene = analyticCase(name).scene();
        scene.width = scene.height = 128;
        for (ShadingMode mode : kAllShadingModes) {
            for (Overlay overlay : {Overlay::None, Overlay::Wireframe}) {
                if (mode == ShadingMode::Exact && overlay != Overlay::None) continue; // no mesh to overlay
                scene.shading = mode;
                scene.overlay = overlay;
                SCOPED_TRACE(std::string(name) + ", " + std::string(toString(mode)) + ", overlay " +
                             std::string(toString(overlay)));
                scene.perspectiveMatrix = PerspectiveMatrix::WebGl;
                const std::size_t drawn = coveredPixels(renderer->render(scene));
                scene.perspectiveMatrix = PerspectiveMatrix::Unnegated;
                const Image unnegated = renderer->render(scene);
                EXPECT_GT(drawn, 2000u) << "the WebGL matrix draws the objects";
                EXPECT_EQ(coveredPixels(unnegated), 0u) << "the unnegated matrix drew object pixels";
                Scene empty = scene;
                empty.objects.clear();
                const Image background = renderer->render(empty);
                EXPECT_EQ(unnegated.rgba, background.rgba)
                    << "the unnegated picture is not the bare background";
            }
        }
        scene.shading = ShadingMode::Phong;
        scene.overlay = Overlay::None;
        scene.perspectiveMatrix = PerspectiveMatrix::Unnegated;
        const ReferenceImage reference = renderReference(scene);
        EXPECT_EQ(std::count(reference.objectId.begin(), reference.objectId.end(), -1),
                  std::ptrdiff_t(reference.objectId.size()))
            << "the reference hit an object through the unnegated matrix";
    }
}

// Orthographic: w = 1 everywhere, and the picture is the WebGL one to the byte.
TEST(PerspectiveMatrix, OrthographicHasNoMinusOneToLeaveOut) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = analyticCase("orthographic").scene();
    scene.width = scene.height = 128;
    for (ShadingMode mode : kAllShadingModes) {
        scene.shading = mode;
        SCOPED_TRACE(std::string(toString(mode)));
        scene.perspectiveMatrix = PerspectiveMatrix::WebGl;
        const Image webgl = renderer->render(scene);
        scene.perspectiveMatrix = PerspectiveMatrix::Unnegated;
        EXPECT_GT(coveredPixels(webgl), 2000u);
        EXPECT_EQ(renderer->render(scene).rgba, webgl.rgba);
    }
}

} // namespace
} // namespace shadelab::test
