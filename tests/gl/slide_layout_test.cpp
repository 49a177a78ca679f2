// Slides a lecture hall can read: at 1920×1080 every view's in-picture text is at least 28 px a line and
// no two labels overlap; a slide's band sits under the picture, not over it — its rows hold the band over
// the bars and nothing of the picture (no split divider, no legend), the picture above it being the step's
// render at the size that fits there; and the probe's vectors show in the outside view.
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "app/demo/demo_draw.h"
#include "app/demo/demo_state.h"
#include "gl/gl_test_support.h"
#include "shadelab/diagram/outside_view.h"
#include "shadelab/diagram/overlay.h"
#include "shadelab/image/image_file.h"
#include "shadelab/scene/scene_file.h"
#include "shadelab/scene/view.h"

namespace shadelab::test {
namespace {

namespace fs = std::filesystem;

constexpr int kSlideWidth = 1920, kSlideHeight = 1080;
constexpr int kReadableLinePx = 28; // a line of text read from the back of a lecture hall

Lesson bundledLesson() {
    return loadLesson(fs::path(SHADELAB_TEST_DATA) / ".." / "lessons" / "lighting.json");
}

// Where the slide of `step` at 1920×1080 puts its picture: above the step's band.
app::PictureRect slidePicture(const LessonStep& step) {
    const Image band = app::lessonBandImage(step.title, step.caption, kSlideWidth, kSlideHeight);
    return app::pictureAboveBand(kSlideWidth, kSlideHeight, kSlideWidth, kSlideHeight, band.height);
}

// The view's labels: each line at least `minLinePx`, no two boxes overlapping, every box inside the picture.
void expectReadableLabels(const gl::ViewFigures& figures, int width, int height, int minLinePx,
                          const std::string& what) {
    SCOPED_TRACE(what);
    EXPECT_GE(textLineHeight(figures.textScale), minLinePx) << "text scale " << figures.textScale;
    EXPECT_FALSE(figures.labels.empty()) << "the view drew no label";
    for (std::size_t i = 0; i < figures.labels.size(); ++i) {
        const gl::ViewFigures::LabelBox& a = figures.labels[i];
        EXPECT_GE(a.height, minLinePx) << "label " << i;
        EXPECT_TRUE(a.left >= 0 && a.top >= 0 && a.left + a.width <= width && a.top + a.height <= height)
            << "label " << i << " leaves the picture";
        for (std::size_t j = i + 1; j < figures.labels.size(); ++j)
            EXPECT_FALSE(a.overlaps(figures.labels[j])) << "labels " << i << " and " << j << " overlap";
    }
}

// Every step of the bundled lesson at a 1920×1080 slide's picture size, and each view of step 1's scene
// there: lines of 28 px or more, labels apart. At 512×512 (the views' test size) the labels stay apart too.
TEST(SlideLayout, EveryViewsTextIsReadableOnA1080Slide) {
    SHADELAB_REQUIRE_GL(renderer);
    const Lesson lesson = bundledLesson();
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const LessonStep& step = lesson.steps[i];
        const app::PictureRect place = slidePicture(step);
        ASSERT_GE(place.height, kSlideHeight * 3 / 5) << "the band takes at most 2/5 of the slide";
        if (step.scene.view.kind == ViewKind::Scene) continue;
        renderer->render(atSize(step.scene, place.width, place.height));
        expectReadableLabels(renderer->viewFigures(), place.width, place.height, kReadableLinePx,
                             "step " + std::to_string(i + 1) + ": " + step.title);
    }
    const Scene outsideScene = lesson.steps.at(0).scene;
    const app::PictureRect place = slidePicture(lesson.steps.at(0));
    for (const char* text : {"outside", "ndc", "error", "profile", "split:gouraud,phong"}) {
        Scene scene = outsideScene;
        const ViewParse parsed = parseView(text);
        ASSERT_TRUE(parsed.view) << parsed.error;
        scene.view = *parsed.view;
        scene.view.observer = outsideScene.view.observer;
        renderer->render(atSize(scene, place.width, place.height));
        expectReadableLabels(renderer->viewFigures(), place.width, place.height, kReadableLinePx,
                             std::string(text) + " on a slide");
        renderer->render(atSize(scene, kSlideWidth, kSlideHeight));
        expectReadableLabels(renderer->viewFigures(), kSlideWidth, kSlideHeight, kReadableLinePx,
                             std::string(text) + " at 1920x1080");
        renderer->render(atSize(scene, 512, 512));
        expectReadableLabels(renderer->viewFigures(), 512, 512, textLineHeight(2),
                             std::string(text) + " at 512");
    }
}

// `shadelab slides` of the bundled lesson at 1920×1080 on this test's backend.
fs::path exportSlides() {
    const fs::path folder =
        fs::temp_directory_path() / ("shadelab_slide_layout_" + std::to_string(::getpid()));
    fs::remove_all(folder);
    const char* backend = std::getenv("SHADELAB_TEST_BACKEND");
    const std::string flags = backend == nullptr                 ? ""
                              : std::string(backend) == "gles"   ? " --api gles"
                              : std::string(backend) == "osmesa" ? " --backend osmesa"
                                                                 : "";
    const std::string command = std::string("'") + SHADELAB_EXE + "' slides '" + SHADELAB_TEST_DATA +
                                "/../lessons/lighting.json' --size 1920x1080 --out-dir '" + folder.string() +
                                "'" + flags + " > /dev/null";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return folder;
}

// The band's rows hold the band over the bars' colour and nothing else; above it, the step's render at the
// picture's size (the split's divider in it, running down to the band), bars beside it. For the split and
// error steps: the divider and the legend would otherwise run under the band.
TEST(SlideLayout, TheBandIsUnderThePictureNotOverIt) {
    SHADELAB_REQUIRE_GL(renderer);
    const Lesson lesson = bundledLesson();
    const fs::path folder = exportSlides();
    int checked = 0;
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const LessonStep& step = lesson.steps[i];
        const ViewKind kind = step.scene.view.kind;
        if (kind != ViewKind::Split && kind != ViewKind::Error) continue;
        ++checked;
        SCOPED_TRACE("step " + std::to_string(i + 1) + ": " + step.title);
        const Image slide = readPng(folder / slideFileName(i, lesson.steps.size(), step.title));
        ASSERT_EQ(slide.width, kSlideWidth);
        ASSERT_EQ(slide.height, kSlideHeight);
        const Image band = app::lessonBandImage(step.title, step.caption, kSlideWidth, kSlideHeight);
        const app::PictureRect place = slidePicture(step);
        ASSERT_GT(place.x, 0) << "a 16:9 picture above the band is narrower than the slide: bars beside it";
        const std::uint8_t* bar = slide.pixel(0, 0);
        // The band's rows: the band blended over the bar's colour, within rounding.
        std::size_t notBand = 0;
        for (int y = kSlideHeight - band.height; y < kSlideHeight; ++y)
            for (int x = 0; x < kSlideWidth; ++x) {
                const std::uint8_t* b = band.pixel(x, y - (kSlideHeight - band.height));
                const std::uint8_t* s = slide.pixel(x, y);
                for (int c = 0; c < 3; ++c) {
                    const double expected = (b[c] * b[3] + bar[c] * (255.0 - b[3])) / 255.0;
                    if (std::abs(s[c] - expected) > 1.5) {
                        ++notBand;
                        break;
                    }
                }
            }
        EXPECT_EQ(notBand, 0u) << "pixels of the band's rows that are not the band over the bars";
        EXPECT_EQ(place.y + place.height, kSlideHeight - band.height)
            << "the picture ends where the band starts";
        // Above: the render at the picture's size, pixel for pixel.
        const Image picture = renderer->render(atSize(step.scene, place.width, place.height));
        std::size_t differing = 0;
        for (int y = 0; y < place.height; ++y)
            for (int x = 0; x < place.width; ++x)
                for (int c = 0; c < 3; ++c)
                    differing += slide.pixel(place.x + x, place.y + y)[c] != picture.pixel(x, y)[c] ? 1 : 0;
        EXPECT_EQ(differing, 0u) << "the picture above the band is not the step's render at its size";
        if (kind == ViewKind::Split) { // the divider's white column reaches the band's top
            const int divider = place.x + int(std::lround(step.scene.view.at.value_or(0.5) * place.width));
            for (int y = place.y + place.height - 10; y < place.y + place.height; ++y)
                EXPECT_EQ(
                    slide.pixel(divider, y)[0] + slide.pixel(divider, y)[1] + slide.pixel(divider, y)[2], 765)
                    << "row " << y;
        }
    }
    EXPECT_GE(checked, 3) << "the bundled lesson's two split steps and its error step";
    fs::remove_all(folder);
}

// The probe's vectors in the outside view: n, v, l and r drawn from the probed point in world space, as
// the observer sees them, in their colours; nothing without a probe. (In the NDC view none: demo_draw.h.)
TEST(SlideLayout, TheProbesVectorsShowInTheOutsideView) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = bundledLesson().steps.at(0).scene; // the outside view of scenes/outside_view.json
    scene.width = 960;
    scene.height = 540;
    ASSERT_EQ(scene.view.kind, ViewKind::Outside);
    const View outside = scene.view;
    scene.view = View{};
    app::DemoState state(scene);
    state.setViewport(scene.width, scene.height);
    // A point of the first object up and to the left of its centre as the camera sees it (there n, v, l
    // and r point four ways).
    const SceneView cameraView = sceneView(scene);
    const glm::dvec3 right = glm::transpose(glm::dmat3(cameraView.viewFromWorld))[0],
                     up = glm::transpose(glm::dmat3(cameraView.viewFromWorld))[1];
    const SceneObject& object = scene.objects.at(0);
    const glm::dvec3 aim = object.center + 0.6 * object.radius * glm::normalize(up - right);
    const glm::dvec4 clip = cameraView.clipFromView * cameraView.viewFromWorld * glm::dvec4(aim, 1);
    ASSERT_TRUE(
        state.probeAt((clip.x / clip.w + 1) / 2 * scene.width, (1 - clip.y / clip.w) / 2 * scene.height));
    state.editScene().view = outside;
    const Scene drawn = state.drawn();
    const auto probe = state.probe();
    ASSERT_TRUE(probe.has_value());
    ASSERT_GE(probe->light, 0) << "a light that is not ambient: l and r are drawn";
    const auto draw = [&](const std::optional<ProbeReport>& report) {
        return renderer->render(drawn, [&](gl::Renderer& gl) {
            app::drawProbeVectors(gl, drawn, report, drawn.width, drawn.height);
        });
    };
    const Image plain = renderer->render(drawn), withProbe = draw(probe), without = draw(std::nullopt);
    EXPECT_EQ(without.rgba, plain.rgba) << "vectors drawn without a probe";
    if (std::getenv("SHADELAB_WRITE_PROBE")) writePng(withProbe, "outside_probe.png");
    // Where the observer sees the probed point (the mode's point, in the camera's view space, to world).
    const glm::dvec3 pointWorld =
        glm::inverse(cameraView.viewFromWorld) * glm::dvec4(probe->mode.pointView.position, 1);
    const Scene observer = observerScene(drawn);
    const SceneView observed = sceneView(observer);
    const glm::dvec4 o = observed.clipFromView * observed.viewFromWorld * glm::dvec4(pointWorld, 1);
    const glm::dvec2 at((o.x / o.w + 1) / 2 * drawn.width, (1 - o.y / o.w) / 2 * drawn.height);
    const double reach = 0.25 * drawn.height; // 0.6 of the radius, seen from the observer's distance
    for (const auto& [name, colour] : {std::pair{"n", kNormalColor}, std::pair{"v", kToViewerColor},
                                       std::pair{"l", kToLightColor}, std::pair{"r", kSpecularVectorColor}}) {
        std::size_t near = 0, far = 0;
        for (int y = 0; y < drawn.height; ++y)
            for (int x = 0; x < drawn.width; ++x) {
                const std::uint8_t* p = withProbe.pixel(x, y);
                const std::uint8_t* q = plain.pixel(x, y);
                if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) continue;
                bool match = true;
                for (int c = 0; c < 3; ++c) match &= std::abs(p[c] - colour[c] * 255.0) <= 2;
                if (!match) continue;
                (glm::length(glm::dvec2(x, y) - at) <= reach ? near : far) += 1;
            }
        EXPECT_GE(near, 8u) << name << ": its colour drawn from the probed point at (" << at.x << ", " << at.y
                            << ")";
        EXPECT_EQ(far, 0u) << name << ": drawn away from the probed point";
    }
}

} // namespace
} // namespace shadelab::test
