// The bundled lesson (lessons/lighting.json) on every API the suite runs (desktop OpenGL and
// OpenGL ES through EGL, OSMesa): each step's scene draws, at a slide's 16:9 shape, a picture with no NaN or
// Inf in it that shows its objects — except the step of the unnegated perspective matrix, whose picture must
// be the bare background (the lecture's point: w < 0 in front of the eye clips everything).
#include <cmath>
#include <filesystem>

#include "gl/gl_test_support.h"
#include "shadelab/scene/scene_file.h"

namespace shadelab::test {
namespace {

TEST(BundledLesson, EveryStepDrawsItsPicture) {
    SHADELAB_REQUIRE_GL(renderer);
    const Lesson lesson =
        loadLesson(std::filesystem::path(SHADELAB_TEST_DATA) / ".." / "lessons" / "lighting.json");
    ASSERT_GE(lesson.steps.size(), 14u) << "the issue asks for at least 14 steps";
    int emptyOnPurpose = 0;
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        SCOPED_TRACE("step " + std::to_string(i + 1) + ": " + lesson.steps[i].title);
        Scene scene = lesson.steps[i].scene;
        scene.width = 192;
        scene.height = 108;
        const ImageF picture = renderer->renderFloat(scene);
        std::size_t covered = 0, notFinite = 0;
        for (std::size_t p = 0; p < picture.rgba.size(); p += 4) {
            for (int c = 0; c < 4; ++c) notFinite += std::isfinite(picture.rgba[p + c]) ? 0 : 1;
            covered += picture.rgba[p + 3] > 0 ? 1 : 0;
        }
        EXPECT_EQ(notFinite, 0u);
        const bool unnegated = scene.perspectiveMatrix == PerspectiveMatrix::Unnegated &&
                               scene.projection.type != ProjectionType::Orthographic;
        if (unnegated) {
            ++emptyOnPurpose;
            Scene empty = scene;
            empty.objects.clear();
            EXPECT_EQ(renderer->render(scene).rgba, renderer->render(empty).rgba)
                << "the unnegated matrix's picture is not the bare background";
        } else {
            EXPECT_GT(covered, 192u * 108u / 50) << "the step's objects cover under 2 % of the picture";
        }
    }
    EXPECT_EQ(emptyOnPurpose, 1) << "one step shows the WebGL matrix's -1 left out";
}

} // namespace
} // namespace shadelab::test
