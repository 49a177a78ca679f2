// The page's shapes and models (docs/DESIGN.md §1): the shape menu switches the chosen object to the teapot,
// a dropped OBJ with its MTL becomes the chosen object in the MTL's colour, and a broken OBJ picked with the
// model input is refused with the loader's message, the scene left as it was (browser_support.h: the
// session).

#include "web/browser_support.h"

namespace shadelab::test {
namespace {

using namespace web_test;

// A scene of one green sphere lit head-on by a white directional light: a model's front face facing the eye
// then shows its diffuse colour, and the sphere's green is none of a red model's.
Scene greenSphereScene() {
    Scene scene = litSphereScene(128, LightType::Directional);
    scene.lights[0].direction = {0, 0, -1};
    scene.objects[0].material = {{0, 0.05, 0}, {0.1, 0.8, 0.1}, {0, 0, 0}, 8};
    return scene;
}

// The pixels a picture covers (alpha: coverage).
int coveredPixels(const Image& image) {
    int covered = 0;
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) covered += image.rgba[i] > 0;
    return covered;
}

// The shape menu sets the chosen object's shape through the setter the window's key uses: the teapot is
// drawn, and its picture is not the sphere's (a teapot of the sphere's radius leaves the sphere's top and
// bottom uncovered and reaches further sideways, spout and handle).
TEST_F(Browser, ShapeMenuSwitchesTheChosenObjectToTheTeapot) {
    Session session;
    session.open();
    session.load(greenSphereScene());
    const std::size_t sphere = session.capture();
    const std::size_t chosen = session.panel("#shape", "teapot");
    const std::size_t teapotUi = session.ui();
    const std::size_t teapot = session.capture();
    const std::size_t message = session.message();
    const std::size_t back = session.panel("#shape", "sphere");
    const std::size_t sphereAgain = session.capture();
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    EXPECT_TRUE(session.answer(chosen).at("found").get<bool>()) << "no shape menu";
    EXPECT_EQ(session.answer(message).at("message"), "");
    const json& ui = session.answer(teapotUi).at("ui");
    EXPECT_EQ(ui.at("scene").at("objects")[0].value("shape", "sphere"), "teapot");
    EXPECT_EQ(ui.at("shownShape"), "teapot");
    const Image& sphereImage = session.image(sphere);
    const Image& teapotImage = session.image(teapot);
    const Comparison differ = compareImages(teapotImage, sphereImage, kBeyondRounding);
    EXPECT_FALSE(differ.passed) << "the teapot drew the sphere's picture";
    EXPECT_GT(differ.outliers, int(0.05 * sphereImage.width * sphereImage.height)) << differ.summary();
    EXPECT_GT(coveredPixels(teapotImage), 0) << "nothing drawn for the teapot";
    EXPECT_TRUE(session.answer(back).at("found").get<bool>());
    const Comparison same = compareImages(session.image(sphereAgain), sphereImage, kBeyondRounding);
    EXPECT_TRUE(same.passed) << "back to the sphere: " << same.summary();
    expectCleanConsole(session.answer(console).at("console"));
}

} // namespace
} // namespace shadelab::test
