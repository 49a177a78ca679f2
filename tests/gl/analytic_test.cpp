// Rendered images against the analytic reference (an exact ray-cast with the same lighting code):
// Phong shading converges to it, and each mode's error falls at the rate its interpolation predicts.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "gl/gl_test_support.h"

namespace shadelab::test {
namespace {

class PhongAgainstReference : public testing::TestWithParam<AnalyticCase> {};

// DESIGN §6: at high subdivision Phong shading is the exact per-point lighting up to the mesh's tiny
// position and normal error; the limits are the (mean < 0.5/255, max <= 4/255 on the interior).
TEST_P(PhongAgainstReference, InteriorErrorIsBelowHalfALevel) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = GetParam().scene();
    scene.shading = ShadingMode::Phong;
    for (SceneObject& o : scene.objects) o.subdivisions = 8;
    for (LightingModel model : kLightingModels) {
        scene.lighting = model;
        const InteriorError e = interiorError(renderer->renderFloat(scene), renderReference(scene));
        SCOPED_TRACE(std::string(toString(model)));
        std::printf("%s/%s: interior mean %.3f/255, max %.3f/255 over %zu pixels\n", GetParam().name,
                    toString(model).data(), e.mean, e.max, e.pixels);
        ASSERT_GT(e.pixels, 1000u) << "the interior is nearly empty: the scene does not show its object";
        EXPECT_LT(e.mean, 0.5) << "mean interior error in 1/255 units";
        EXPECT_LE(e.max, 4.0) << "max interior error in 1/255 units";
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, PhongAgainstReference, testing::ValuesIn(analyticCases()),
                         [](const auto& info) { return std::string(info.param.name); });

struct ErrorStats {
    double median = 0, fractionOver = 0; // fraction of pixels with error > the threshold
};
ErrorStats errorStats(std::vector<double> errors, double threshold) {
    ErrorStats stats;
    if (errors.empty()) return stats;
    stats.fractionOver =
        double(std::count_if(errors.begin(), errors.end(), [&](double e) { return e > threshold; })) /
        double(errors.size());
    const auto middle = errors.begin() + std::ptrdiff_t(errors.size() / 2);
    std::nth_element(errors.begin(), middle, errors.end());
    stats.median = *middle;
    return stats;
}

class ToonAgainstReference : public testing::TestWithParam<AnalyticCase> {};

// DESIGN §3: toon shading is per-fragment lighting with the diffuse term quantized into bands and a
// thresholded highlight; the reference quantizes the exact lighting the same way. At level 8 the mesh's
// normals are nearly exact, so most pixels match to float rounding; but a pixel whose centre lies within the
// tiny normal error of a band edge or the highlight threshold lands in the neighbouring band and is off by
// a whole band. Those are a thin line of pixels: at most 1% of the interior may exceed 2/255, and the median
// must stay below 0.5/255. Catches: toon falling back to smooth Phong (every lit pixel off by up to a band),
// a different band count or rounding (floor vs ceil), a different highlight threshold, bands not quantized
// per light, the wrong lighting model in the toon programs.
TEST_P(ToonAgainstReference, MatchesExceptAtBandEdges) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = GetParam().scene();
    scene.shading = ShadingMode::Toon;
    for (SceneObject& o : scene.objects) o.subdivisions = 8;
    for (LightingModel model : kLightingModels) {
        scene.lighting = model;
        SCOPED_TRACE(std::string(toString(model)));
        const std::vector<double> errors =
            interiorPixelErrors(renderer->renderFloat(scene), renderReference(scene));
        const ErrorStats stats = errorStats(errors, 2.0);
        std::printf("toon %s/%s: %zu interior pixels, %.3f%% over 2/255, median %.4f/255\n", GetParam().name,
                    toString(model).data(), errors.size(), 100 * stats.fractionOver, stats.median);
        ASSERT_GT(errors.size(), 1000u) << "the interior is nearly empty: the scene does not show its object";
        EXPECT_LE(stats.fractionOver, 0.01) << "fraction of interior pixels off by more than 2/255";
        EXPECT_LT(stats.median, 0.5) << "median interior error in 1/255 units";
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ToonAgainstReference, testing::ValuesIn(analyticCases()),
                         [](const auto& info) { return std::string(info.param.name); });

// Mean interior error per level n = 3..6 at 512×512 with the sphere's radius ≈ 250 px (DESIGN §6).
std::vector<double> errorByLevel(HeadlessRenderer& renderer, ShadingMode mode) {
    Scene scene = litSphereScene(512, LightType::Point);
    scene.eye = {0, 0, 3.1}; // radius ≈ 250 px at fovy 40°
    scene.objects[0].material.shininess = 16;
    scene.shading = mode;
    const ReferenceImage reference = renderReference(scene);
    std::vector<double> errors;
    for (int level = 3; level <= 6; ++level) {
        scene.objects[0].subdivisions = level;
        errors.push_back(interiorError(renderer.renderFloat(scene), reference).mean);
    }
    return errors;
}

std::string describe(const std::vector<double>& errors) {
    std::string out;
    for (std::size_t i = 0; i < errors.size(); ++i)
        out += "n=" + std::to_string(3 + i) + ": " + std::to_string(errors[i]) + "  ";
    return out;
}

// Smooth modes interpolate over triangles of edge h ~ 2⁻ⁿ with O(h²) error: ~4× per level; the issue
// asks for at least 3×. The margin is thin. Measured on Mesa 22.3 llvmpipe (EGL and OSMesa alike), mean
// error n=3..6: Phong 4.85, 1.57, 0.460, 0.129 — ratios 3.08 at n=3→4 (the shininess-16 highlight is not
// yet resolved by level-3 triangles, so the error is not yet in its O(h²) regime), then 3.42 and 3.57;
// Gouraud 8.79, 2.75, 0.847, 0.246 — ratios 3.19, 3.25, 3.45. A small change to the scene or the interior
// mask can push the n=3→4 ratio under 3 without any rendering fault: look at the later ratios first.
TEST(Convergence, GouraudAndPhongFallAtLeast3xPerLevel) {
    SHADELAB_REQUIRE_GL(renderer);
    for (ShadingMode mode : {ShadingMode::Gouraud, ShadingMode::Phong}) {
        const std::vector<double> errors = errorByLevel(*renderer, mode);
        std::printf("%s interior mean error (1/255): %s\n", toString(mode).data(), describe(errors).c_str());
        for (std::size_t i = 0; i + 1 < errors.size(); ++i)
            EXPECT_GE(errors[i] / errors[i + 1], 3.0) << toString(mode) << ": " << describe(errors);
    }
}

// Flat shading is piecewise constant: O(h) error, about 2× per level (1.6–2.6 allowed: the ratio
// wobbles with how triangle centroids fall relative to the highlight).
TEST(Convergence, FlatFallsAbout2xPerLevel) {
    SHADELAB_REQUIRE_GL(renderer);
    const std::vector<double> errors = errorByLevel(*renderer, ShadingMode::Flat);
    std::printf("flat interior mean error (1/255): %s\n", describe(errors).c_str());
    for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
        EXPECT_GE(errors[i] / errors[i + 1], 1.6) << describe(errors);
        EXPECT_LE(errors[i] / errors[i + 1], 2.6) << describe(errors);
    }
}

} // namespace
} // namespace shadelab::test
