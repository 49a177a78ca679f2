// The "view" scene value (view.h): its spellings, how a split side reads, round trips through the scene
// JSON, and the messages for what it refuses.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "shadelab/diagram/outside_view.h"
#include "shadelab/errors.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/view.h"

namespace shadelab {
namespace {

// A side that sets only these (the rest the scene's own).
SplitSide side(std::optional<ShadingMode> shading, std::optional<LightingModel> lighting,
               std::optional<int> level) {
    SplitSide out;
    out.shading = shading;
    out.lighting = lighting;
    out.level = level;
    return out;
}

View parsed(std::string_view text) {
    const ViewParse p = parseView(text);
    EXPECT_TRUE(p.view) << text << ": " << p.error;
    return p.view.value_or(View{});
}

TEST(ViewSpelling, TheIssuesExamplesReadAsMeant) {
    EXPECT_EQ(parsed("scene").kind, ViewKind::Scene);
    EXPECT_EQ(parsed("error").kind, ViewKind::Error);
    EXPECT_EQ(parsed("profile").kind, ViewKind::Profile);

    const View modes = parsed("split:gouraud,phong");
    EXPECT_EQ(modes.kind, ViewKind::Split);
    EXPECT_EQ(modes.left, side(ShadingMode::Gouraud, std::nullopt, std::nullopt));
    EXPECT_EQ(modes.right, side(ShadingMode::Phong, std::nullopt, std::nullopt));

    const View levels = parsed("split:phong@4,phong@6");
    EXPECT_EQ(levels.left, side(ShadingMode::Phong, std::nullopt, 4));
    EXPECT_EQ(levels.right, side(ShadingMode::Phong, std::nullopt, 6));

    // "phong" beside "blinn-phong" is the lighting model: the split compares the two lighting models.
    const View lighting = parsed("split:phong,blinn-phong");
    EXPECT_EQ(lighting.left, side(std::nullopt, LightingModel::Phong, std::nullopt));
    EXPECT_EQ(lighting.right, side(std::nullopt, LightingModel::BlinnPhong, std::nullopt));

    // ... but a name that is only a shading mode stays one, and shading/lighting names both.
    const View mixed = parsed("split:gouraud,blinn-phong");
    EXPECT_EQ(mixed.left, side(ShadingMode::Gouraud, std::nullopt, std::nullopt));
    EXPECT_EQ(mixed.right, side(std::nullopt, LightingModel::BlinnPhong, std::nullopt));
    const View both = parsed("split:phong/phong@5,exact/blinn-phong");
    EXPECT_EQ(both.left, side(ShadingMode::Phong, LightingModel::Phong, 5));
    EXPECT_EQ(both.right, side(ShadingMode::Exact, LightingModel::BlinnPhong, std::nullopt));
    EXPECT_EQ(parsed("split:@3,@7").left.level, 3);

    // The camera's picture beside the outside or NDC view of the scene.
    const View outside = parsed("split:scene,outside");
    EXPECT_EQ(outside.left, SplitSide{});
    EXPECT_EQ(outside.right.view, ViewKind::Outside);
    EXPECT_EQ(parsed("split:gouraud,ndc").right.view, ViewKind::Ndc);
    EXPECT_EQ(parsed("outside").kind, ViewKind::Outside);
    EXPECT_EQ(parsed("ndc").kind, ViewKind::Ndc);
}

TEST(ViewSpelling, EveryParsedViewWritesBackToItself) {
    for (const char* text : {"scene",
                             "error",
                             "profile",
                             "split:gouraud,phong",
                             "split:phong@4,phong@6",
                             "split:phong,blinn-phong",
                             "split:gouraud,blinn-phong",
                             "split:flat/phong@2,exact",
                             "split:@3,@7",
                             "split:toon,exact",
                             "outside",
                             "ndc",
                             "split:scene,outside",
                             "split:phong,ndc",
                             "split:outside,ndc",
                             "split:phong{shininess=8},phong{shininess=150}",
                             "side-by-side:phong{shininess=8},phong{shininess=150}",
                             "split:phong{normal_matrix=model},phong{normal_matrix=inverse-transpose}",
                             "side-by-side:gouraud@3{term=specular,diffuse=0.7 0.2 0.2},phong/phong@5",
                             "split:{ambient=0.25},{specular=0,shininess=2.5}",
                             "side-by-side:scene,outside"}) {
        const View view = parsed(text);
        EXPECT_EQ(toString(view), text);
        EXPECT_EQ(parsed(toString(view)), view) << text;
    }
}

// A side's settings: the term, the normal matrix and every object's material values, applied over the
// scene's own; side-by-side is the same split laid out in two halves.
TEST(ViewSpelling, ASideCarriesMaterialTermAndNormalMatrix) {
    const View shininess = parsed("side-by-side:phong{shininess=8},phong{ shininess = 150 }");
    EXPECT_EQ(shininess.kind, ViewKind::Split);
    EXPECT_EQ(shininess.layout, SplitLayout::SideBySide);
    EXPECT_EQ(shininess.left.shading, ShadingMode::Phong);
    EXPECT_EQ(shininess.left.shininess, 8.0);
    EXPECT_EQ(shininess.right.shininess, 150.0);
    EXPECT_EQ(parsed("split:phong{shininess=8},phong{shininess=150}").layout, SplitLayout::Divider);

    const View settings = parsed("split:gouraud@2{term=diffuse, normal_matrix=model, diffuse=0.5 0.25 1, "
                                 "specular=0.5, ambient=0},exact");
    const SplitSide& left = settings.left;
    EXPECT_EQ(left.term, LightingTerm::Diffuse);
    EXPECT_EQ(left.normalMatrix, NormalMatrixRule::Model);
    EXPECT_EQ(left.diffuse, glm::dvec3(0.5, 0.25, 1));
    EXPECT_EQ(left.specular, glm::dvec3(0.5));
    EXPECT_EQ(left.ambient, glm::dvec3(0));
    EXPECT_EQ(left.level, 2);

    // Applied to every object, over the scene's values; what a side leaves unset stays the scene's.
    Scene scene;
    scene.objects.push_back(scene.objects[0]);
    scene.objects[1].material.shininess = 64;
    Scene applied = scene;
    applySplitSideValues(applied, left);
    EXPECT_EQ(applied.shading, ShadingMode::Gouraud);
    EXPECT_EQ(applied.term, LightingTerm::Diffuse);
    EXPECT_EQ(applied.normalMatrix, NormalMatrixRule::Model);
    EXPECT_EQ(applied.lighting, scene.lighting);
    for (const SceneObject& object : applied.objects) {
        EXPECT_EQ(object.subdivisions, 2);
        EXPECT_EQ(object.material.diffuse, glm::dvec3(0.5, 0.25, 1));
        EXPECT_EQ(object.material.specular, glm::dvec3(0.5));
    }
    EXPECT_EQ(applied.objects[1].material.shininess, 64) << "unset: the object's own";
    // Sides that differ only in a setting are two different sides.
    EXPECT_TRUE(parseView("split:phong{term=ambient},phong").view.has_value());
    // In a scene file, the settings' commas are the side's, not the split's.
    Scene read =
        parseScene(R"({"view": "side-by-side:phong{shininess=8,term=specular},phong{shininess=150}"})");
    EXPECT_EQ(read.view.layout, SplitLayout::SideBySide);
    EXPECT_EQ(read.view.left.term, LightingTerm::Specular);
    EXPECT_EQ(parseScene(sceneToJson(read)).view, read.view);
}

TEST(ViewSpelling, RefusalsSayWhatIsWrongAndWhatIsExpected) {
    struct Case {
        const char* text;
        const char* says;
    };
    for (const Case& c :
         {Case{"errors", "expected scene, error, profile, outside, ndc, split:A,B or side-by-side:A,B"},
          Case{"split:phong{shininess=0.5},phong", "shininess in \"shininess=0.5\" must be a number >= 1"},
          Case{"split:phong{shininess=nan},phong", "must be a number >= 1"},
          Case{"split:phong{shine=8},phong", "unknown setting \"shine\""},
          Case{"split:phong{shininess},phong", "is key=value"},
          Case{"split:phong{term=glossy},phong", "term in \"term=glossy\" must be all, ambient"},
          Case{"split:phong{normal_matrix=m},phong", "must be inverse-transpose or model"},
          Case{"split:phong{diffuse=1 2},phong",
               "diffuse in \"diffuse=1 2\" must be a grey or three numbers"},
          Case{"split:phong{diffuse=-1},phong", "must be a grey or three numbers >= 0"},
          Case{"split:phong{shininess=8,shininess=9},phong", "\"shininess\" is set twice"},
          Case{"split:phong{shininess=8}x,phong", "one {…} at its end"},
          Case{"split:phong{shininess=8},phong{shininess=8}", "both sides of the split are the same"},
          Case{"split:phong", "two sides separated by one comma"},
          Case{"split:a,b,c", "two sides separated by one comma"},
          Case{"split:phong,phongg", "unknown shading \"phongg\""},
          Case{"split:phong/blin,phong", "unknown lighting \"blin\""},
          Case{"split:phong@11,phong", "0..10"},
          Case{"split:phong@x,phong", "0..10"},
          Case{"split:phong@-1,phong", "0..10"},
          Case{"split:,phong", "a split side is empty"},
          Case{"split:phong,phong", "both sides of the split are the same"},
          Case{"split:outside,outside", "both sides of the split are the same"},
          Case{"split:outside@3,phong", "unknown shading \"outside\""}}) {
        const ViewParse p = parseView(c.text);
        EXPECT_FALSE(p.view) << c.text;
        EXPECT_NE(p.error.find(c.says), std::string::npos) << c.text << ": " << p.error;
    }
}

TEST(ViewScene, SavedAndReadBackWithItsPosition) {
    Scene scene;
    scene.view = parsed("split:phong@3,exact");
    scene.view.at = 0.25;
    EXPECT_EQ(parseScene(sceneToJson(scene)), scene);
    scene.view = parsed("error");
    scene.view.at.reset();
    EXPECT_EQ(parseScene(sceneToJson(scene)), scene);
    EXPECT_EQ(parseScene(R"({"view": "profile", "view_at": 0.5})").view.at, 0.5);
}

TEST(ViewScene, BadValuesNameTheKey) {
    auto message = [](const char* json) {
        try {
            parseScene(json, "s.json");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(
        message(R"({"view": "split:x,phong"})"),
        "s.json: view: \"split:x,phong\": unknown shading \"x\" in a split side; expected flat, gouraud, "
        "phong, toon or exact (or scene, outside or ndc alone)");
    EXPECT_EQ(message(R"({"view": 3})").find("s.json: view: "), 0u);
    EXPECT_EQ(message(R"({"view_at": 1.5})"),
              "s.json: view_at: must be between 0 and 1 (a fraction of the picture), got 1.5");
    Scene scene;
    scene.view.at = -0.1;
    EXPECT_THROW(validateScene(scene), InputError);
}

// The outside view's observer (outside_view.h) sees the eye and every object inside its clip volume,
// whatever the far plane and wherever it is orbited, and the NDC view's observer sees the whole cube.
TEST(ObserverFraming, TheEyeAndTheObjectsAreInsideTheObserversVolume) {
    for (double far : {7.0, 20.0, 1e6}) {
        for (const Observer& observer : {Observer{}, Observer{-150, -80, 1}, Observer{90, 0, 0.5}}) {
            Scene scene;
            scene.width = 320;
            scene.height = 200;
            scene.projection.far = far;
            scene.objects = {SceneObject{}, SceneObject{}};
            scene.objects[1].center = {2, -1, -3};
            scene.view.kind = ViewKind::Outside;
            scene.view.observer = observer;
            const Scene seen = observerScene(scene);
            EXPECT_NO_THROW(validateScene(seen));
            const SceneView view = sceneView(seen);
            std::vector<glm::dvec3> points{scene.eye};
            for (const SceneObject& o : scene.objects) points.push_back(o.center);
            for (const glm::dvec3& p : points) {
                const glm::dvec4 clip = view.clipFromView * view.viewFromWorld * glm::dvec4(p, 1);
                const bool inside = clip.w > 0 && std::abs(clip.x) <= clip.w && std::abs(clip.y) <= clip.w &&
                                    std::abs(clip.z) <= clip.w;
                // Zoomed in to half, the observer may stand among the points; at zoom 1 it sees them all.
                if (observer.zoom >= 1) {
                    EXPECT_TRUE(inside)
                        << "far " << far << ", azimuth " << observer.azimuthDeg << ": (" << p.x << ", " << p.y
                        << ", " << p.z << ") outside the observer's view";
                }
            }
        }
    }
    Scene scene;
    scene.view.kind = ViewKind::Ndc;
    const Scene cube = ndcObserverScene(scene);
    const SceneView view = sceneView(cube);
    for (int i = 0; i < 8; ++i) {
        const glm::dvec4 clip = view.clipFromView * view.viewFromWorld *
                                glm::dvec4(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1, 1);
        EXPECT_TRUE(clip.w > 0 && std::abs(clip.x) < clip.w && std::abs(clip.y) < clip.w &&
                    std::abs(clip.z) < clip.w)
            << "cube corner " << i;
    }
}

} // namespace
} // namespace shadelab
