// A window frame copies no scene (DemoState keeps its drawn scene and hands it out by reference): the CPU
// side of a frame — what demo.cpp's drawFrame asks of the state for the picture, the title, the status and
// the panel — run twice over an unchanged scene of 10,000 objects, with operator new watched
// (gl/allocation_watch.h). The second frame may make its short texts; it makes nothing scene-sized.
#include <cstddef>
#include <string>

#include <gtest/gtest.h>

#include "app/demo/demo_state.h"
#include "app/demo/matrices_text.h"
#include "app/demo/scene_setters.h"
#include "app/demo/view_explanations.h"
#include "gl/allocation_watch.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app {
namespace {

// 10,000 objects (kMaxObjects) in a grid, a probe pinned on one: every per-frame query has work to do.
Scene crowd() {
    Scene scene;
    scene.objects.clear();
    for (int i = 0; i < 100; ++i)
        for (int j = 0; j < 100; ++j) {
            SceneObject o;
            o.center = {(i - 49.5) * 0.05, (j - 49.5) * 0.05, 0};
            o.radius = 0.024;
            o.subdivisions = 1;
            scene.objects.push_back(o);
        }
    scene.eye = {0, 0, 6};
    return scene;
}

// What a frame asks of the state, as FramedPicture::draw, Demo::remakeTexts and Panel::draw do (they read
// it through a const DemoState&: the non-const scene() is an edit); returns the texts' total length so that
// nothing is optimized away.
std::size_t frame(DemoState& changing) {
    const DemoState& state = changing;
    changing.setViewport(640, 480); // FramedPicture::draw, every frame
    const Scene& drawn = state.drawn();
    std::size_t made = drawn.objects.size();
    changing.setViewReport("");                            // what the view measured (none: the scene view)
    made += state.probe().has_value();                     // the probe's vectors
    made += presentationFacts(drawn).level;                // presenting: the label's key
    made += statusText(state).size();                      // the panel's status
    made += windowTitle(state, 1.25).size();               // the title
    made += whatYouAreSeeing(state.drawn()).size();        // the panel's "what you are seeing"
    made += state.drawnVersion() + *state.shownObject();   // the panel's matrices' key
    made += readValue(state, "material.shininess").size(); // a panel field's value
    made += state.scene().lights.size();                   // the light controls
    return made;
}

TEST(DemoFrame, ASecondFrameOfAnUnchangedSceneCopiesNoScene) {
    Scene scene = crowd();
    ASSERT_EQ(scene.objects.size(), kMaxObjects);
    DemoState state(scene);
    state.setViewport(640, 480);
    // Object (50, 50), centred at (0.025, 0.025): 2.75 px right of and above the picture's centre.
    ASSERT_TRUE(state.probeAt(322.75, 237.25)) << "the probe pins an object near the picture's centre";
    frame(state); // the first frame makes the drawn scene, the probe's mesh and report

    // Nothing between the frames: what the first leaves to do, the second does, and is measured doing.
    test::resetLargestAllocation();
    const long before = test::allocationCount();
    EXPECT_GT(frame(state), 0u);
    const long allocations = test::allocationCount() - before;
    const std::size_t largest = test::largestAllocation();
    RecordProperty("allocations", int(allocations));
    RecordProperty("largestBytes", int(largest));

    // A scene's objects are 10,000 × sizeof(SceneObject) bytes; its texts a few hundred.
    const std::size_t objectsBytes = kMaxObjects * sizeof(SceneObject);
    EXPECT_LT(largest, objectsBytes / 100) << "a frame allocated " << largest << " bytes at once ("
                                           << allocations << " allocations): a copy of the scene";
    EXPECT_LT(allocations, 200) << "the texts of a frame, not its objects";
    const std::uint64_t version = state.drawnVersion();
    frame(state);
    EXPECT_EQ(state.drawnVersion(), version) << "an unchanged frame made the drawn scene again";
}

// A change makes the drawn scene again, once, and the frame after it copies nothing again.
TEST(DemoFrame, AChangeMakesTheDrawnSceneOnceAndNotAtEveryFrame) {
    DemoState state(crowd());
    frame(state);
    const std::uint64_t version = state.drawnVersion();
    state.drag(10, 0);
    frame(state);
    const std::uint64_t moved = state.drawnVersion();
    EXPECT_NE(moved, version) << "an orbit changes the drawn scene";
    EXPECT_EQ(setValue(state, "shading", "flat"), "");
    EXPECT_NE(state.drawnVersion(), moved) << "a setter changes the drawn scene";
    const std::uint64_t flat = state.drawnVersion();
    state.setViewport(640, 480);  // the same size again: no change
    state.pointer(10, 10, false); // the pointer over the plain scene view changes nothing
    EXPECT_EQ(state.drawnVersion(), flat);
    test::resetLargestAllocation();
    frame(state);
    EXPECT_LT(test::largestAllocation(), kMaxObjects * sizeof(SceneObject) / 100);
}

} // namespace
} // namespace shadelab::app
