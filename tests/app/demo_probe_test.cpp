// The probe and the panel's edits in the demo (src/app/demo/demo_state.h): a click pins the probe, which
// follows the drawn scene, traces the point to the pixel clicked and says when the point is behind the
// object; the click chooses the object the panel edits, and the panel's material and scale edits go to that
// object or to all, a refused value naming the object's place.
#include "app/demo/demo_state.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "shadelab/errors.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app {
namespace {

// A click on the sphere pins the probe; it follows the drawn scene (a mode change re-evaluates it) and a
// click on the background removes it.
TEST(DemoProbe, ClickPinsTheProbeAndTheBackgroundRemovesIt) {
    Scene scene;
    scene.width = scene.height = 200;
    DemoState state{scene};
    state.setViewport(200, 200);
    EXPECT_FALSE(state.probe().has_value());
    ASSERT_TRUE(state.probeAt(100, 100));
    const auto phong = state.probe();
    ASSERT_TRUE(phong.has_value());
    EXPECT_NEAR(phong->exact.pointView.normal.z, 1, 1e-3) << "the centre of the sphere faces the camera";
    EXPECT_NE(state.lastChange().find("probe: phong differs from exact by "), std::string::npos);
    state.apply(Command::Flat);
    const auto flat = state.probe();
    ASSERT_TRUE(flat.has_value());
    EXPECT_NE(flat->mode.pointView.position, phong->mode.pointView.position) << "flat lights the centroid";
    const std::string text = probeText(*flat, ShadingMode::Flat, LightingModel::BlinnPhong);
    for (const char* word : {"ambient", "diffuse", "specular", "pixel", "exact", "n (white)", "h (magenta)"})
        EXPECT_NE(text.find(word), std::string::npos) << word << " in\n" << text;
    EXPECT_FALSE(state.probeAt(2, 2));
    EXPECT_FALSE(state.probe().has_value());
}

// The point tracer: the probe's text follows the exact point through object, world, camera, clip, NDC and
// window coordinates, and the window row is the pixel that was clicked (read back from the text).
TEST(DemoProbe, TheProbeTextTracesThePointToThePixelClicked) {
    Scene scene;
    scene.eye = {1.5, 1, 3.5};
    DemoState state{scene};
    state.setViewport(300, 200);
    ASSERT_TRUE(state.probeAt(170.5, 80.5));
    const std::string text = probeText(state);
    for (const char* stage : {"object p", "world  α = M·p", "camera β = M_cam·α", "clip   M_proj·β",
                              "NDC    clip/w", "window x, y (px), depth"})
        EXPECT_NE(text.find(stage), std::string::npos) << stage << " in\n" << text;
    const std::size_t window = text.find("window x, y (px), depth");
    ASSERT_NE(window, std::string::npos);
    double x = 0, y = 0, depth = 0;
    ASSERT_EQ(std::sscanf(text.c_str() + window + std::strlen("window x, y (px), depth"), "%lf %lf %lf", &x,
                          &y, &depth),
              3)
        << text;
    EXPECT_NEAR(x, 170.5, 1e-3);
    EXPECT_NEAR(y, 80.5, 1e-3);
    EXPECT_TRUE(depth > 0 && depth < 1) << depth;
}

} // namespace
} // namespace shadelab::app

// After an orbit of 180° the probed point is on the far side of the sphere: the table says the
// probe is hidden behind the object (and the window draws no vectors for it: probeFacesAway); orbiting
// back shows it again.
TEST(DemoProbe, AProbeBehindTheObjectIsSaidToBeHidden) {
    using namespace shadelab::app;
    DemoState state{shadelab::Scene{}};
    state.setViewport(200, 200);
    ASSERT_TRUE(state.probeAt(100, 100));
    ASSERT_TRUE(state.probe());
    EXPECT_FALSE(probeFacesAway(*state.probe()));
    EXPECT_EQ(probeText(state).find("probe hidden"), std::string::npos);
    state.drag(360, 0); // 0.5° a pixel: half a turn around the target
    ASSERT_TRUE(state.probe());
    EXPECT_TRUE(probeFacesAway(*state.probe()));
    EXPECT_TRUE(probeText(state).starts_with("probe hidden: behind the object")) << probeText(state);
    state.drag(-360, 0);
    EXPECT_FALSE(probeFacesAway(*state.probe()));
}

// The panel's material edits apply to one chosen object, or to all only when chosen so. A probe
// click picks the object it hits; the status line names what the edits apply to, and the material's name
// says it was edited.
TEST(DemoPanelEdits, AProbeClickChoosesTheObjectThePanelEdits) {
    shadelab::Scene scene;
    scene.width = 200;
    scene.height = 100;
    scene.objects.resize(2);
    scene.objects[0].center = {-1.2, 0, 0};
    scene.objects[1].center = {1.2, 0, 0};
    scene.objects[0].radius = scene.objects[1].radius = 0.8;
    shadelab::app::DemoState state(scene);
    state.setViewport(200, 100);
    EXPECT_EQ(state.editedObjectName(), "object 1 of 2");
    ASSERT_TRUE(state.probeAt(150, 50)) << "the right sphere is under (150, 50)";
    EXPECT_EQ(state.editedObject(), 1);
    EXPECT_EQ(state.editedObjectName(), "object 2 of 2");
    EXPECT_NE(shadelab::app::statusText(state).find("panel edits: object 2 of 2"), std::string::npos)
        << shadelab::app::statusText(state);
    ASSERT_TRUE(state.probeAt(50, 50));
    EXPECT_EQ(state.editedObject(), 0);

    state.chooseEditedObject(0); // chosen explicitly: a click keeps it
    EXPECT_EQ(state.editedObjectName(), "all 2 objects");
    ASSERT_TRUE(state.probeAt(150, 50));
    EXPECT_EQ(state.editedObject(), shadelab::app::DemoState::kAllObjects);

    EXPECT_EQ(state.materialName(), "scene's own");
    shadelab::Material edited = state.scene().objects[0].material;
    edited.shininess = 7;
    state.editMaterial(edited);
    EXPECT_EQ(state.materialName(), "scene's own, edited in the panel");
    state.apply(shadelab::app::Command::NextMaterial);
    EXPECT_EQ(state.materialName().find("edited"), std::string::npos)
        << "M sets a preset: " << state.materialName();

    shadelab::Scene one = scene;
    one.objects.resize(1);
    EXPECT_EQ(shadelab::app::DemoState(one).editedObjectName(), "the object");
}

// The window's panel and the page edit materials through DemoState: the chosen object alone, or with all
// objects chosen, the property that changed on every object while each keeps its others (grid.json's
// spheres differ in shininess and specular); the chooser's numbers (0: all) are clamped to the objects.
TEST(DemoPanelEdits, AnEditChangesTheChosenObjectOrThatPropertyOfAll) {
    using shadelab::app::DemoState;
    shadelab::Scene scene;
    scene.objects.resize(3);
    const double shininess[3] = {5, 20, 60};
    for (std::size_t i = 0; i < 3; ++i) {
        scene.objects[i].center = {double(i) * 2.5 - 2.5, 0, 0};
        scene.objects[i].material.shininess = shininess[i];
        scene.objects[i].material.specular = glm::dvec3(0.25 * double(i + 1));
    }
    DemoState state(scene);
    EXPECT_EQ(state.editedObjectNumber(), 1);
    state.chooseEditedObject(3);
    EXPECT_EQ(state.editedObject(), 2);
    ASSERT_EQ(state.shownObject(), std::optional<std::size_t>(2));
    shadelab::Material m = state.scene().objects[2].material;
    m.shininess = 31.6;
    m.diffuse = {0.1, 0.9, 0.1};
    state.editMaterial(m);
    EXPECT_EQ(state.scene().objects[2].material, m);
    EXPECT_EQ(state.scene().objects[0].material, scene.objects[0].material);
    EXPECT_EQ(state.scene().objects[1].material, scene.objects[1].material);
    EXPECT_EQ(state.materialName(), "scene's own, edited in the panel");

    state.chooseEditedObject(0);
    EXPECT_EQ(state.editedObject(), DemoState::kAllObjects);
    EXPECT_EQ(state.editedObjectNumber(), 0);
    ASSERT_EQ(state.shownObject(), std::optional<std::size_t>(0)); // all: the first object's values show
    m = state.scene().objects[0].material;
    m.shininess = 100;
    state.editMaterial(m);
    for (std::size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(state.scene().objects[i].material.shininess, 100);
        EXPECT_EQ(state.scene().objects[i].material.specular, scene.objects[i].material.specular)
            << "an unchanged property was copied from the first object";
    }
    EXPECT_EQ(state.scene().objects[2].material.diffuse, glm::dvec3(0.1, 0.9, 0.1));

    state.chooseEditedObject(7);
    EXPECT_EQ(state.editedObject(), 2) << "past the last object: the last";
    state.chooseEditedObject(-3);
    EXPECT_EQ(state.editedObject(), DemoState::kAllObjects);
    shadelab::Scene none = scene;
    none.objects.clear();
    DemoState empty(none);
    EXPECT_FALSE(empty.shownObject().has_value());
    empty.editMaterial(m); // nothing to edit, and no crash
    EXPECT_EQ(empty.materialName(), "scene's own");
}

// The panel's scale: the chosen object's, or every object's with all chosen; a zero or non-finite
// component is refused with a message naming the object's place and changes nothing. J then toggles the
// normal matrix, and the title says so.
TEST(DemoObjects, ScaleEditsTheChosenObjectOrAllAndJTogglesTheNormalMatrix) {
    using namespace shadelab::app;
    shadelab::Scene scene =
        shadelab::parseScene(R"({"objects": [{"center": [-2, 0, 0]}, {"center": [2, 0, 0]}]})");
    DemoState state(scene);
    state.chooseEditedObject(2);
    state.editScale({1.5, 0.5, 1});
    EXPECT_EQ(state.scene().objects[1].scale, glm::dvec3(1.5, 0.5, 1));
    EXPECT_EQ(state.scene().objects[0].scale, glm::dvec3(1));
    try {
        state.editScale({1, 0, 1});
        ADD_FAILURE() << "a zero scale was accepted";
    } catch (const shadelab::InputError& e) {
        EXPECT_STREQ(e.what(), "objects[1].scale[1]: must be non-zero, got 0");
    }
    EXPECT_THROW(state.editScale({std::nan(""), 1, 1}), shadelab::InputError);
    // What 32-bit float cannot carry is refused as a scene file's scale is (exact shading drew nothing).
    try {
        state.editScale({1, 1, 1e-20});
        ADD_FAILURE() << "a scale of 1e-20 was accepted";
    } catch (const shadelab::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("objects[1]"), std::string::npos) << e.what();
    }
    EXPECT_EQ(state.scene().objects[1].scale, glm::dvec3(1.5, 0.5, 1)) << "a refused edit changed the scale";
    state.chooseEditedObject(0); // all: the first object's scale shows; y changes on both, x stays each's
    state.editScale({1, 2, 1});
    EXPECT_EQ(state.scene().objects[0].scale, glm::dvec3(1, 2, 1));
    EXPECT_EQ(state.scene().objects[1].scale, glm::dvec3(1.5, 2, 1));

    EXPECT_EQ(state.scene().normalMatrix, shadelab::NormalMatrixRule::InverseTranspose);
    ASSERT_TRUE(state.apply(*commandForKey('J')));
    EXPECT_EQ(state.scene().normalMatrix, shadelab::NormalMatrixRule::Model);
    EXPECT_NE(windowTitle(state, 1.0).find("normals by M"), std::string::npos) << windowTitle(state, 1.0);
    EXPECT_NE(presentationLabel(state).find("NORMALS BY M"), std::string::npos) << presentationLabel(state);
    EXPECT_EQ(state.lastChange(), "normals transformed by M: wrong wherever M scales unevenly");
    ASSERT_TRUE(state.apply(*commandForKey('J')));
    EXPECT_EQ(state.scene().normalMatrix, shadelab::NormalMatrixRule::InverseTranspose);
    EXPECT_EQ(windowTitle(state, 1.0).find("normals by M"), std::string::npos);
}
