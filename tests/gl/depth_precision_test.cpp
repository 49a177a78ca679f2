// Depth precision under stress: two equal spheres on the view axis, the farther one `gap` behind
// the nearer, so it is hidden everywhere; every pixel where the farther one wins is a depth-test failure.
// For each distance and near plane the smallest gap with no failing pixel is found by bisection, in both
// depth modes, and compared with DESIGN §2's estimates: ≈ 6e-8·d²/near (standard) and ≈ 1.2e-7·d
// (reversed-Z, independent of near). The table is printed for the README.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "gl/gl_test_support.h"
#include "shadelab/errors.h"
#include "shadelab/scene/scene.h"

namespace shadelab::test {
namespace {

constexpr int kSize = 48;

Scene twoSpheres(double distance, double gap, double near, double far, DepthMode depth) {
    Scene scene;
    scene.width = scene.height = kSize;
    scene.eye = {0, 0, 0};
    scene.target = {0, 0, -1};
    scene.projection = {ProjectionType::Perspective, 6, -1, 1, -1, 1, near, far};
    scene.depth = depth;
    const double radius = 0.04 * distance;
    SceneObject front, back;
    front.radius = back.radius = radius;
    front.subdivisions = back.subdivisions = 4;
    front.center = {0, 0, -(distance + radius)}; // front surface at `distance`
    back.center = {0, 0, -(distance + radius + gap)};
    front.material = {{1, 0, 0}, {0, 0, 0}, {0, 0, 0}, 1};
    back.material = {{0, 0, 1}, {0, 0, 0}, {0, 0, 0}, 1};
    Light ambient;
    ambient.type = LightType::Ambient;
    ambient.ambient = {1, 1, 1};
    ambient.diffuse = ambient.specular = glm::dvec3(0);
    scene.lights = {ambient};
    // The farther sphere is drawn first: where the two depths round to the same value, GL_GREATER keeps
    // it, so a tie counts as a failure, as it must.
    scene.objects = {back, front};
    return scene;
}

// Pixels where the depth test failed: the farther (blue) sphere shows, or the nearer (red) one is missing
// where it should cover — with a tiny near plane the standard mapping can squeeze both spheres to the
// cleared depth, where GL_GREATER draws neither.
int farWins(HeadlessRenderer& renderer, const Scene& scene) {
    const Image image = renderer.render(scene);
    int blue = 0, red = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            blue += image.pixel(x, y)[2] > 128;
            red += image.pixel(x, y)[0] > 128;
        }
    // How many pixels the nearer sphere covers, from its exact silhouette, less a rim for tessellation.
    const std::vector<int> ids = renderReference(scene).objectId;
    const int expected = int(std::count(ids.begin(), ids.end(), 1));
    return blue + std::max(0, int(0.8 * expected) - red);
}

// The smallest relative gap (gap / distance), on a grid of factor 1.25, from which every larger gap
// resolves with no failing pixel; 1 if even a gap of the whole distance fails. Scanned downwards, not
// bisected: quantized depths can resolve a lucky tiny gap while failing larger ones.
double smallestResolvableGap(HeadlessRenderer& renderer, double distance, double near, double far,
                             DepthMode depth) {
    double resolved = 1;
    if (farWins(renderer, twoSpheres(distance, distance, near, far, depth)) > 0) return 1;
    for (double gap = 0.8; gap > 1e-12; gap *= 0.8) {
        if (farWins(renderer, twoSpheres(distance, gap * distance, near, far, depth)) > 0) break;
        resolved = gap;
    }
    return resolved;
}

TEST(DepthPrecision, ReversedZResolvesGapsProportionalToDistanceAtAnyNear) {
    SHADELAB_REQUIRE_GL(renderer);
    const double far = 1e7;
    std::printf("| distance d | near | standard: smallest gap | 6e-8·d²/near | reversed: smallest gap | "
                "1.2e-7·d |\n|---|---|---|---|---|---|\n");
    for (double near : {0.1, 1e-4}) {
        for (double distance : {1.0, 10.0, 100.0, 1e3, 1e4, 1e5}) {
            // Standard depth refuses scenes reaching past kMaxStandardDepthRatio near distances (their
            // objects' depth rounds to the clear value): those rows must be ones it could not resolve anyway.
            bool refused = false;
            try {
                validateScene(twoSpheres(distance, distance, near, far, DepthMode::Standard));
            } catch (const InputError& e) {
                refused = true;
                EXPECT_GT(distance / near, 1e6) << "a usable standard-depth scene was refused: " << e.what();
                EXPECT_NE(std::string(e.what()).find("reversed"), std::string::npos) << e.what();
            }
            const double standard =
                refused ? 1 : smallestResolvableGap(*renderer, distance, near, far, DepthMode::Standard);
            const double reversed =
                smallestResolvableGap(*renderer, distance, near, far, DepthMode::Reversed);
            const double standardTheory = 6e-8 * distance * distance / near,
                         reversedTheory = 1.2e-7 * distance;
            char standardText[32];
            std::snprintf(standardText, sizeof standardText, "%.2g", standard * distance);
            std::printf("| %g | %g | %s | %.2g | %.2g | %.2g |\n", distance, near,
                        refused         ? "refused"
                        : standard >= 1 ? "none (> d)"
                                        : standardText,
                        standardTheory, reversed * distance, reversedTheory);
            // Reversed-Z: within a small factor of 1.2e-7·d (float w and the sphere's own tessellation
            // add a little), whatever near is.
            EXPECT_LE(reversed * distance, 8 * reversedTheory) << "d " << distance << ", near " << near;
            // Standard: no better than its theory allows (a factor 4 for the estimate's looseness), and
            // never better than reversed by more than that factor.
            if (refused) continue;
            if (standardTheory < distance) {
                EXPECT_GE(standard * distance, standardTheory / 4) << "d " << distance << ", near " << near;
            }
            EXPECT_GE(standard * 4, reversed) << "d " << distance << ", near " << near;
        }
    }
}

TEST(DepthPrecision, InfiniteFarPlaneDrawsBeyondAnyFarAndStillResolves) {
    SHADELAB_REQUIRE_GL(renderer);
    // far = 10 would clip a sphere at 1000; the infinite far plane draws it, and depth still works.
    const Scene scene = twoSpheres(1000, 1, 0.01, 10, DepthMode::ReversedInfinite);
    const Image image = renderer->render(scene);
    EXPECT_GT(image.pixel(kSize / 2, kSize / 2)[0], 200) << "the near sphere is not drawn";
    EXPECT_EQ(farWins(*renderer, scene), 0);
    EXPECT_LE(smallestResolvableGap(*renderer, 1e4, 1e-4, 10, DepthMode::ReversedInfinite) * 1e4,
              8 * 1.2e-7 * 1e4);
}

} // namespace
} // namespace shadelab::test
