// A frame of an unchanged scene makes no heap allocation — so it builds no string, keys no map and copies
// no scene (DESIGN §7's one renderer: render, report, bench, the window and the page all draw through it) —
// and the caches that make that so never show a stale picture: each picture drawn through the process's
// renderer, after others, equals a new renderer's picture of the same scene.
// Allocations are counted by gl/allocation_watch.h (linked into this executable only).
#include <cctype>
#include <new>
#include <string>
#include <vector>

#include "gl/allocation_watch.h"
#include "gl/gl_test_support.h"
#include "shadelab/gl/renderer.h"
#include "shadelab/gl/screen_pass.h"
#include "shadelab/scene/view.h"

namespace shadelab::test {
namespace {

struct FrameCase {
    std::string name;
    Scene scene;
    gl::Specialization specialization = gl::Specialization::Values;
};

void PrintTo(const FrameCase& c, std::ostream* os) {
    *os << c.name;
}

Scene withView(Scene scene, std::string_view text) {
    const ViewParse parsed = parseView(text);
    EXPECT_TRUE(parsed.view.has_value()) << text << ": " << parsed.error;
    scene.view = parsed.view.value_or(View{});
    return scene;
}

// Every shading mode under both lighting models and each specialization; one term; the wrong matrices;
// orthographic; several objects of several materials; each overlay (wireframe, normals, lights); and every
// view with its labels: error, split (a side a view too), profile, outside and NDC.
std::vector<FrameCase> frameCases() {
    std::vector<FrameCase> cases;
    const Scene base = litSphereScene(96, LightType::Spot);
    for (const ShadingMode mode :
         {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong, ShadingMode::Toon, ShadingMode::Exact})
        for (const LightingModel lighting : {LightingModel::Phong, LightingModel::BlinnPhong}) {
            Scene scene = base;
            scene.shading = mode;
            scene.lighting = lighting;
            cases.push_back({std::string(toString(mode)) + "-" + std::string(toString(lighting)), scene});
        }
    for (const auto& [specialization, label] : kSpecializationLabels)
        cases.push_back({std::string("phong-") + label, base, specialization});
    Scene term = base;
    term.term = LightingTerm::Specular;
    cases.push_back({"specular-term", term});
    Scene byM = base;
    byM.normalMatrix = NormalMatrixRule::Model;
    byM.objects[0].scale = {1, 0.5, 1};
    cases.push_back({"normals-by-M", byM});
    Scene orthographic = base;
    orthographic.projection = Projection{};
    orthographic.projection.type = ProjectionType::Orthographic;
    orthographic.projection.left = orthographic.projection.bottom = -1.5;
    orthographic.projection.right = orthographic.projection.top = 1.5;
    cases.push_back({"orthographic", orthographic});
    Scene several = base;
    several.objects = {SceneObject{}, SceneObject{}, SceneObject{}};
    for (std::size_t i = 0; i < several.objects.size(); ++i) {
        several.objects[i].center = {double(i) - 1, 0, 0};
        several.objects[i].radius = 0.4;
        several.objects[i].material.diffuse = {0.2 * double(i), 0.5, 0.3};
    }
    cases.push_back({"three-objects", several});
    for (const Overlay overlay : {Overlay::Wireframe, Overlay::Normals, Overlay::Lights}) {
        Scene overlaid = base;
        overlaid.overlay = overlay;
        cases.push_back({std::string(toString(overlay)), overlaid});
    }
    for (const char* view : {"error", "split:gouraud,phong", "split:phong@2,phong@6", "split:flat,exact",
                             "split:scene,outside", "profile", "outside", "ndc"})
        cases.push_back({view, withView(base, view)});
    Scene profileOverlaid = withView(base, "profile");
    profileOverlaid.overlay = Overlay::Wireframe;
    cases.push_back({"profile-wireframe", profileOverlaid});
    Scene orthographicNdc = withView(orthographic, "ndc");
    cases.push_back({"ndc-orthographic", orthographicNdc});
    return cases;
}

class SteadyFrame : public ::testing::TestWithParam<FrameCase> {};

TEST_P(SteadyFrame, AllocatesNothing) {
    SHADELAB_REQUIRE_GL(renderer);
    const FrameCase& c = GetParam();
    renderer->setSpecialization(c.specialization);
    long counts[2] = {-1, -1};
    renderer->render(c.scene, [&](gl::Renderer& drawing) {
        drawing.render(c.scene, c.scene.width,
                       c.scene.height); // the first frame of the scene builds its plan
        for (long& count : counts) {
            const long before = allocationCount();
            drawing.render(c.scene, c.scene.width, c.scene.height);
            count = allocationCount() - before;
        }
    });
    renderer->setSpecialization(gl::Specialization::Values);
    EXPECT_EQ(counts[0], 0) << "heap allocations in a frame of an unchanged scene";
    EXPECT_EQ(counts[1], 0) << "heap allocations in the next frame";
}

INSTANTIATE_TEST_SUITE_P(Cases, SteadyFrame, ::testing::ValuesIn(frameCases()), [](const auto& info) {
    std::string name = info.param.name;
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return name;
});

// The labels, the views' drawings and the draw plans are kept between frames and remade only when what
// they show changes. Drawn one after another through the process's renderer, each of these scenes (whose
// labels, sides, levels, figures and drawings change from one to the next, and come back) gives the
// picture a new renderer gives it, pixel for pixel.
TEST(CachedPictures, MatchANewRenderersPictures) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene base = litSphereScene(160, LightType::Point);
    std::vector<Scene> scenes;
    for (int level : {2, 3, 2}) {
        Scene scene = withView(base, "error");
        scene.objects[0].subdivisions = level;
        scenes.push_back(scene);
    }
    Scene toon = withView(base, "error");
    toon.shading = ShadingMode::Toon;
    scenes.push_back(toon);
    for (const char* view : {"split:gouraud,phong", "split:phong@2,phong@6", "split:gouraud,phong", "outside",
                             "ndc", "profile", "split:scene,outside"})
        scenes.push_back(withView(base, view));
    Scene moved = withView(base, "outside");
    moved.eye = {1, 1, 4};
    scenes.push_back(moved);
    Scene unnegated = withView(base, "outside");
    unnegated.perspectiveMatrix = PerspectiveMatrix::Unnegated;
    scenes.push_back(unnegated);
    Scene orthographicNdc = withView(base, "ndc");
    orthographicNdc.projection.type = ProjectionType::Orthographic;
    orthographicNdc.projection.left = orthographicNdc.projection.bottom = -1.5;
    orthographicNdc.projection.right = orthographicNdc.projection.top = 1.5;
    scenes.push_back(orthographicNdc);
    Scene row = withView(base, "profile");
    row.view.at = 0.3;
    scenes.push_back(row);
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const Scene& scene = scenes[i];
        const Image kept = renderer->render(scene);
        const Image fresh = renderer->render(scene, [&](gl::Renderer&) {
            gl::Renderer newRenderer;
            newRenderer.render(scene, scene.width, scene.height);
        });
        ASSERT_EQ(kept.rgba, fresh.rgba) << "scene " << i << " (" << toString(scene.view)
                                         << "): the kept renderer's picture differs from a new renderer's";
    }
}

// A sprite whose image could not be made (or uploaded) is made again at the next update with the same key,
// rather than shown stale or empty from then on.
TEST(KeyedSprite, AFailedMakeIsTriedAgain) {
    SHADELAB_REQUIRE_GL(renderer);
    (void)renderer->render(litSphereScene(8, LightType::Point), [&](gl::Renderer&) {
        gl::KeyedSprite<int> sprite;
        int made = 0;
        EXPECT_THROW(sprite.update(1, [&]() -> Image { throw std::bad_alloc(); }), std::bad_alloc);
        sprite.update(1, [&] {
            ++made;
            return Image(3, 2);
        });
        EXPECT_EQ(made, 1);
        EXPECT_EQ(sprite.width(), 3);
        sprite.update(1, [&] {
            ++made;
            return Image(5, 5);
        });
        EXPECT_EQ(made, 1) << "the same key: nothing made";
        EXPECT_EQ(sprite.height(), 2);
    });
}

} // namespace
} // namespace shadelab::test
