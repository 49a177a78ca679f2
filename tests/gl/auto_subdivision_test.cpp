// "auto" subdivision (DESIGN §1): the level is the smallest whose guaranteed silhouette error R_px·δₙ
// (δₙ the max radial deviation, < 4^(1−n)) stays within the tolerance. The measured error must then be
// within the tolerance too: pixels whose coverage differs from the analytic reference, divided by the
// silhouette's length, give the mean gap in pixels between the mesh's outline and the sphere's.
//
// The issue also asks that one level lower the measured gap exceed the tolerance. It does not: the mean
// gap along the outline is about R_px·4^(−n), a quarter of the bound (the outline runs along edges,
// whose sag is a quarter of a face's), so one level lower it is about R_px·δₙ — at or below the
// tolerance. Measured here: 0.11, 0.47, 0.33 px at one level below auto for R = 40, 120, 300 px.
// What this test asserts instead is that auto is the smallest level with the guarantee.
#include <cmath>
#include <numbers>

#include "gl/gl_test_support.h"
#include "shadelab/geometry/subdivision.h"
#include "shadelab/scene/auto_level.h"

namespace shadelab::test {
namespace {

// Mean distance in pixels between the rendered outline and the exact one.
double silhouetteGapPx(const Image& rendered, const ReferenceImage& reference, double radiusPx) {
    std::size_t differing = 0;
    for (int y = 0; y < rendered.height; ++y)
        for (int x = 0; x < rendered.width; ++x) {
            const bool covered = rendered.pixel(x, y)[3] > 0;
            const bool exact = reference.objectId[std::size_t(y) * rendered.width + x] >= 0;
            differing += covered != exact;
        }
    return double(differing) / (2 * std::numbers::pi * radiusPx);
}

struct AutoCase {
    const char* name;
    double radiusPx;
    bool perspective;
};

// Test names and failure messages show the case by its name, not as bytes.
inline void PrintTo(const AutoCase& c, std::ostream* os) {
    *os << c.name;
}

class AutoSubdivision : public testing::TestWithParam<AutoCase> {};

TEST_P(AutoSubdivision, ChosenLevelIsTheSmallestWithinTolerance) {
    SHADELAB_REQUIRE_GL(renderer);
    const AutoCase& c = GetParam();
    Scene scene = litSphereScene(2 * int(c.radiusPx) + 40, LightType::Directional);
    const double half = scene.width / 2.0 / c.radiusPx; // world units across half the image (radius 1)
    if (c.perspective) {
        scene.eye = {0, 0, 1 / std::sin(std::atan(std::tan(20 * std::numbers::pi / 180) / half))};
        scene.projection.far = 100;
    } else {
        scene.projection = {ProjectionType::Orthographic, 40, -half, half, -half, half, 0.5, 20};
    }
    scene.objects[0].subdivisions = kAutoSubdivisions;
    scene.tolerancePx = 0.5;
    const double radiusPx = projectedRadiusPx(scene, scene.objects[0]);
    const int level = autoSubdivisionLevel(scene, scene.objects[0]);
    const ReferenceImage reference = renderReference(scene);
    scene.objects[0].subdivisions = level;
    const double gap = silhouetteGapPx(renderer->render(scene), reference, radiusPx);
    scene.objects[0].subdivisions = level - 1;
    const double coarserGap = silhouetteGapPx(renderer->render(scene), reference, radiusPx);
    std::printf("%s: R = %.1f px, auto level %d: gap %.3f px; level %d: %.3f px\n", c.name, radiusPx, level,
                gap, level - 1, coarserGap);
    EXPECT_LE(gap, scene.tolerancePx) << "the measured gap exceeds the tolerance at the auto level";
    EXPECT_LT(gap, coarserGap) << "one level lower must be visibly coarser";
    // Smallest with the guarantee: the bound holds at the chosen level and fails one level lower.
    const double tolerance =
        scene.tolerancePx * (c.perspective ? 1 - std::pow(1 / glm::length(scene.eye), 2) : 1);
    EXPECT_LE(radiusPx * std::pow(4.0, 1 - level), tolerance);
    EXPECT_GT(radiusPx * std::pow(4.0, 2 - level), tolerance);
    // And the guarantee itself: the mesh's max radial deviation, measured, times R_px.
    EXPECT_LE(radiusPx * maxRadialDeviation(buildSphere(level)), tolerance);
}

INSTANTIATE_TEST_SUITE_P(Radii, AutoSubdivision,
                         testing::Values(AutoCase{"ortho_r40", 40, false}, AutoCase{"ortho_r120", 120, false},
                                         AutoCase{"ortho_r300", 300, false},
                                         AutoCase{"persp_r100", 100, true}),
                         [](const auto& info) { return std::string(info.param.name); });

} // namespace
} // namespace shadelab::test
