// The demo's teaching views (src/app/demo/demo_state.h): Y shows the outside view and Q the NDC view, where a
// drag orbits the observer and leaves the camera (Q is refused under exact shading, which has no mesh to
// transform); the view volume the panel and the page edit becomes the drawn projection, a refused edit
// naming its field.
#include "app/demo/demo_state.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "demo_test_support.h"
#include "shadelab/errors.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app {
namespace {

using namespace demo_test;

// ---- Y: the outside view ----

TEST(DemoOutsideView, YShowsItDragOrbitsTheObserverAndTheCameraStays) {
    DemoState state{Scene{}};
    ASSERT_EQ(commandForKey('Y'), Command::ToggleOutsideView);
    ASSERT_TRUE(state.apply(Command::ToggleOutsideView));
    EXPECT_EQ(state.current().view.kind, ViewKind::Outside);
    EXPECT_EQ(state.lastChange(), "view: outside");
    const Scene before = state.current();
    state.drag(40, -20);
    state.zoom(2);
    const Scene after = state.current();
    EXPECT_EQ(after.eye, before.eye) << "the drag orbits the observer, not the camera";
    EXPECT_EQ(after.view.observer.azimuthDeg, before.view.observer.azimuthDeg - 20);
    EXPECT_EQ(after.view.observer.elevationDeg, before.view.observer.elevationDeg - 10);
    EXPECT_NEAR(after.view.observer.zoom, 0.81, 1e-12);
    EXPECT_FALSE(state.probeAt(256, 256)) << "the picture is the observer's: no probe";
    // S saves the observer with the view, and the saved scene reads back the same.
    EXPECT_EQ(parseScene(sceneToJson(after)).view, after.view);
    for (int i = 0; i < 400; ++i) state.drag(0, 10);
    EXPECT_EQ(state.current().view.observer.elevationDeg, kMaxObserverElevationDeg);
    EXPECT_NO_THROW(validateScene(state.current()));
    ASSERT_TRUE(state.apply(Command::ToggleOutsideView));
    EXPECT_EQ(state.current().view.kind, ViewKind::Scene);
    state.drag(40, 0);
    EXPECT_NE(state.current().eye, before.eye) << "back in the scene view, the drag orbits the camera";
}

// ---- Q: the NDC view ----

TEST(DemoNdcView, QShowsItUnlessTheShadingIsExactWhichHasNoMesh) {
    DemoState state{Scene{}};
    ASSERT_EQ(commandForKey('Q'), Command::ToggleNdcView);
    ASSERT_TRUE(state.apply(Command::ToggleNdcView));
    EXPECT_EQ(state.current().view.kind, ViewKind::Ndc);
    EXPECT_NO_THROW(validateScene(state.current()));
    const Scene before = state.current();
    state.drag(-20, 0);
    EXPECT_EQ(state.current().eye, before.eye) << "the drag orbits the observer, not the camera";
    EXPECT_EQ(state.current().view.observer.azimuthDeg, before.view.observer.azimuthDeg + 10);
    // 5 (exact) leaves the NDC view: the pair would be refused (exact has no mesh to transform).
    state.apply(Command::Exact);
    EXPECT_EQ(state.current().view.kind, ViewKind::Scene);
    EXPECT_NO_THROW(validateScene(state.current()));
    ASSERT_TRUE(state.apply(Command::ToggleNdcView));
    EXPECT_EQ(state.current().view.kind, ViewKind::Scene) << "Q under exact shading";
    EXPECT_NE(state.lastChange().find("exact shading has none"), std::string::npos) << state.lastChange();
    Scene refused = before;
    refused.shading = ShadingMode::Exact;
    EXPECT_THROW(validateScene(refused), InputError);
}

// ---- the view volume on the panel and the page ----

TEST(DemoViewVolume, AnEditBecomesTheDrawnProjectionAndARefusalNamesTheField) {
    DemoState state{Scene{}};
    const Projection narrow{ProjectionType::Perspective, 30, -1, 1, -1, 1, 1, 9};
    state.editViewVolume(narrow);
    EXPECT_EQ(state.current().projection, narrow);
    EXPECT_EQ(parseScene(sceneToJson(state.current())).projection, narrow) << "S saves the edited volume";
    Projection backwards = narrow;
    backwards.far = 0.5;
    try {
        state.editViewVolume(backwards);
        ADD_FAILURE() << "far < near was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("projection.far"), std::string::npos) << e.what();
    }
    EXPECT_EQ(state.current().projection, narrow) << "a refused edit changed the volume";

    // An orthographic box, off-centre and not of the picture's aspect, is drawn as edited; zooming out
    // scales it about the axis by the distance, as the demo's orthographic zoom always has.
    const Projection box{ProjectionType::Orthographic, 40, -2, 1, -1.5, 1.5, 0.5, 20};
    state.editViewVolume(box);
    EXPECT_TRUE(state.orthographic());
    EXPECT_EQ(state.current().projection, box);
    const double before = glm::length(state.current().eye - state.current().target);
    state.zoom(-2);
    const double ratio = glm::length(state.current().eye - state.current().target) / before;
    ASSERT_GT(ratio, 1.1);
    const Projection zoomed = state.current().projection;
    EXPECT_NEAR(zoomed.left, box.left * ratio, 1e-12);
    EXPECT_NEAR(zoomed.right, box.right * ratio, 1e-12);
    EXPECT_NEAR(zoomed.top, box.top * ratio, 1e-12);
    EXPECT_EQ(zoomed.near, box.near);
    // O goes to perspective from the edited box, showing the same height at the target.
    state.apply(Command::ToggleProjection);
    const Scene perspective = state.current();
    EXPECT_EQ(perspective.projection.type, ProjectionType::Perspective);
    EXPECT_NEAR(std::tan(perspective.projection.fovyDeg * kDeg / 2) * glm::length(perspective.eye),
                box.top * ratio, 1e-9);
}

} // namespace
} // namespace shadelab::app
