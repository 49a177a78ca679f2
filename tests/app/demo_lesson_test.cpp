// A lesson in the demo (src/app/demo/demo_state.h, docs/lecturers.md "Lessons"): the step keys move through
// its steps, each as written with the window's own settings kept; keys and the mouse work inside a step, and
// R gives the step back as written.
#include "app/demo/demo_state.h"

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "shadelab/scene/scene.h"

namespace shadelab::app {
namespace {

// A lesson's step keys move through it, each step as written with the window's own settings kept;
// a key works inside a step, and R returns to the step as written (not only its camera).
TEST(DemoLesson, StepKeysMoveThroughTheStepsAndRReturnsToTheStep) {
    auto lesson = std::make_shared<Lesson>();
    lesson->title = "Two steps";
    Scene first, second;
    first.shading = ShadingMode::Flat;
    second.shading = ShadingMode::Toon;
    second.lighting = LightingModel::Phong;
    second.objects[0].subdivisions = 2;
    lesson->steps = {{"One", "the first", "", first, "", {}}, {"Two", "", "", second, "", {}}};
    DemoState state(Scene{});
    EXPECT_TRUE(state.apply(Command::NextStep));
    EXPECT_NE(state.lastChange().find("no lesson open"), std::string::npos) << state.lastChange();
    state.setPresenting(true);
    state.setShowPanel(false);
    state.openLesson(lesson);
    EXPECT_EQ(state.step(), 0u);
    EXPECT_EQ(state.scene().shading, ShadingMode::Flat);
    EXPECT_NE(windowTitle(state, 0).find("shadelab — step 1 of 2 | flat shading"), std::string::npos)
        << windowTitle(state, 0);
    state.apply(Command::PreviousStep);
    EXPECT_EQ(state.step(), 0u);
    EXPECT_EQ(state.lastChange(), "already at the first step");
    state.apply(Command::NextStep);
    EXPECT_EQ(state.step(), 1u);
    EXPECT_EQ(state.lastChange(), "step 2 of 2: Two");
    EXPECT_EQ(state.scene().shading, ShadingMode::Toon);
    EXPECT_EQ(state.level(), 2);
    EXPECT_TRUE(state.presenting()) << "the window's settings are kept";
    EXPECT_FALSE(state.showPanel());
    // Inside the step: keys and the mouse change it; R gives the step back as written.
    state.apply(Command::Phong);
    state.apply(Command::LevelUp);
    state.apply(Command::NextMaterial);
    state.drag(40, 10);
    EXPECT_EQ(state.scene().shading, ShadingMode::Phong);
    state.apply(Command::ResetView);
    EXPECT_EQ(state.scene().shading, ShadingMode::Toon);
    EXPECT_EQ(state.level(), 2);
    EXPECT_EQ(state.materialName(), DemoState(second).materialName());
    EXPECT_EQ(state.drawn().eye, DemoState(second).drawn().eye) << "the camera too";
    state.apply(Command::FirstStep);
    EXPECT_EQ(state.step(), 0u);
    state.apply(Command::LastStep);
    EXPECT_EQ(state.step(), 1u);
    state.apply(Command::NextStep);
    EXPECT_EQ(state.lastChange(), "already at the last step");
}

} // namespace
} // namespace shadelab::app
