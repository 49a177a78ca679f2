// The page's teaching instruments and views (W, probes, the normals overlay, the keys, 5/E/V/I/the NDC view)
// against native renders of the state the page reports (browser_support.h: the session and fixture).

#include "web/browser_support.h"

namespace shadelab::test {
namespace {

using namespace web_test;

// The teaching instruments in the page, with real mouse input: W draws the wireframe (its edges where
// native render draws them for the state the page reports, within a pixel); Shift + drag moves the light
// around the target; a click probes the point under the pointer, and the page's table holds the values the
// native probe computes there; a click that only takes the focus back from the panel places no probe.
// The pixels where an overlay's lines changed a picture (more than 30/255 in a channel from `under`).
struct LineMask {
    int width = 0, height = 0;
    std::vector<bool> set;
    std::size_t count() const { return std::size_t(std::count(set.begin(), set.end(), true)); }
    // How many of this mask's pixels lie within a pixel of one of `other`'s.
    std::size_t within1(const LineMask& other) const {
        std::size_t near = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                if (!set[std::size_t(y * width + x)]) continue;
                bool found = false;
                for (int dy = -1; dy <= 1 && !found; ++dy)
                    for (int dx = -1; dx <= 1 && !found; ++dx)
                        found = x + dx >= 0 && y + dy >= 0 && x + dx < width && y + dy < height &&
                                other.set[std::size_t((y + dy) * width + x + dx)];
                near += found;
            }
        return near;
    }
};
LineMask linePixels(const Image& over, const Image& under) {
    LineMask mask{over.width, over.height,
                  std::vector<bool>(std::size_t(over.width) * std::size_t(over.height))};
    for (std::size_t i = 0; i < mask.set.size(); ++i)
        for (std::size_t k = 0; k < 3; ++k)
            mask.set[i] =
                mask.set[i] || std::abs(int(over.rgba[i * 4 + k]) - int(under.rgba[i * 4 + k])) > 30;
    return mask;
}

TEST_F(Browser, OverlayLightDragAndProbeAsInTheWindow) {
    Scene scene = litSphereScene(160, LightType::Point);
    scene.objects[0].subdivisions = 3;
    Session session;
    session.open();
    session.load(scene);
    const std::size_t plain = session.capture();
    const std::size_t press = session.key('W');
    const std::size_t wired = session.ui();
    const std::size_t wire = session.capture();
    session.drag(-60, 0, true);
    const std::size_t moved = session.ui();
    session.click();
    const std::size_t probed = session.ui();
    // A click that takes the keys back from the panel only focuses the canvas; the next one probes.
    session.clickElement("#help-button"); // H: the help shows
    session.clickElement("#help-button"); // and goes; the button keeps the focus
    session.click(120, 80);
    const std::size_t focused = session.ui();
    session.click(120, 80);
    const std::size_t probedAgain = session.ui();
    session.key('K'); // the ambient term alone: the probe's pixel row follows what is drawn
    const std::size_t ambient = session.ui();
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;

    EXPECT_EQ(session.answer(focused).at("ui").at("probe"), session.answer(probed).at("ui").at("probe"))
        << "the click that focused the canvas placed a probe";
    EXPECT_NE(session.answer(probedAgain).at("ui").at("probe"), session.answer(probed).at("ui").at("probe"))
        << "the click on the focused canvas placed no probe";
    EXPECT_EQ(session.answer(press).at("result"), 1);
    const Scene wireState = parseScene(session.answer(wired).at("ui").at("atImageSize").dump(), "page state");
    EXPECT_EQ(wireState.overlay, Overlay::Wireframe);
    // Lines are one pixel wide and SwiftShader rasterizes them by its own rule: the page's edge pixels
    // (those the overlay changed) must lie within a pixel of native's, and be about as many.
    const Image browser = session.image(wire), browserPlain = session.image(plain);
    Scene plainState = wireState;
    plainState.overlay = Overlay::None;
    const Image native = nativeGles().render(wireState), nativePlain = nativeGles().render(plainState);
    const LineMask pageLines = linePixels(browser, browserPlain),
                   nativeLines = linePixels(native, nativePlain);
    const std::size_t pageCount = pageLines.count(), nativeCount = nativeLines.count(),
                      nearNative = pageLines.within1(nativeLines);
    std::printf(
        "wireframe: %zu edge pixels in the page, %zu native, %zu of the page's within 1 px of native's\n",
        pageCount, nativeCount, nearNative);
    EXPECT_GT(nativeCount, 300u);
    EXPECT_NEAR(double(pageCount), double(nativeCount), 0.15 * double(nativeCount));
    EXPECT_GE(double(nearNative), 0.97 * double(pageCount));
    // Away from the lines the picture is native's.
    const Comparison c = compareImages(browserPlain, nativePlain, swiftShaderTolerance(browserPlain));
    EXPECT_TRUE(c.passed) << c.summary();

    const json afterDrag = session.answer(moved).at("ui");
    const Scene dragged = parseScene(afterDrag.at("current").dump(), "page state");
    EXPECT_LT(dragged.lights[0].position.x, scene.lights[0].position.x) << "dragged left";
    EXPECT_NEAR(glm::length(dragged.lights[0].position), glm::length(scene.lights[0].position), 1e-6);
    EXPECT_NE(afterDrag.at("title").get<std::string>().find("light 1 (point) at ("), std::string::npos);

    const json afterClick = session.answer(probed).at("ui");
    const std::string title = afterClick.at("title"), table = afterClick.at("probe");
    EXPECT_NE(title.find("probe: phong differs from exact by "), std::string::npos) << title;
    ASSERT_EQ(table.rfind("probe: object 1, level 3", 0), 0u) << table;
    // The table's exact pixel against the native probe at the canvas's centre (where the click landed,
    // give or take the rounding of CSS pixels: 0.02 covers a pixel's change there).
    const Scene shown = parseScene(afterClick.at("current").dump(), "page state");
    const auto point = pickSurfacePoint(shown, shown.width / 2.0, shown.height / 2.0);
    ASSERT_TRUE(point.has_value());
    const ProbeReport expected = probeSurface(shown, *point, buildSphere(3));
    const std::size_t row = table.find("pixel");
    ASSERT_NE(row, std::string::npos) << table;
    double values[6] = {};
    ASSERT_EQ(std::sscanf(table.c_str() + row, "pixel %lf %lf %lf | %lf %lf %lf", &values[0], &values[1],
                          &values[2], &values[3], &values[4], &values[5]),
              6)
        << table;
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(values[k], expected.mode.color[k], 0.02) << "phong, channel " << k << "\n" << table;
        EXPECT_NEAR(values[3 + k], expected.exact.color[k], 0.02) << "exact, channel " << k << "\n" << table;
    }
    // With K's ambient term drawn, the table's pixel row is its ambient row (both sides), and the point
    // tracer follows the probed point through the lecture's stages.
    const std::string ambientTable = session.answer(ambient).at("ui").at("probe");
    const auto rowOf = [&](const char* name) {
        std::array<double, 6> v{};
        const std::size_t at = ambientTable.find(std::string(name) + " ");
        EXPECT_NE(at, std::string::npos) << name << " in\n" << ambientTable;
        if (at == std::string::npos) return v;
        const std::string format = std::string(name) + " %lf %lf %lf | %lf %lf %lf";
        EXPECT_EQ(
            std::sscanf(ambientTable.c_str() + at, format.c_str(), &v[0], &v[1], &v[2], &v[3], &v[4], &v[5]),
            6)
            << ambientTable;
        return v;
    };
    const std::array<double, 6> pixel = rowOf("pixel"), ambientRow = rowOf("ambient");
    for (std::size_t k = 0; k < 6; ++k)
        EXPECT_NEAR(pixel[k], std::min(1.0, ambientRow[k]), 1e-3) << "column " << k << "\n" << ambientTable;
    for (const char* stage : {"world  α = M·p", "camera β = M_cam·α", "clip   M_proj·β", "NDC    clip/w"})
        EXPECT_NE(ambientTable.find(stage), std::string::npos) << stage << " in\n" << ambientTable;
    expectCleanConsole(session.answer(console).at("console"));
}

// The normals overlay draws the normals the shading uses (issue 46, item 1): on an ellipsoid, J (normals by
// M) moves the drawn normals, and under each rule the page's lines lie where native's do.
TEST_F(Browser, NormalsOverlayFollowsTheNormalMatrix) {
    Scene scene = litSphereScene(160, LightType::Point);
    scene.objects[0].subdivisions = 1;
    scene.objects[0].scale = {1.6, 0.6, 1};
    scene.overlay = Overlay::Normals;
    scene.term = LightingTerm::Ambient; // an even surface under the lines
    Session session;
    session.open();
    session.load(scene);
    const std::size_t rightUi = session.ui(), right = session.capture();
    const std::size_t press = session.key('J');
    const std::size_t modelUi = session.ui(), model = session.capture();
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    EXPECT_EQ(session.answer(press).at("result"), 1);
    LineMask page[2], native[2];
    int k = 0;
    for (const auto& [ui, capture] : {std::pair{rightUi, right}, std::pair{modelUi, model}}) {
        const Scene state = parseScene(session.answer(ui).at("ui").at("atImageSize").dump(), "page state");
        EXPECT_EQ(state.normalMatrix, k == 0 ? NormalMatrixRule::InverseTranspose : NormalMatrixRule::Model);
        Scene plain = state;
        plain.overlay = Overlay::None;
        const Image under = nativeGles().render(plain);
        page[k] = linePixels(session.image(capture), under);
        native[k] = linePixels(nativeGles().render(state), under);
        SCOPED_TRACE(std::string(toString(state.normalMatrix)));
        std::printf("normals by %s: %zu line pixels in the page, %zu native, %zu within 1 px of native's\n",
                    std::string(toString(state.normalMatrix)).c_str(), page[k].count(), native[k].count(),
                    page[k].within1(native[k]));
        EXPECT_GT(native[k].count(), 200u);
        EXPECT_GE(double(page[k].within1(native[k])), 0.95 * double(page[k].count()));
        ++k;
    }
    // The two rules draw different normals: many of one's line pixels are nowhere near the other's.
    const std::size_t moved = page[0].count() - page[0].within1(page[1]);
    EXPECT_GT(moved, 50u) << "J did not move the drawn normals";
    EXPECT_GT(native[0].count() - native[0].within1(native[1]), 50u);
    expectCleanConsole(session.answer(console).at("console"));
}

// Keys 1–4, B, K (each term of the lighting sum, then all), J (normals by M and back), U (the unnegated
// perspective matrix, an empty picture, and back), +, −, O change the page's picture as they change the
// window's: after each, the picture differs from the one before, and it is what native `render` draws for
// the state the page reports.
TEST_F(Browser, KeysChangeThePictureAsInTheWindow) {
    Scene scene = litSphereScene(160, LightType::Point);
    scene.shading = ShadingMode::Toon;
    scene.objects[0].subdivisions = 3;
    scene.objects[0].scale = {1.4, 0.7, 1}; // an ellipsoid: normals by M (J) change its picture
    Session session;
    session.open();
    session.load(scene);
    struct Step {
        const char* key;
        int code;
        std::size_t ui = 0, capture = 0, press = 0;
    };
    // B in Phong shading, where the highlight shows the model (toon's threshold can hide it).
    std::vector<Step> steps = {{"start", 0}, {"1", '1'}, {"2", '2'}, {"4", '4'}, {"5", '5'}, {"3", '3'},
                               {"B", 'B'},   {"K", 'K'}, {"K", 'K'}, {"K", 'K'}, {"K", 'K'}, {"J", 'J'},
                               {"J", 'J'},   {"U", 'U'}, {"U", 'U'}, {"+", '='}, {"-", '-'}, {"O", 'O'}};
    for (Step& step : steps) {
        if (step.code) step.press = session.key(step.code);
        step.ui = session.ui();
        step.capture = session.capture();
    }
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    Image previous;
    for (const Step& step : steps) {
        SCOPED_TRACE(std::string("after key ") + step.key);
        if (step.code) {
            EXPECT_EQ(session.answer(step.press).at("result"), 1) << "the key was not applied";
        }
        const Scene state =
            parseScene(session.answer(step.ui).at("ui").at("atImageSize").dump(), "page state");
        const Image browser = session.image(step.capture);
        const Image native = nativeGles().render(state);
        const Comparison c = compareImages(browser, native, swiftShaderTolerance(browser));
        EXPECT_TRUE(c.passed) << "the page's picture is not native render's of its state: " << c.summary();
        std::printf("key %s: page vs native render of its state: %s\n", step.key, c.summary().c_str());
        if (!previous.rgba.empty()) {
            EXPECT_FALSE(compareImages(browser, previous, kBeyondRounding).passed)
                << "the key did not change the picture";
        }
        previous = browser;
    }
    const json ui = session.answer(steps.back().ui).at("ui");
    EXPECT_TRUE(ui.at("orthographic").get<bool>());
    EXPECT_EQ(ui.at("current").at("lighting"), "phong") << "B from Blinn-Phong";
    EXPECT_EQ(ui.at("current").at("term"), "all") << "K four times: ambient, diffuse, specular, all";
    EXPECT_EQ(ui.at("current").at("normal_matrix"), "inverse-transpose") << "J twice: model, then back";
    EXPECT_EQ(ui.at("current").at("perspective_matrix"), "webgl") << "U twice: unnegated, then back";
    expectCleanConsole(session.answer(console).at("console"));
}

// The NDC view of one flat red unit sphere (ambient light only: SwiftShader and llvmpipe then differ at
// the silhouette alone) from the eye at 8, the sphere spanning distances 7 to 9: cut by the near plane at
// 7.5 or by the far plane at 8.4, each seen from the side of the face that cuts it, under perspective and
// orthographic projection (the scenes of views_test.cpp's
// NdcView.ASphereTheNearOrFarPlaneCutsEndsAtTheCubesFace).
std::vector<Scene> ndcCutScenes() {
    std::vector<Scene> scenes;
    for (const auto& [near, far, azimuthDeg] : {std::tuple{7.5, 10.0, 40.0}, std::tuple{6.0, 8.4, 110.0}})
        for (ProjectionType type : {ProjectionType::Perspective, ProjectionType::Orthographic}) {
            Scene scene;
            scene.width = scene.height = 200;
            scene.eye = {0, 0, 8};
            scene.projection = {type, 40, -2.4, 2.4, -2.4, 2.4, near, far};
            scene.view.kind = ViewKind::Ndc;
            scene.view.observer = {azimuthDeg, 20, 1};
            scene.objects[0].subdivisions = 5;
            scene.objects[0].material = {{0.9, 0, 0}, {0, 0, 0}, {0, 0, 0}, 1};
            Light ambient;
            ambient.type = LightType::Ambient;
            ambient.ambient = {1, 1, 1};
            ambient.diffuse = ambient.specular = glm::dvec3(0);
            scene.lights = {ambient};
            scene.shading = ShadingMode::Flat;
            scenes.push_back(scene);
        }
    return scenes;
}

// The NDC view's clip, per fragment, in shaders/surface.frag.glsl (NDC_VIEW), and the same in x and y only:
// the mutation that must fail the NDC tests.
constexpr const char* kNdcClipInCube = "any(greaterThan(abs(vCameraClip.xyz), vec3(vCameraClip.w)))";
constexpr const char* kNdcClipXyOnly = "any(greaterThan(abs(vCameraClip.xy), vec2(vCameraClip.w)))";

// The teaching views in the page: 5 (exact), E (error), V (split) and a real mouse drag of its divider, I
// (profile) and a pointer move choosing its row. Each picture is native OpenGL ES's render of the page's
// state (its view included) within the SwiftShader tolerance, and the state says what the key did. The
// panel's "what you are seeing" line follows the view and the shading mode (the one table,
// view_explanations.h), and H's help shows the table under the keys. The NDC view's clip in z: spheres
// the near or far plane cuts are drawn cut, as natively; with the page's shader clipping in x and y only
// (a mutation made here, through WebGL's shaderSource) the same pictures fail the comparison.
TEST_F(Browser, ViewsAsInTheWindow) {
    Scene scene = litSphereScene(200, LightType::Point);
    scene.shading = ShadingMode::Gouraud;
    scene.objects[0].subdivisions = 3;
    Session session;
    session.open();
    session.load(scene);
    struct Step {
        const char* what;
        std::function<std::size_t()> act;
        std::size_t done = 0, ui = 0, capture = 0;
    };
    std::vector<Step> steps = {
        {"start", nullptr},
        {"5", [&] { return session.key('5'); }},
        {"E",
         [&] {
             session.key('2');
             return session.key('E');
         }},
        {"V", [&] { return session.key('V'); }},
        {"divider drag", [&] { return session.drag(-40, 0, false); }},
        {"I", [&] { return session.key('I'); }},
        {"pointer move", [&] { return session.move(0, -50); }},
        {"Y", [&] { return session.key('Y'); }},
        {"observer drag", [&] { return session.drag(30, 10, false); }},
        {"Q", [&] { return session.key('Q'); }},
    };
    std::vector<std::size_t> seeing;
    for (Step& step : steps) {
        if (step.act) step.done = step.act();
        step.ui = session.ui();
        step.capture = session.capture();
        seeing.push_back(session.element("#seeing"));
    }
    // The title after Q's picture was captured: its view report is set when the picture is drawn.
    const std::size_t afterQ = session.ui();
    session.key('H');
    const std::size_t help = session.element("#help");
    const std::size_t viewHelp = session.element("#view-help");
    session.key('H');
    // The outside view's corners on the page, as on GL, GLES and OSMesa (views_test.cpp): a volume alone.
    Scene volume;
    volume.width = volume.height = 256;
    volume.eye = {0, 0, 5};
    volume.projection = {ProjectionType::Perspective, 50, -1, 1, -1, 1, 2.5, 7};
    volume.objects.clear();
    volume.lights.clear();
    volume.view.kind = ViewKind::Outside;
    session.load(volume);
    const std::size_t volumeCapture = session.capture();
    const std::vector<Scene> cuts = ndcCutScenes();
    std::vector<std::size_t> cutCaptures, unclippedCaptures;
    for (const Scene& cut : cuts) {
        session.load(cut);
        cutCaptures.push_back(session.capture());
    }
    // Gouraud draws ambient-only flat red as flat does, through another program: compiled after the mutation.
    session.mutateShader(kNdcClipInCube, kNdcClipXyOnly);
    for (Scene cut : cuts) {
        cut.shading = ShadingMode::Gouraud;
        session.load(cut);
        unclippedCaptures.push_back(session.capture());
    }
    const std::size_t mutations = session.shaderMutations();
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    std::vector<json> states;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const Step& step = steps[i];
        SCOPED_TRACE(step.what);
        const json ui = session.answer(step.ui).at("ui");
        states.push_back(ui.at("current"));
        const Scene state = parseScene(ui.at("atImageSize").dump(), "page state");
        const json line = session.answer(seeing[i]).at("element");
        ASSERT_TRUE(line.is_object()) << "no 'what you are seeing' line in the panel";
        EXPECT_EQ(line.at("text"), app::whatYouAreSeeing(state));
        const Image browser = session.image(step.capture);
        const Comparison c =
            compareImages(browser, nativeGles().render(state), swiftShaderTolerance(browser));
        std::printf("%s: view %s; page vs native render of its state: %s\n", step.what,
                    ui.at("view").get<std::string>().c_str(), c.summary().c_str());
        EXPECT_TRUE(c.passed) << c.summary();
    }
    EXPECT_EQ(states[1].at("shading"), "exact");
    EXPECT_EQ(states[2].at("view"), "error");
    EXPECT_EQ(states[3].at("view"), "split:gouraud,exact");
    ASSERT_TRUE(states[4].contains("view_at"));
    EXPECT_LT(states[4].at("view_at").get<double>(), 0.49) << "the drag did not move the divider left";
    EXPECT_EQ(states[4].at("camera"), states[3].at("camera")) << "the divider drag orbited the camera";
    EXPECT_EQ(states[5].at("view"), "profile");
    ASSERT_TRUE(states[6].contains("view_at"));
    EXPECT_LT(states[6].at("view_at").get<double>(), 0.49) << "the pointer above the centre: a row above it";
    EXPECT_NE(session.answer(steps[6].ui).at("ui").at("title").get<std::string>().find("| profile: row "),
              std::string::npos);
    EXPECT_EQ(states[7].at("view"), "outside");
    EXPECT_EQ(states[8].at("camera"), states[7].at("camera"))
        << "the drag orbited the camera, not the observer";
    EXPECT_NE(states[8].at("view_observer"), states[7].at("view_observer")) << "the drag left the observer";
    EXPECT_EQ(states[9].at("view"), "ndc");
    EXPECT_EQ(states[9].at("view_observer"), states[8].at("view_observer")) << "Q keeps the observer";
    EXPECT_TRUE(session.answer(seeing[0]).at("element").at("text").get<std::string>().starts_with("scene: "));
    EXPECT_NE(session.answer(seeing[0]).at("element").at("text").get<std::string>().find("gouraud: "),
              std::string::npos);
    EXPECT_NE(session.answer(seeing[1]).at("element").at("text").get<std::string>().find("exact: "),
              std::string::npos);
    EXPECT_TRUE(session.answer(seeing[9]).at("element").at("text").get<std::string>().starts_with("ndc: "));
    EXPECT_FALSE(session.answer(help).at("element").at("hidden").get<bool>()) << "H shows the help";
    EXPECT_EQ(session.answer(viewHelp).at("element").at("text"), app::viewHelpText());
    const std::string titleAfterQ = session.answer(afterQ).at("ui").at("title");
    EXPECT_NE(titleAfterQ.find("| ndc: observer at azimuth "), std::string::npos) << titleAfterQ;
    const Image& volumeImage = session.image(volumeCapture);
    ASSERT_EQ(volumeImage.width, 256);
    std::string misses;
    for (const std::string& miss : outsideCornerMisses(volumeImage, volume)) misses += miss + "\n";
    EXPECT_EQ(misses, "") << "the view volume's corners on the page";

    EXPECT_GT(session.answer(mutations).at("count").get<int>(), 0)
        << "the NDC view's shader no longer holds the clip test this test mutates: " << kNdcClipInCube;
    for (std::size_t i = 0; i < cuts.size(); ++i) {
        const std::string label = std::string(cuts[i].projection.near > 7 ? "near" : "far") +
                                  " plane cuts, " + std::string(toString(cuts[i].projection.type));
        SCOPED_TRACE(label);
        const Image native = nativeGles().render(cuts[i]);
        const Image& page = session.image(cutCaptures[i]);
        const Image& unclipped = session.image(unclippedCaptures[i]);
        const Comparison cut = compareImages(page, native, swiftShaderTolerance(page));
        const Comparison whole = compareImages(unclipped, native, swiftShaderTolerance(unclipped));
        std::printf("ndc, %s: page vs native %s; the page clipping in x and y only: %s\n", label.c_str(),
                    cut.summary().c_str(), whole.summary().c_str());
        EXPECT_TRUE(cut.passed) << cut.summary();
        EXPECT_FALSE(whole.passed) << "the comparison cannot tell a sphere left whole in z: "
                                   << whole.summary();
        if (!cut.passed || whole.passed) { // to look at
            writePng(page, dir_ / ("ndc-cut-" + std::to_string(i) + ".png"));
            writePng(unclipped, dir_ / ("ndc-whole-" + std::to_string(i) + ".png"));
        }
    }
    expectCleanConsole(session.answer(console).at("console"));
}

} // namespace
} // namespace shadelab::test
