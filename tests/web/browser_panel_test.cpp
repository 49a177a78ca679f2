// The page's panel, menus, messages, canvas, downloads and presentation label, as the window and the command
// line have them (browser_support.h: the session and fixture).

#include <map>

#include "shadelab/scene/view.h"
#include "web/browser_support.h"

namespace shadelab::test {
namespace {

using namespace web_test;

// The control panel edits the scene through the same parser as a file: a spot's cutoff from its slider
// reaches the scene and the picture; an attenuation of 0, 0, 0 is refused with the scene's own message.
TEST_F(Browser, PanelEditsGoThroughTheSceneParser) {
    Scene scene = litSphereScene(128, LightType::Spot);
    Session session;
    session.open();
    session.load(scene);
    const std::size_t before = session.capture();
    const std::size_t cutoff = session.panel("#lights input[type=range]", "30");
    const std::size_t widened = session.ui();
    const std::size_t after = session.capture();
    const std::string attenuation =
        "#lights label:nth-of-type(6) input:nth-of-type"; // a, b, c: (1), (2), (3)
    session.panel(attenuation + "(2)", "0");
    session.panel(attenuation + "(3)", "0");
    const std::size_t zero = session.panel(attenuation + "(1)", "0");
    const std::size_t message = session.message();
    // The view volume: a narrower field of view, then the near plane moved through the sphere (3.6 of
    // the eye's 4 to its centre: the front cap is clipped), then a far plane short of near, refused.
    const std::size_t narrowed = session.panel("#fovy", "30", "input");
    const std::size_t clipping = session.panel("#near", std::to_string(std::log10(3.6)), "input");
    const std::size_t clipped = session.capture();
    const std::size_t clippedUi = session.ui();
    const std::size_t matrices = session.element("#matrices");
    session.panel("#far", "-2", "input"); // 0.01, nearer than near
    const std::size_t refused = session.message();
    const std::size_t afterRefusal = session.ui();
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    EXPECT_TRUE(session.answer(cutoff).at("found").get<bool>());
    EXPECT_EQ(session.answer(widened).at("ui").at("scene").at("lights")[0].at("cutoff_deg"), 30);
    EXPECT_FALSE(compareImages(session.image(after), session.image(before), kBeyondRounding).passed)
        << "a wider cone lights more of the sphere";
    Scene wide = scene;
    wide.lights[0].cutoffDeg = 30;
    const Comparison c = compareImages(session.image(after), nativeGles().render(wide),
                                       swiftShaderTolerance(session.image(after)));
    EXPECT_TRUE(c.passed) << c.summary();
    EXPECT_TRUE(session.answer(zero).at("found").get<bool>());
    const std::string shown = session.answer(message).at("message");
    EXPECT_NE(shown.find("attenuation"), std::string::npos) << shown;

    EXPECT_TRUE(session.answer(narrowed).at("found").get<bool>()) << "no field-of-view slider";
    EXPECT_TRUE(session.answer(clipping).at("found").get<bool>()) << "no near-plane slider";
    const Scene clippedScene =
        parseScene(session.answer(clippedUi).at("ui").at("scene").dump(), "page state");
    EXPECT_EQ(clippedScene.projection.fovyDeg, 30);
    EXPECT_EQ(clippedScene.projection.near, 3.6);
    // The page draws what `render` draws of the scene it holds, the clipped cap included.
    Scene expectedClip = wide;
    expectedClip.lights[0].attenuation = clippedScene.lights[0].attenuation; // b and c edited to 0
    expectedClip.projection.fovyDeg = 30;
    expectedClip.projection.near = 3.6;
    const Image& clippedImage = session.image(clipped);
    const Comparison clip =
        compareImages(clippedImage, nativeGles().render(expectedClip), swiftShaderTolerance(clippedImage));
    EXPECT_TRUE(clip.passed) << clip.summary();
    Scene unclipped = expectedClip;
    unclipped.projection.near = 0.5;
    EXPECT_FALSE(compareImages(clippedImage, nativeGles().render(unclipped), Tolerance{2, 0, 0}).passed)
        << "a near plane through the sphere must change the picture";
    const std::string matrixText = session.answer(matrices).at("element").at("text");
    EXPECT_NE(matrixText.find("M_cam = [u v w e]^-1"), std::string::npos) << matrixText;
    EXPECT_NE(matrixText.find("n = -3.6, f = -20"), std::string::npos) << matrixText;
    const std::string refusal = session.answer(refused).at("message");
    EXPECT_NE(refusal.find("projection.far"), std::string::npos) << refusal;
    EXPECT_EQ(session.answer(afterRefusal).at("ui").at("scene").at("projection").at("far"), 20)
        << "a refused edit leaves the view volume as it was";
    expectCleanConsole(session.answer(console).at("console"));
}

// A bad scene shows the command line's own message on the page, and the previous picture stays.
TEST_F(Browser, BadSceneShowsTheCommandLineMessage) {
    const std::string bad =
        R"({ "lights": [ { "type": "point", "position": [3, 3, 5], "attenuation": [1, 0, -1] } ] })";
    std::ofstream(dir_ / "bad.json") << bad;
    const Outcome cli = runShadelab({"render", "bad.json", "--out", "x.png"}, dir_);
    ASSERT_EQ(cli.exitCode, 2) << cli.err;
    ASSERT_TRUE(cli.err.starts_with("shadelab: ")) << cli.err;
    const std::string expected = cli.err.substr(10, cli.err.find('\n') - 10);

    Session session;
    session.open();
    session.load(litSphereScene(96, LightType::Point), "good.json");
    const std::size_t load = session.loadText(bad, "bad.json");
    const std::size_t shown = session.message();
    const std::size_t picture = session.capture();
    const std::size_t notJson = session.loadText("{ \"shading\": ", "cut.json");
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    EXPECT_EQ(session.answer(load).at("message"), expected);
    EXPECT_EQ(session.answer(shown).at("message"), expected) << "the page must show it";
    const Image image = session.image(picture);
    std::size_t covered = 0;
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) covered += image.rgba[i] != 0;
    EXPECT_GT(covered, 1000u) << "the canvas went blank";
    EXPECT_TRUE(session.answer(notJson).at("message").get<std::string>().starts_with("cut.json: "))
        << session.answer(notJson);
    expectCleanConsole(session.answer(console).at("console"));
}

// Resizing the browser resizes the canvas's drawing buffer; the picture in it keeps the scene's aspect,
// the largest that fits (fitPicture, as the window places it), and is what the page draws.
// Then the page on a phone: Chromium's mobile emulation of a 390×844 screen at 2 device pixels per CSS
// pixel, with touch events. The picture comes first and as wide as the screen, the panel below it, nothing
// wider than the screen; a one-finger drag orbits, a two-finger pinch zooms by the ratio of the fingers'
// spread (60 to 90 px: the eye 1.5 times nearer), a tap probes, and the probe's table lies inside the
// screen with none of it cut off. (The page gave the panel half the width and squeezed the picture into
// the other half, 195 px wide, the probe's table scrolled out of sight.) Its screenshot:
// build/web-phone.png.
TEST_F(Browser, CanvasFollowsTheWindowAndAPhoneGetsThePictureFirstAndTouch) {
    Session session;
    session.open();
    const std::size_t wide = session.resize(1200, 600);
    const std::size_t wideUi = session.ui();
    const std::size_t tall = session.resize(700, 900);
    const std::size_t tallUi = session.ui();
    const std::size_t phone = session.phone(390, 844, 2);
    const std::vector<std::string> parts = {"#canvas", "#panel", "#probe"};
    const std::size_t before = session.layout(parts);
    const std::size_t start = session.ui();
    session.touchDrag(80, 0);
    const std::size_t dragged = session.ui();
    session.pinch(60, 90);
    const std::size_t pinched = session.ui();
    session.tap();
    const std::size_t tapped = session.ui();
    const std::size_t after = session.layout(parts);
    session.screenshot(fs::path(SHADELAB_BUILD_DIR) / "web-phone.png");
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    for (auto [resize, ui] : {std::pair{wide, wideUi}, std::pair{tall, tallUi}}) {
        const json canvas = session.answer(resize).at("canvas"); // [width, height, clientWidth, clientHeight]
        const json shown = session.answer(ui).at("ui");
        const json image = shown.at("current").at("image"), own = shown.at("scene").at("image");
        EXPECT_EQ(canvas[0], canvas[2]) << canvas;
        EXPECT_EQ(canvas[1], canvas[3]) << canvas;
        const app::PictureRect picture =
            app::fitPicture(own.at("width"), own.at("height"), canvas[0], canvas[1]);
        EXPECT_EQ(image.at("width"), picture.width) << canvas;
        EXPECT_EQ(image.at("height"), picture.height) << canvas;
    }
    const json w = session.answer(wide).at("canvas"), t = session.answer(tall).at("canvas");
    EXPECT_GT(w[0].get<int>(), w[1].get<int>()) << "a wide window gives a wide canvas";
    EXPECT_LT(t[0].get<int>(), t[1].get<int>()) << "a tall window gives a tall canvas";

    const json p = session.answer(phone).at("canvas");
    EXPECT_EQ(p[0].get<int>(), 2 * p[2].get<int>()) << "the drawing buffer at 2 pixels per CSS pixel: " << p;
    for (const std::size_t measured : {before, after}) {
        const json layout = session.answer(measured).at("layout");
        const double width = layout.at("innerWidth");
        const json canvas = layout.at("elements").at("#canvas"), panel = layout.at("elements").at("#panel");
        SCOPED_TRACE(layout.dump());
        EXPECT_EQ(width, 390);
        EXPECT_LE(layout.at("scrollWidth").get<double>(), width) << "the page is wider than the screen";
        EXPECT_NEAR(canvas.at("left").get<double>(), 0, 1);
        EXPECT_NEAR(canvas.at("width").get<double>(), width, 1) << "the picture is not the screen's width";
        EXPECT_LE(canvas.at("bottom").get<double>(), panel.at("top").get<double>())
            << "the panel is not below it";
    }
    const auto eye = [&](std::size_t ui) {
        const json camera = session.answer(ui).at("ui").at("current").at("camera");
        return glm::dvec3(camera.at("eye")[0], camera.at("eye")[1], camera.at("eye")[2]) -
               glm::dvec3(camera.at("target")[0], camera.at("target")[1], camera.at("target")[2]);
    };
    EXPECT_GT(glm::length(eye(dragged) - eye(start)), 0.5) << "the drag did not orbit the camera";
    EXPECT_NEAR(glm::length(eye(dragged)), glm::length(eye(start)), 1e-9) << "the drag zoomed";
    EXPECT_NEAR(glm::length(eye(dragged)) / glm::length(eye(pinched)), 1.5, 0.02) << "the pinch's zoom";
    const std::string table = session.answer(tapped).at("ui").at("probe");
    EXPECT_EQ(table.rfind("probe: object 1,", 0), 0u) << "the tap placed no probe: " << table;
    const json layout = session.answer(after).at("layout");
    const json probe = layout.at("elements").at("#probe");
    EXPECT_GE(probe.at("left").get<double>(), 0) << probe;
    EXPECT_LE(probe.at("right").get<double>(), layout.at("innerWidth").get<double>()) << probe;
    EXPECT_LE(probe.at("scrollWidth").get<double>(), probe.at("clientWidth").get<double>())
        << "the probe's table is cut off at its box's edge: " << probe;
    expectCleanConsole(session.answer(console).at("console"));
}

// S saves what the window's S saves: the picture as an opaque PNG and the scene JSON that draws it, here as
// two downloads. The PNG is the canvas's picture (native render of the saved JSON agrees), the JSON the
// state. Also the picture of the page for the README (build/web-page.png, copied to docs/ by hand).
TEST_F(Browser, SDownloadsThePictureAndItsScene) {
    Session session;
    session.open("", {}, dir_);
    const std::size_t canvas = session.resize(1280, 800);
    const std::size_t shot = session.screenshot(fs::path(SHADELAB_BUILD_DIR) / "web-page.png");
    session.key('M'); // a material preset, so the JSON is not the file the page started with
    const std::size_t press = session.key('S');
    const std::size_t files = session.waitFiles({dir_ / "shadelab-001.png", dir_ / "shadelab-001.json"});
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    (void)shot;
    EXPECT_EQ(session.answer(press).at("result"), 2);
    ASSERT_EQ(session.answer(files).at("present"), json::array({true, true}));
    const Image png = readPng(dir_ / "shadelab-001.png");
    const Scene saved = loadScene(dir_ / "shadelab-001.json");
    EXPECT_EQ(png.width, saved.width);
    EXPECT_EQ(png.height, saved.height);
    // The picture without the bars: the showcase's square at its size in the canvas.
    const json size = session.answer(canvas).at("canvas");
    const Scene showcase = loadScene(fs::path(SHADELAB_WEB_BUILD) / "scenes" / "showcase.json");
    const app::PictureRect picture = app::fitPicture(showcase.width, showcase.height, size[0], size[1]);
    EXPECT_EQ(png.width, picture.width) << size;
    EXPECT_EQ(png.height, picture.height) << size;
    EXPECT_NE(saved.objects.at(0).material.shininess, 24.0) << "the material preset is not in the JSON";
    const Comparison c = compareImages(png, nativeGles().render(saved), swiftShaderTolerance(png));
    EXPECT_TRUE(c.passed) << c.summary();
    expectCleanConsole(session.answer(console).at("console"));
}

// Presentation mode in the page: ?present shows the large label (the window's words), F2 hides it.
TEST_F(Browser, PresentationLabelShowsAndF2HidesIt) {
    Session session;
    session.open("?present");
    const std::size_t ui = session.ui();
    const std::size_t canvas = session.resize(1280, 720);
    session.screenshot(dir_ / "with-label.png");
    session.key(kKeyF2);
    session.screenshot(dir_ / "without.png");
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    const std::string label = session.answer(ui).at("ui").at("presentation");
    EXPECT_TRUE(label.starts_with("PHONG SHADING\nBLINN-PHONG LIGHTING\nLEVEL 3")) << label;
    // The label is drawn into the picture by the same code as the window's (FramedPicture with
    // presentationLabelImage), so the page shows it where and as large as that layout says: the pixels
    // that F2 changes are those of the label's box at the bottom left of the picture (the scene's framing
    // in the canvas, between bars), and most of the box.
    const Image a = readPng(dir_ / "with-label.png"), b = readPng(dir_ / "without.png");
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    const json size = session.answer(canvas).at("canvas"); // drawing buffer, then CSS size
    const json own = session.answer(ui).at("ui").at("scene").at("image");
    const app::PictureRect picture = app::fitPicture(own.at("width"), own.at("height"), size[0], size[1]);
    const auto layout = shadelab::app::presentationLabelImage(label, picture.width, picture.height);
    int minX = a.width, minY = a.height, maxX = -1, maxY = -1, changed = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            if (!std::equal(a.pixel(x, y), a.pixel(x, y) + 3, b.pixel(x, y))) {
                ++changed;
                minX = std::min(minX, x), maxX = std::max(maxX, x), minY = std::min(minY, y),
                maxY = std::max(maxY, y);
            }
    ASSERT_GT(changed, 0) << "F2 changed nothing: no label was drawn";
    // The canvas is the page's right part, as tall as the page (the screenshot's CSS pixels at ratio 1).
    const int canvasLeft = a.width - size[0].get<int>();
    EXPECT_EQ(minX, canvasLeft + picture.x + layout.margin) << "the box's left edge";
    EXPECT_EQ(maxY, picture.y + picture.height - layout.margin - 1) << "the box's bottom edge";
    EXPECT_EQ(maxX - minX + 1, layout.image.width) << "the box is as wide as the layout says";
    EXPECT_EQ(maxY - minY + 1, layout.image.height) << "the box is as tall as the layout says";
    expectCleanConsole(session.answer(console).at("console"));
}

// The page's gaps: the picker names a bundled scene opened by ?scene=; the view menu says what
// the split draws; every warning the command line prints for a scene shows on the page; the probe's table
// keeps its columns (no wrapping); every menu stays inside its box; a spot's cutoff and exponent sliders
// show their numbers; Esc's note goes away by itself.
TEST_F(Browser, PickerViewMenuWarningsProbeSlidersAndEscAsTheCommandLineHasThem) {
    const std::string colourScene = R"({"image": {"width": 64, "height": 64},
      "lights": [{"type": "spot", "position": [0, 2, 4], "direction": [0, -0.4, -1], "cutoff_deg": 27.5,
                  "exponent": 12, "diffuse": [200, 30, 30]}]})";
    std::ofstream(dir_ / "colour.json") << colourScene;
    const Outcome cli =
        runWith({"render", (dir_ / "colour.json").string(), "--out", (dir_ / "c.png").string()}, dir_);
    ASSERT_EQ(cli.exitCode, 0) << describe(cli);
    std::vector<std::string> cliWarnings; // "shadelab: warning: FILE: WARNING", FILE the path given
    for (std::size_t at = 0; (at = cli.err.find("shadelab: warning: ", at)) != std::string::npos;) {
        const std::size_t start = cli.err.find(": ", cli.err.find("colour.json", at)) + 2;
        const std::size_t end = cli.err.find('\n', start);
        cliWarnings.push_back(cli.err.substr(start, end - start));
        at = end;
    }
    ASSERT_FALSE(cliWarnings.empty()) << "the command line warned of nothing: " << cli.err;

    Session session;
    session.open("?scene=scenes/grid.json&view=split:flat,gouraud");
    const std::size_t picker = session.element("#bundled");
    const std::size_t split = session.element("#view-kind option[value=\"split\"]");
    const std::size_t probeStyle = session.element("#probe");
    const std::vector<std::string> selects = {
        "#bundled",       "#shading",    "#lighting", "#term",    "#perspective-matrix",
        "#normal-matrix", "#projection", "#normals",  "#overlay", "#view-kind"};
    const std::size_t menus = session.layout(selects);
    session.loadText(colourScene, "colour.json");
    const std::size_t warnings = session.element("#warnings");
    const std::size_t slider = session.element("#lights output");
    session.key(256); // Esc
    const std::size_t escNote = session.element("#message");
    session.sleep(4.5);
    const std::size_t later = session.element("#message");
    if (!session.run(dir_)) return;
    EXPECT_EQ(session.answer(picker).at("element").at("value"), "grid.json");
    EXPECT_EQ(session.answer(split).at("element").at("text"), "split: flat | gouraud (V)");
    EXPECT_EQ(session.answer(probeStyle).at("element").at("whiteSpace"), "pre");
    // Every menu inside its fieldset's box (the view menu's longest option pushed it 8 px past it).
    for (const std::string& select : selects) {
        const json box = session.answer(menus).at("layout").at("elements").at(select);
        ASSERT_TRUE(box.is_object()) << select;
        EXPECT_LE(box.at("right").get<double>(), box.at("fieldset").at("right").get<double>()) << select;
        EXPECT_GE(box.at("left").get<double>(), box.at("fieldset").at("left").get<double>()) << select;
    }
    const json shown = session.answer(warnings).at("element");
    EXPECT_FALSE(shown.at("hidden").get<bool>());
    for (const std::string& warning : cliWarnings)
        EXPECT_NE(shown.at("text").get<std::string>().find("warning: colour.json: " + warning),
                  std::string::npos)
            << "the command line's warning '" << warning << "' is not on the page: " << shown;
    EXPECT_EQ(session.answer(slider).at("element").at("text"), "27.5") << "the cutoff slider's number";
    EXPECT_FALSE(session.answer(escNote).at("element").at("hidden").get<bool>());
    EXPECT_TRUE(session.answer(later).at("element").at("hidden").get<bool>()) << "Esc's note stayed";
}

// The page frames a scene as `render` does, with the window's code (fitPicture, FramedPicture).
// grid.json (800x600, four columns of spheres) in a canvas narrower than 4:3 (bars above and below) and in
// a wider one (bars at the sides): what differs from the bars' colour is the largest rectangle of the
// scene's aspect, centred, where the page says the picture is; its pixels are native render's of grid.json
// at that size (the SwiftShader tolerance); and every canvas pixel around it is one colour. The page drew
// the scene at the canvas's aspect, cutting half of the fourth column off in the narrow canvas.
TEST_F(Browser, WideScenesKeepTheirFramingBetweenBars) {
    const Scene grid = loadScene(fs::path(SHADELAB_WEB_BUILD) / "scenes" / "grid.json");
    Session session;
    session.open("?scene=scenes/grid.json");
    struct Case {
        std::string name;
        int windowWidth;
        std::size_t canvas = 0, ui = 0;
    };
    std::vector<Case> cases = {{"narrow", 900}, {"wide", 1280}}; // canvases of about 560x657 and 940x657
    for (Case& c : cases) {
        c.canvas = session.resize(c.windowWidth, 800);
        c.ui = session.ui();
        session.screenshot(dir_ / (c.name + ".png"));
    }
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const json size = session.answer(c.canvas).at("canvas");
        const int width = size[0], height = size[1];
        const Image shot = readPng(dir_ / (c.name + ".png"));
        // The canvas is the page's right part, as tall as the page (the screenshot's CSS pixels at ratio 1).
        ASSERT_GE(shot.width, width);
        ASSERT_GE(shot.height, height);
        const int left = shot.width - width;
        const std::uint8_t* bar = shot.pixel(left, 0); // a corner of the canvas: a bar in both cases
        auto isBar = [&](int x, int y) { return std::equal(bar, bar + 3, shot.pixel(left + x, y)); };
        int minX = width, minY = height, maxX = -1, maxY = -1;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                if (!isBar(x, y)) {
                    minX = std::min(minX, x), maxX = std::max(maxX, x);
                    minY = std::min(minY, y), maxY = std::max(maxY, y);
                }
        ASSERT_GE(maxX, 0) << "the canvas is one colour";
        const app::PictureRect seen{minX, minY, maxX - minX + 1, maxY - minY + 1};
        std::printf("%s: canvas %dx%d, picture %dx%d at (%d, %d)\n", c.name.c_str(), width, height,
                    seen.width, seen.height, seen.x, seen.y);
        // The scene's aspect within one pixel's rounding, centred, touching two sides of the canvas.
        const app::PictureRect fitted = app::fitPicture(grid.width, grid.height, width, height);
        EXPECT_EQ(seen.x, fitted.x);
        EXPECT_EQ(seen.y, fitted.y);
        EXPECT_EQ(seen.width, fitted.width);
        EXPECT_EQ(seen.height, fitted.height);
        EXPECT_LE(std::abs(seen.width * grid.height - seen.height * grid.width),
                  std::max(grid.width, grid.height))
            << "not the scene's aspect";
        EXPECT_TRUE(seen.width == width || seen.height == height) << "not the largest that fits";
        const json picture = session.answer(c.ui).at("ui").value("picture", json::object());
        EXPECT_EQ(picture,
                  json({{"x", seen.x}, {"y", seen.y}, {"width", seen.width}, {"height", seen.height}}))
            << "where the page says the picture is";

        // The bars: every canvas pixel outside the picture is the corner's colour (they exist: the aspects
        // differ); inside it, the picture is native render's of the scene at the picture's size.
        std::size_t barPixels = 0, otherColour = 0;
        Image inside(fitted.width, fitted.height);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                if (fitted.contains(x, y)) {
                    std::copy_n(shot.pixel(left + x, y), 4, inside.pixel(x - fitted.x, y - fitted.y));
                } else {
                    ++barPixels;
                    otherColour += !isBar(x, y);
                }
            }
        EXPECT_GT(barPixels, std::size_t(width)) << "no bars";
        EXPECT_EQ(otherColour, 0u) << "bar pixels not of the bars' one colour";
        Scene sized = grid;
        sized.width = fitted.width;
        sized.height = fitted.height;
        const Comparison compared =
            compareImages(inside, nativeGles().render(sized), swiftShaderTolerance(inside));
        std::printf("%s: the picture vs native render of grid.json at its size: %s\n", c.name.c_str(),
                    compared.summary().c_str());
        EXPECT_TRUE(compared.passed) << compared.summary();
    }
    expectCleanConsole(session.answer(console).at("console"));
}

// The page's material controls edit the object chosen (0: all objects), as the window's panel
// does (DemoState::chooseEditedObject and editMaterial), and a probe click chooses the object it hits.
// grid.json's twelve spheres each have their own shininess: choosing object 7 and moving the shininess
// slider changes object 7's alone, and the panel says "panel edits: object 7 of 12"; a click on the second
// sphere makes it the edited object, and the sliders then show its values; with all objects chosen the
// slider sets that property of every object. The page showed objects[0]'s values and copied an edit to
// every object.
TEST_F(Browser, MaterialControlsEditTheChosenObjectAndAProbeClickChoosesIt) {
    const Scene grid = loadScene(fs::path(SHADELAB_WEB_BUILD) / "scenes" / "grid.json");
    ASSERT_EQ(grid.objects.size(), 12u);
    // The second sphere's middle, in CSS pixels from the canvas's centre (the picture's centre), for the
    // picture a 1280x800 window gives (876x657); checked below against the picture the page reports.
    Scene nominal = grid;
    nominal.width = 876;
    nominal.height = 657;
    double sumX = 0, sumY = 0, hits = 0;
    for (int y = 0; y < nominal.height; y += 2)
        for (int x = 0; x < nominal.width; x += 2)
            if (const auto point = pickSurfacePoint(nominal, x + 0.5, y + 0.5); point && point->object == 1) {
                sumX += x + 0.5, sumY += y + 0.5, ++hits;
            }
    ASSERT_GT(hits, 100);
    const int clickX = int(std::lround(sumX / hits - nominal.width / 2.0));
    const int clickY = int(std::lround(sumY / hits - nominal.height / 2.0));

    Session session;
    session.open("?scene=scenes/grid.json");
    const std::size_t canvas = session.resize(1280, 800);
    const std::size_t chose = session.panel("#object", "7");
    const std::size_t slid = session.panel("#shininess", "1.5", "input"); // log10: 31.6
    const std::size_t edited = session.ui();
    const std::size_t editedValue = session.element("#shininess-out");
    session.click(clickX, clickY);
    const std::size_t clicked = session.ui();
    const std::size_t chooser = session.element("#object");
    const std::size_t clickedValue = session.element("#shininess-out");
    session.panel("#object", "0");             // all objects
    session.panel("#shininess", "2", "input"); // log10: 100
    const std::size_t all = session.ui();
    // The scale sliders (the normal-matrix lesson's ellipsoid): object 3's x, then every object's y.
    session.panel("#object", "3");
    const std::size_t scaled = session.panel("#scale-x", "2.5", "input");
    const std::size_t scaledValue = session.element("#scale-out");
    session.panel("#object", "0");
    session.panel("#scale-y", "0.5", "input");
    const std::size_t allScaled = session.ui();
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;

    EXPECT_TRUE(session.answer(chose).at("found").get<bool>()) << "no object chooser on the page";
    ASSERT_TRUE(session.answer(slid).at("found").get<bool>()) << "no shininess slider";
    const json afterEdit = session.answer(edited).at("ui");
    const std::string status = afterEdit.at("status");
    EXPECT_NE(status.find("panel edits: object 7 of 12"), std::string::npos) << status;
    EXPECT_NE(status.find("material: scene's own, edited in the panel"), std::string::npos) << status;
    EXPECT_EQ(afterEdit.at("editedObject"), 7);
    const Scene afterEditScene = parseScene(afterEdit.at("scene").dump(), "page state");
    ASSERT_EQ(afterEditScene.objects.size(), 12u);
    for (std::size_t i = 0; i < 12; ++i) {
        SCOPED_TRACE("object " + std::to_string(i + 1));
        Material expected = grid.objects[i].material;
        if (i == 6) expected.shininess = 31.6;
        EXPECT_EQ(afterEditScene.objects[i].material, expected)
            << "shininess " << afterEditScene.objects[i].material.shininess;
    }
    EXPECT_EQ(session.answer(editedValue).at("element").at("text"), "31.6");

    // The click landed on the second sphere of the picture the page drew (else the window gave another size).
    const json afterClick = session.answer(clicked).at("ui");
    const json size = session.answer(canvas).at("canvas"), picture = afterClick.at("picture");
    const Scene shown = parseScene(afterClick.at("current").dump(), "page state");
    const double pictureX = size[0].get<int>() / 2.0 + clickX - picture.at("x").get<int>();
    const double pictureY = size[1].get<int>() / 2.0 + clickY - picture.at("y").get<int>();
    const auto hit = pickSurfacePoint(shown, pictureX, pictureY);
    ASSERT_TRUE(hit && hit->object == 1) << "the click at (" << pictureX << ", " << pictureY
                                         << ") of the picture missed the second sphere: " << picture;
    const std::string clickedStatus = afterClick.at("status"), table = afterClick.at("probe");
    EXPECT_EQ(table.rfind("probe: object 2,", 0), 0u) << table;
    EXPECT_EQ(afterClick.at("editedObject"), 2);
    EXPECT_NE(clickedStatus.find("panel edits: object 2 of 12"), std::string::npos) << clickedStatus;
    EXPECT_EQ(session.answer(chooser).at("element").at("value"), "2");
    char own[16];
    std::snprintf(own, sizeof own, "%.1f", grid.objects[1].material.shininess);
    EXPECT_EQ(session.answer(clickedValue).at("element").at("text"), own) << "the slider shows object 2's";
    const Scene afterClickScene = parseScene(afterClick.at("scene").dump(), "page state");
    EXPECT_EQ(afterClickScene.objects.at(6).material.shininess, 31.6) << "a click edits nothing";

    // All objects, chosen explicitly: the slider sets every object's shininess, and each keeps the rest of
    // its own material (the grid's rows differ in specular).
    const json afterAll = session.answer(all).at("ui");
    const std::string allStatus = afterAll.at("status");
    EXPECT_NE(allStatus.find("panel edits: all 12 objects"), std::string::npos) << allStatus;
    const Scene allScene = parseScene(afterAll.at("scene").dump(), "page state");
    ASSERT_EQ(allScene.objects.size(), 12u);
    for (std::size_t i = 0; i < 12; ++i) {
        SCOPED_TRACE("object " + std::to_string(i + 1));
        Material expected = grid.objects[i].material;
        expected.shininess = 100;
        EXPECT_EQ(allScene.objects[i].material, expected)
            << "shininess " << allScene.objects[i].material.shininess;
    }

    // Object 3 got x = 2.5; then every object y = 0.5, each keeping its x (as the material sliders).
    ASSERT_TRUE(session.answer(scaled).at("found").get<bool>()) << "no scale slider";
    EXPECT_EQ(session.answer(scaledValue).at("element").at("text"), "2.50 1.00 1.00");
    const Scene scaledScene = parseScene(session.answer(allScaled).at("ui").at("scene").dump(), "page state");
    ASSERT_EQ(scaledScene.objects.size(), 12u);
    for (std::size_t i = 0; i < 12; ++i) {
        SCOPED_TRACE("object " + std::to_string(i + 1));
        EXPECT_EQ(scaledScene.objects[i].scale, glm::dvec3(i == 2 ? 2.5 : 1, 0.5, 1))
            << "scale " << scaledScene.objects[i].scale.x << " " << scaledScene.objects[i].scale.y;
    }
    expectCleanConsole(session.answer(console).at("console"));
}

// Where WebGL 2 is missing the page says so, never a blank canvas.
TEST_F(Browser, WithoutWebGl2ThePageSaysSo) {
    Session session;
    const std::size_t open = session.open("", {"--disable-webgl2"});
    if (!session.run(dir_)) return;
    EXPECT_NE(session.answer(open).at("failed").get<std::string>().find("no WebGL 2"), std::string::npos)
        << session.answer(open);
}

// Scenes pass through the heap: one over about 1.3 MB (or a panel edit of 10,000 objects, 1.6 MB of JSON)
// threw "memory access out of bounds" and left the page dead. Up to the CLI's 16 MiB loads; beyond it the
// CLI's own message; the page draws on after each, and its panel edits apply to all 10,000 objects. (The
// panel's twice-a-second refresh read the 10,000 objects' JSON three times over, so every call to the
// page waited 10 s, and each material slider step took 2 s: it now reads the scene's values and the shown
// object's material only.)
TEST_F(Browser, LargeScenesLoadAndTooLargeOnesGetTheCommandLineMessage) {
    std::string objects;
    for (int i = 0; i < 10000; ++i)
        objects += std::string(i ? ", " : "") + R"({"center": [)" + std::to_string(i % 100 * 0.05 - 2.5) +
                   ", " + std::to_string(i / 100 * 0.05 - 2.5) +
                   R"(, -3], "radius": 0.02, "subdivisions": 0})";
    std::ofstream(dir_ / "many.json")
        << R"({"image": {"width": 96, "height": 96}, "objects": [)" << objects << "]}";
    std::ofstream(dir_ / "padded.json")
        << R"({"image": {"width": 96, "height": 96})" << std::string(3 << 20, ' ') << "}";
    std::ofstream(dir_ / "huge.json")
        << R"({"image": {"width": 96, "height": 96})" << std::string(17 << 20, ' ') << "}";
    const Outcome cli = runShadelab({"render", "huge.json", "--out", "x.png"}, dir_);
    ASSERT_EQ(cli.exitCode, 2) << cli.err;
    const std::string expected = cli.err.substr(10, cli.err.find('\n') - 10); // less "shadelab: "

    Session session;
    session.open();
    const std::size_t padded = session.loadFile(dir_ / "padded.json", "padded.json");
    const std::size_t huge = session.loadFile(dir_ / "huge.json", "huge.json");
    const std::size_t many = session.loadFile(dir_ / "many.json", "many.json");
    // The toon bands' edit (as a light's) hands back the scene's values; its objects stay.
    const std::size_t edit = session.panel("#bands", "7", "input");
    const std::size_t after = session.message();
    // A material slider with every object chosen: that property of all 10,000.
    session.panel("#object", "0", "input");
    const std::size_t slid = session.panel("#shininess", "1.5", "input"); // log10: 31.6
    const std::size_t afterSlide = session.message();
    const std::size_t ui = session.ui();
    if (!session.run(dir_)) return;
    EXPECT_EQ(session.answer(padded).at("message"), "") << "a 3 MB scene";
    EXPECT_EQ(session.answer(huge).at("message"), expected);
    EXPECT_EQ(session.answer(many).at("message"), "") << "10,000 objects";
    EXPECT_TRUE(session.answer(edit).at("found").get<bool>()) << "no bands slider";
    EXPECT_EQ(session.answer(after).at("message"), "") << "the panel edit of 10,000 objects";
    const json& sceneShown = session.answer(ui).at("ui").at("scene");
    ASSERT_EQ(sceneShown.at("objects").size(), 10000u);
    EXPECT_EQ(sceneShown.at("toon_bands"), 7);
    EXPECT_TRUE(session.answer(slid).at("found").get<bool>()) << "no shininess slider";
    EXPECT_EQ(session.answer(afterSlide).at("message"), "") << "the material edit of 10,000 objects";
    EXPECT_EQ(sceneShown.at("objects").at(0).at("material").at("shininess"), 31.6);
    EXPECT_EQ(sceneShown.at("objects").at(9999).at("material").at("shininess"), 31.6);
}

template <class Enum, std::size_t N> std::vector<std::string> spellings(const std::array<Enum, N>& values) {
    std::vector<std::string> out;
    for (Enum value : values) out.emplace_back(toString(value));
    return out;
}

// The panel's menus are the C++ tables (STYLE 5), not lists typed into index.html: every <select> of a
// vocabulary holds its table's values in its order (the projection menu: the two O switches between; the
// view menu: view.h's kViewNames), and a value's key is in its label (shading 1..5, views E, V, I, Y, Q).
// Fails with a value dropped from the menus the page reads (tables.cpp's term menu given kLightingTerms
// without specular: the page's menu lacked it, so the table was not what the page showed).
TEST_F(Browser, EveryMenuHoldsItsCppTablesValues) {
    Session session;
    session.open();
    const std::size_t menus = session.menus();
    if (!session.run(dir_)) return;
    std::vector<std::string> views;
    for (const ViewName& view : kViewNames) views.emplace_back(view.name);
    const std::map<std::string, std::vector<std::string>> expected = {
        {"shading", spellings(kAllShadingModes)},
        {"lighting", spellings(kLightingModels)},
        {"term", spellings(kLightingTerms)},
        {"perspective-matrix", spellings(kPerspectiveMatrices)},
        {"normal-matrix", spellings(kNormalMatrixRules)},
        {"projection", spellings(std::array{ProjectionType::Perspective, ProjectionType::Orthographic})},
        {"normals", spellings(kVertexNormals)},
        {"overlay", spellings(kOverlays)},
        {"view-kind", views},
        {"shape", spellings(kShapes)},
    };
    std::map<std::string, json> shown;
    for (const json& menu : session.answer(menus).at("menus")) shown[menu.at("id")] = menu;
    for (const auto& [id, values] : expected) {
        ASSERT_TRUE(shown.contains(id)) << "no menu #" << id;
        EXPECT_EQ(shown[id].at("values").get<std::vector<std::string>>(), values) << "#" << id;
    }
    const auto labels = [&](const std::string& id) {
        return shown[id].at("labels").get<std::vector<std::string>>();
    };
    EXPECT_EQ(labels("shading").at(0), "flat (1)");
    EXPECT_EQ(labels("shading").at(4), "exact (5)");
    for (std::size_t i = 0; i < kViewNames.size(); ++i)
        if (!kViewNames[i].key.empty()) {
            EXPECT_NE(labels("view-kind").at(i).find("(" + std::string(kViewNames[i].key) + ")"),
                      std::string::npos)
                << labels("view-kind").at(i);
        }
}

// A % in ?scene= that is no escape: the page starts and says it cannot fetch that scene (a URIError stopped
// it with nothing shown).
TEST_F(Browser, APercentThatIsNoEscapeInTheSceneUrlIsAMessage) {
    Session session;
    const std::size_t open = session.open("?scene=scenes/50%off.json");
    const std::size_t message = session.message();
    if (!session.run(dir_)) return;
    EXPECT_EQ(session.answer(open).at("failed"), "") << session.answer(open);
    const std::string shown = session.answer(message).at("message").get<std::string>();
    EXPECT_NE(shown.find("50%off.json: cannot fetch the scene (HTTP 404)"), std::string::npos) << shown;
}

} // namespace
} // namespace shadelab::test
