// The shape of the edited object (DESIGN §1: the sphere or Newell's teapot) in the demo: D switches it, the
// "shape" setter sets it by name for the panels, + and − keep within the teapot's levels 0..8, and the
// status line and the title name it. Expected values come from DESIGN and teapot.h, not from the demo.
#include <string>

#include <gtest/gtest.h>

#include "shadelab/geometry/sphere.h"

#include "shadelab/scene/model.h"

#include "app/demo/scene_setters.h"
#include "demo_test_support.h"
#include "shadelab/geometry/teapot.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app {
namespace {

using namespace demo_test;

TEST(DemoShape, DSwitchesTheEditedObjectBetweenSphereAndTeapot) {
    DemoState state(threeObjectScene());
    state.chooseEditedObject(2);
    ASSERT_TRUE(state.apply(Command::ToggleShape));
    EXPECT_EQ(state.scene().objects[1].shape, Shape::Teapot);
    EXPECT_EQ(state.scene().objects[0].shape, Shape::Sphere) << "only the edited object changes";
    EXPECT_EQ(state.scene().objects[2].shape, Shape::Sphere) << "only the edited object changes";
    EXPECT_EQ(state.drawn().objects[1].shape, Shape::Teapot) << "the drawn scene follows";
    EXPECT_NE(statusText(state).find("teapot, level 3"), std::string::npos) << statusText(state);
    EXPECT_NE(state.lastChange().find("teapot"), std::string::npos) << state.lastChange();
    ASSERT_TRUE(state.apply(Command::ToggleShape));
    EXPECT_EQ(state.scene().objects[1].shape, Shape::Sphere);
    EXPECT_NE(statusText(state).find("sphere, level 3"), std::string::npos) << statusText(state);
}

TEST(DemoShape, WithAllObjectsEditedEveryObjectSwitches) {
    DemoState state(threeObjectScene());
    state.chooseEditedObject(0); // all
    state.apply(Command::ToggleShape);
    for (const SceneObject& object : state.scene().objects) EXPECT_EQ(object.shape, Shape::Teapot);
}

TEST(DemoShape, TheTitleNamesTheTeapotAndKeepsTheSpheresWords) {
    Scene scene;
    scene.objects[0].subdivisions = 5;
    DemoState state(scene);
    EXPECT_NE(windowTitle(state, 0).find("| level 5 | "), std::string::npos) << windowTitle(state, 0);
    state.apply(Command::ToggleShape);
    EXPECT_NE(windowTitle(state, 0).find("| teapot, level 5 | "), std::string::npos) << windowTitle(state, 0);
    // The triangles the title counts are the teapot's (992 at level 2, teapot.h).
    ASSERT_TRUE(state.setLevel(2)) << state.levelRefusal();
    EXPECT_EQ(state.triangleCount(), 992u);
    EXPECT_NE(windowTitle(state, 0).find("| 992 triangles | "), std::string::npos) << windowTitle(state, 0);
}

TEST(DemoShape, LevelKeysStayWithinTheTeapotsLevels) {
    Scene scene;
    scene.objects[0].subdivisions = 10; // the sphere's finest
    DemoState state(scene);
    state.apply(Command::ToggleShape);
    EXPECT_EQ(state.scene().objects[0].subdivisions, kMaxTeapotLevel) << "a teapot has no level 10";
    EXPECT_EQ(state.level(), kMaxTeapotLevel);
    state.apply(Command::LevelUp);
    EXPECT_EQ(state.scene().objects[0].subdivisions, kMaxTeapotLevel) << "+ past the teapot's finest";
    // The panels' level row: the teapot's range in checkTeapotLevel's words (teapot.h).
    EXPECT_EQ(setValue(state, "level", "9"), "level: must be between 0 and 8, got 9");
    EXPECT_EQ(state.level(), kMaxTeapotLevel);
    state.apply(Command::LevelDown);
    EXPECT_EQ(state.level(), kMaxTeapotLevel - 1);
    // Back to the sphere, the sphere's levels again.
    state.apply(Command::ToggleShape);
    state.apply(Command::LevelUp);
    state.apply(Command::LevelUp);
    EXPECT_EQ(state.level(), kMaxTeapotLevel + 1);
}

TEST(DemoShape, TheShapeSetterSetsAndReadsTheShapeAndRefusesAMesh) {
    DemoState state(threeObjectScene());
    state.chooseEditedObject(3);
    EXPECT_EQ(readValue(state, "shape"), "sphere");
    EXPECT_EQ(setValue(state, "shape", " teapot "), "");
    EXPECT_EQ(readValue(state, "shape"), "teapot");
    EXPECT_EQ(state.scene().objects[2].shape, Shape::Teapot);
    EXPECT_EQ(state.scene().objects[0].shape, Shape::Sphere);
    const std::string mesh = setValue(state, "shape", "mesh");
    EXPECT_NE(mesh.find("shape: "), std::string::npos) << mesh;
    EXPECT_NE(mesh.find("sphere, teapot"), std::string::npos) << mesh;
    EXPECT_NE(setValue(state, "shape", "cube"), "");
    EXPECT_EQ(state.scene().objects[2].shape, Shape::Teapot) << "a refused value changes nothing";
    EXPECT_EQ(setValue(state, "shape", "sphere"), "");
    EXPECT_EQ(state.scene().objects[2].shape, Shape::Sphere);
}

// A model (dropped on the page, or a scene's) becomes the sphere or the teapot on D or the shape menu,
// keeping the material it drew with; nothing of the file is left on it.
TEST(DemoShape, AMeshObjectTakesTheShapeAndKeepsItsMaterial) {
    Scene scene;
    auto model = std::make_shared<Model>();
    model->mesh = buildSphere(1, VertexNormals::Exact);
    scene.objects[0].shape = Shape::Mesh;
    scene.objects[0].mesh = "cube.obj";
    scene.objects[0].model = model;
    scene.objects[0].materialGiven = false;
    scene.objects[0].material.diffuse = {0.9, 0.1, 0.1};
    DemoState state(scene);
    EXPECT_EQ(setValue(state, "shape", "teapot"), "");
    const SceneObject& o = state.scene().objects[0];
    EXPECT_EQ(o.shape, Shape::Teapot);
    EXPECT_TRUE(o.mesh.empty());
    EXPECT_EQ(o.model, nullptr);
    EXPECT_TRUE(o.materialGiven); // written back with the scene, as drawn
    EXPECT_EQ(o.material.diffuse, glm::dvec3(0.9, 0.1, 0.1));
    EXPECT_NO_THROW(validateScene(state.scene()));
}

TEST(DemoShape, HelpNamesTheShapeKey) {
    const std::string help = keyHelpText();
    EXPECT_NE(help.find("D        shape of the edited object: sphere <-> Newell's teapot"), std::string::npos)
        << help;
}

} // namespace
} // namespace shadelab::app
