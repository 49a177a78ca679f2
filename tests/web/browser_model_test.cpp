// The page's shapes and models (docs/DESIGN.md §1): the shape menu switches the chosen object to the teapot,
// a dropped OBJ with its MTL becomes the chosen object in the MTL's colour, and a broken OBJ picked with the
// model input is refused with the loader's message, the scene left as it was (browser_support.h: the
// session).

#include <fstream>

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

std::array<int, 3> centrePixel(const Image& image) {
    const std::size_t at = (std::size_t(image.height / 2) * image.width + image.width / 2) * 4;
    return {image.rgba[at], image.rgba[at + 1], image.rgba[at + 2]};
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

// A cube, corners at ±1, with a normal per face (flat faces, however a renderer interpolates), faces
// counter-clockwise seen from outside, its material from cube.mtl: red.
void writeCube(const fs::path& folder) {
    std::ofstream(folder / "cube.mtl") << "newmtl red\nKa 0 0 0\nKd 0.9 0.1 0.1\nKs 0 0 0\nNs 10\n";
    std::ofstream obj(folder / "cube.obj");
    obj << "mtllib cube.mtl\nusemtl red\n";
    for (int i = 0; i < 8; ++i) // corner i + 1: x from bit 0, y from bit 1, z from bit 2
        obj << "v " << (i & 1 ? 1 : -1) << ' ' << (i & 2 ? 1 : -1) << ' ' << (i & 4 ? 1 : -1) << '\n';
    obj << "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 0 1 0\nvn -1 0 0\nvn 1 0 0\n";
    const int faces[6][4] = {{1, 3, 4, 2}, {5, 6, 8, 7}, {1, 2, 6, 5},
                             {3, 7, 8, 4}, {1, 5, 7, 3}, {2, 4, 8, 6}};
    for (int n = 0; n < 6; ++n) {
        const auto corner = [&](int k) { return std::to_string(faces[n][k]) + "//" + std::to_string(n + 1); };
        obj << "f " << corner(0) << ' ' << corner(1) << ' ' << corner(2) << "\nf " << corner(0) << ' '
            << corner(2) << ' ' << corner(3) << '\n';
    }
}

// An OBJ dropped on the canvas with its MTL: the chosen object becomes that mesh (a cube covers more than
// the sphere inscribed in it), drawn in the MTL's red where the sphere was green, the material the file's
// (not written back into the scene: materialGiven false).
TEST_F(Browser, DroppedObjWithItsMtlDrawsInTheMtlsColour) {
    writeCube(dir_);
    Session session;
    session.open();
    session.load(greenSphereScene());
    const std::size_t sphere = session.capture();
    const std::size_t dropped = session.dropFiles({dir_ / "cube.obj", dir_ / "cube.mtl"});
    const std::size_t ui = session.ui();
    const std::size_t cube = session.capture();
    const std::size_t shapeOut = session.element("#shape-out");
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    EXPECT_EQ(session.answer(dropped).at("message"), "");
    const json& object = session.answer(ui).at("ui").at("scene").at("objects")[0];
    EXPECT_EQ(object.value("mesh", ""), "cube.obj") << object;
    EXPECT_FALSE(object.contains("material")) << "the file's material is not the scene's: " << object;
    const json& shown = session.answer(ui).at("ui").at("shownMaterial");
    EXPECT_EQ(shown.at("diffuse"), json::array({0.9, 0.1, 0.1})) << shown;
    EXPECT_NE(session.answer(shapeOut).at("element").at("text").get<std::string>().find("cube.obj"),
              std::string::npos);
    const Image& before = session.image(sphere);
    const Image& after = session.image(cube);
    EXPECT_GT(coveredPixels(after), coveredPixels(before) * 5 / 4)
        << "the cube's front face alone is larger than the sphere's disc";
    const auto [r0, g0, b0] = centrePixel(before);
    EXPECT_GT(g0, 2 * r0) << "the sphere is green";
    // The front face, lit head-on: 0.9 · 1 red, 0.1 green and blue (in 8 bits: 230, 26, 26).
    const auto [r, g, b] = centrePixel(after);
    EXPECT_NEAR(r, 230, 3);
    EXPECT_NEAR(g, 26, 3);
    EXPECT_NEAR(b, 26, 3);
    expectCleanConsole(session.answer(console).at("console"));
}

// A broken OBJ picked with the model input (its name markup, which the page shows as text): the loader's
// message names the file and the line, shown on the error line as it is; the scene and the picture stay
// what they were.
TEST_F(Browser, BrokenObjIsRefusedNamingTheFileAndLineAndTheSceneStays) {
    const std::string name = "<b>broken.obj";
    std::ofstream(dir_ / name) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n";
    Session session;
    session.open();
    session.load(greenSphereScene());
    const std::size_t uiBefore = session.ui();
    const std::size_t before = session.capture();
    const std::size_t picked = session.pickFiles({dir_ / name});
    const std::size_t shown = session.message();
    const std::size_t uiAfter = session.ui();
    const std::size_t after = session.capture();
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    const std::string message = session.answer(picked).at("message");
    EXPECT_NE(message.find(name), std::string::npos) << "the message names the file as text: " << message;
    EXPECT_NE(message.find("line 5"), std::string::npos) << "the message names the line: " << message;
    EXPECT_EQ(session.answer(shown).at("message"), message);
    EXPECT_EQ(session.answer(uiAfter).at("ui").at("scene"), session.answer(uiBefore).at("ui").at("scene"));
    const Comparison same = compareImages(session.image(after), session.image(before), Tolerance{0, 0, 0});
    EXPECT_TRUE(same.passed) << same.summary();
    expectCleanConsole(session.answer(console).at("console"));
}

} // namespace
} // namespace shadelab::test
