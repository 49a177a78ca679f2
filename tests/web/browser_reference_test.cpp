// The WebGL 2 build in a real browser (DESIGN §7): Debian's headless Chromium (SwiftShader) driven by
// chromium-driver through web/driver.py, the page served from 127.0.0.1. Held to the same analytic reference
// as the native APIs, to the CPU's flat lighting, and to the native OpenGL ES render of the same scenes; the
// page's keys, messages, canvas size and console are checked as a user meets them (browser_*_test.cpp).
//
// Here: the page's pictures against the analytic references, the CPU and native OpenGL ES.
//
// A session is a batch of requests run by one browser (driver.py session); each test builds one, runs it,
// and reads the answers. Without the browser build or Chromium the tests skip with the reason, except in
// CI (CI set), where they fail.

#include "web/browser_support.h"

namespace shadelab::test {
namespace {

using namespace web_test;

// The bar for every API: Phong at level 8 against the exact ray-cast, interior mean < 0.5/255 and
// max <= 4/255, on the analytic test scenes, read back unrounded through a float target.
TEST_F(Browser, PhongLevel8MatchesTheAnalyticReference) {
    Session session;
    session.open();
    const std::vector<AnalyticCapture> items = captureAnalyticCases(session, ShadingMode::Phong, 8);
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    for (const AnalyticCapture& item : items) {
        const ImageF rendered = session.imageF(item.capture);
        const ReferenceImage reference = renderReference(item.scene);
        const InteriorError e = interiorError(rendered, reference);
        // A spot light's cone edge is a step in the lighting itself: a pixel centre within float rounding
        // of the cutoff is lit in double and unlit in float, or the other way round. SwiftShader lands a few
        // such pixels on the other side (llvmpipe, by chance, none); they are counted, and only for spots.
        const std::size_t over = interiorPixelsOver(rendered, reference, 4);
        const bool hardEdge = std::any_of(item.scene.lights.begin(), item.scene.lights.end(),
                                          [](const Light& l) { return l.type == LightType::Spot; });
        std::printf("webgl2 %s: interior mean %.3f/255, max %.3f/255 over %zu pixels; %zu over 4/255\n",
                    item.label.c_str(), e.mean, e.max, e.pixels, over);
        SCOPED_TRACE(item.label);
        ASSERT_GT(e.pixels, 1000u);
        EXPECT_LT(e.mean, 0.5);
        if (hardEdge) {
            EXPECT_LE(double(over), 0.001 * double(e.pixels)) << "more than the spot cone's edge pixels";
        } else {
            EXPECT_LE(e.max, 4.0);
        }
    }
    expectCleanConsole(session.answer(console).at("console"));
}

// Exact shading on WebGL 2: the sphere ray-cast in the fragment shader against the same ray cast
// in double, on the analytic scenes, read back through a float target: interior mean <= 0.05/255 and max
// <= 2/255 (except, under a spot, pixel centres within float rounding of the cone's edge, counted as in the
// Phong test), and the covered pixels those of the reference within 0.05 per silhouette pixel.
TEST_F(Browser, ExactShadingMatchesTheAnalyticReference) {
    Session session;
    session.open();
    const std::vector<AnalyticCapture> items = captureAnalyticCases(session, ShadingMode::Exact, 8);
    const std::size_t console = session.console();
    if (!session.run(dir_)) return;
    for (const AnalyticCapture& item : items) {
        const ImageF rendered = session.imageF(item.capture);
        const ReferenceImage reference = renderReference(item.scene);
        const InteriorError e = interiorError(rendered, reference);
        const std::size_t over = interiorPixelsOver(rendered, reference, 2);
        const bool hardEdge = std::any_of(item.scene.lights.begin(), item.scene.lights.end(),
                                          [](const Light& l) { return l.type == LightType::Spot; });
        const double shift = silhouetteShiftPx(rendered, reference);
        std::printf("webgl2 exact %s: interior mean %.4f/255, max %.3f/255 over %zu pixels; %zu over 2/255; "
                    "silhouette %.4f px\n",
                    item.label.c_str(), e.mean, e.max, e.pixels, over, shift);
        SCOPED_TRACE(item.label);
        ASSERT_GT(e.pixels, 1000u);
        EXPECT_LE(e.mean, 0.05);
        EXPECT_LE(shift, 0.05);
        if (hardEdge) {
            EXPECT_LE(double(over), 0.001 * double(e.pixels)) << "more than the spot cone's edge pixels";
        } else {
            EXPECT_LE(e.max, 2.0);
        }
    }
    expectCleanConsole(session.answer(console).at("console"));
}

// DESIGN §3 on WebGL 2: one colour per triangle, the CPU's lighting at its centroid within ±1.
TEST_F(Browser, FlatIsLitOnceAtEachCentroidAsTheCpuComputes) {
    Session session;
    session.open();
    // The check asks for each lighting model of its level-1 scene: render both up front.
    std::vector<std::pair<Scene, std::size_t>> shots;
    for (LightingModel model : kLightingModels) {
        Scene scene = litSphereScene(256, LightType::Point);
        scene.shading = ShadingMode::Flat;
        scene.objects[0].subdivisions = 1;
        scene.lighting = model;
        session.load(scene);
        shots.emplace_back(scene, session.capture());
    }
    if (!session.run(dir_)) return;
    checkFlatLitAtCentroids([&](const Scene& scene) {
        for (const auto& [shot, index] : shots)
            if (shot.lighting == scene.lighting) return session.image(index);
        ADD_FAILURE() << "no browser render for " << toString(scene.lighting);
        return Image(scene.width, scene.height);
    });
}

// SwiftShader is not llvmpipe: the same program gives slightly different pixels. Every mode × lighting
// model against the native OpenGL ES render. Where the picture is smooth they agree within 2/255 (mean on the
// interior below 0.1/255); where it steps — the silhouette, flat triangles' shared edges, toon bands, the
// spot cone's edge — a pixel centre may fall on the other side, so those pixels are counted, not bounded: at
// most 1.5 % of the image may differ by more than 2/255.
TEST_F(Browser, MatchesTheNativeOpenGlEsRender) {
    Session session;
    session.open();
    std::vector<std::pair<Scene, std::size_t>> shots;
    for (const Scene& scene : modeScenes(192, 5)) {
        session.load(scene);
        shots.emplace_back(scene, session.capture());
    }
    if (!session.run(dir_)) return;
    for (const auto& [scene, index] : shots) {
        const Image browser = session.image(index);
        const Image native = nativeGles().render(scene);
        const ReferenceImage reference = renderReference(scene);
        const std::vector<bool> interior = interiorMask(reference.objectId, 192, 192, 2);
        int interiorMax = 0;
        std::size_t differing = 0, interiorDiffering = 0, overTwo = 0;
        double interiorSum = 0;
        std::size_t interiorPixels = 0;
        for (std::size_t i = 0; i < interior.size(); ++i) {
            int delta = 0;
            for (int c = 0; c < 3; ++c)
                delta = std::max(delta, std::abs(int(browser.rgba[i * 4 + c]) - int(native.rgba[i * 4 + c])));
            differing += delta > 0;
            overTwo += delta > 2;
            if (!interior[i]) continue;
            ++interiorPixels;
            interiorSum += delta;
            interiorMax = std::max(interiorMax, delta);
            interiorDiffering += delta > 0;
        }
        const std::string label =
            std::string(toString(scene.shading)) + "/" + std::string(toString(scene.lighting));
        std::printf(
            "webgl2 vs native gles %s: interior max %d/255, mean %.4f/255, %zu of %zu interior px differ; "
            "%zu px differ in all, %zu by more than 2/255\n",
            label.c_str(), interiorMax, interiorSum / double(interiorPixels), interiorDiffering,
            interiorPixels, differing, overTwo);
        // Each against the exact answer, both read back in 8 bits: the error the shading mode makes.
        const InteriorError browserError = interiorError(asFloat(browser), reference);
        const InteriorError nativeError = interiorError(asFloat(native), reference);
        std::printf("  %s against the analytic reference (8-bit, interior mean / max): webgl2 %.3f / %.1f, "
                    "native gles %.3f / %.1f\n",
                    label.c_str(), browserError.mean, browserError.max, nativeError.mean, nativeError.max);
        SCOPED_TRACE(label);
        EXPECT_NEAR(browserError.mean, nativeError.mean, 0.1) << "the browser's error is not the shading's";
        EXPECT_LT(interiorSum / double(interiorPixels), 0.1);
        EXPECT_LE(double(overTwo), 0.015 * 192 * 192);
    }
}

} // namespace
} // namespace shadelab::test
