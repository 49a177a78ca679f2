// One term of the lighting sum (the scene's "term", DESIGN §3): each term drawn alone against the analytic
// reference of that term, and the three terms adding up to the whole picture, in every shading mode.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "gl/gl_test_support.h"

namespace shadelab::test {
namespace {

constexpr std::array kSingleTerms = {LightingTerm::Ambient, LightingTerm::Diffuse, LightingTerm::Specular};

Scene withTerm(Scene scene, LightingTerm term) {
    scene.term = term;
    return scene;
}

// The renderer draws a term by zeroing the other terms' coefficients (onlyTerm); the reference takes the
// term from its three sums (LightTerms::of). Phong shading at level 8 is held to the bars of the whole sum
// (analytic_test.cpp: mean < 0.5/255, max <= 4/255 on the interior), for both lighting models.
TEST(Terms, EachTermAloneMatchesTheReferenceOfThatTerm) {
    SHADELAB_REQUIRE_GL(renderer);
    for (const char* name : {"perspective_point", "spot", "orthographic"}) {
        Scene scene = analyticCase(name).scene();
        scene.shading = ShadingMode::Phong;
        for (SceneObject& o : scene.objects) o.subdivisions = 8;
        // Every light with an ambient part too, so that the ambient term is not black.
        for (Light& light : scene.lights) light.ambient = {0.3, 0.3, 0.3};
        for (LightingModel model : kLightingModels) {
            scene.lighting = model;
            const ReferenceImage whole = renderReference(scene);
            for (LightingTerm term : kSingleTerms) {
                SCOPED_TRACE(std::string(name) + ", " + std::string(toString(model)) + ", " +
                             std::string(toString(term)));
                const ReferenceImage expected = renderReference(withTerm(scene, term));
                const InteriorError e = interiorError(renderer->renderFloat(withTerm(scene, term)), expected);
                std::printf("%s/%s/%s: interior mean %.3f/255, max %.3f/255 over %zu pixels\n", name,
                            toString(model).data(), toString(term).data(), e.mean, e.max, e.pixels);
                ASSERT_GT(e.pixels, 1000u) << "the interior is nearly empty";
                EXPECT_LT(e.mean, 0.5) << "mean interior error in 1/255 units";
                EXPECT_LE(e.max, 4.0) << "max interior error in 1/255 units";
                // The term is not the whole picture (a test of a term that draws everything would pass).
                double largest = 0;
                for (std::size_t i = 0; i < whole.color.rgba.size(); ++i)
                    largest =
                        std::max(largest, double(std::abs(whole.color.rgba[i] - expected.color.rgba[i])));
                EXPECT_GT(largest, 0.05) << "the term's reference equals the whole sum's";
            }
        }
    }
}

// The sum is linear before the clamp, so where nothing saturates the three terms' 8-bit pictures add up
// to the whole picture within their three roundings (3/255 per channel), in every mode: flat (once per
// triangle), Gouraud (per vertex, interpolated), Phong, toon (bands and a thresholded highlight) and exact.
// The scene is lit so that nothing reaches 1 anywhere: Gouraud clamps each vertex before it interpolates,
// so a saturated vertex would break the sum across its triangles, not only at itself.
TEST(Terms, AmbientDiffuseAndSpecularAddUpToTheWholePicture) {
    SHADELAB_REQUIRE_GL(renderer);
    Scene scene = litSphereScene(128, LightType::Point);
    for (Light& light : scene.lights) {
        light.ambient = {0.3, 0.3, 0.3};
        light.diffuse = {0.6, 0.6, 0.6};
        light.specular = {0.5, 0.5, 0.5};
    }
    for (SceneObject& o : scene.objects) {
        o.subdivisions = 3;
        o.material.specular = {0.5, 0.5, 0.5}; // at most 0.03 + 0.42 + 0.25 = 0.7 in every channel
    }
    for (ShadingMode mode : kAllShadingModes)
        for (LightingModel model : kLightingModels) {
            scene.shading = mode;
            scene.lighting = model;
            SCOPED_TRACE(std::string(toString(mode)) + ", " + std::string(toString(model)));
            const Image whole = renderer->render(scene);
            std::vector<Image> terms;
            for (LightingTerm term : kSingleTerms) terms.push_back(renderer->render(withTerm(scene, term)));
            std::size_t covered = 0, highlighted = 0, off = 0;
            int worst = 0, brightest = 0;
            for (int y = 0; y < whole.height; ++y)
                for (int x = 0; x < whole.width; ++x) {
                    if (whole.pixel(x, y)[3] == 0) continue; // background
                    ++covered;
                    if (terms[2].pixel(x, y)[0] > 0) ++highlighted;
                    for (int c = 0; c < 3; ++c) {
                        const int sum =
                            terms[0].pixel(x, y)[c] + terms[1].pixel(x, y)[c] + terms[2].pixel(x, y)[c];
                        const int d = std::abs(sum - whole.pixel(x, y)[c]);
                        brightest = std::max<int>(brightest, whole.pixel(x, y)[c]);
                        worst = std::max(worst, d);
                        if (d > 3) ++off;
                    }
                }
            ASSERT_GT(covered, 5000u) << "the sphere does not fill the picture";
            ASSERT_LT(brightest, 250) << "a channel saturates: the scene no longer tests the sum";
            EXPECT_GT(highlighted, 50u) << "no highlight in the specular term";
            EXPECT_EQ(off, 0u)
                << "channels where ambient + diffuse + specular differs from the whole by more "
                   "than 3/255 (worst "
                << worst << "/255)";
        }
}

} // namespace
} // namespace shadelab::test
