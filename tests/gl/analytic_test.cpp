// Rendered images against the analytic reference (an exact ray-cast with the same lighting code):
// Phong shading converges to it, and each mode's error falls at the rate its interpolation predicts.
#include <cmath>
#include <functional>

#include "gl/gl_test_support.h"

namespace shadelab::test {
namespace {

struct AnalyticCase {
    const char* name;
    std::function<Scene()> scene;
};

Scene withObjects(Scene scene, std::vector<SceneObject> objects) {
    scene.objects = std::move(objects);
    return scene;
}

const AnalyticCase kCases[] = {
    {"perspective_point", [] { return litSphereScene(256, LightType::Point); }},
    {"directional", [] { return litSphereScene(256, LightType::Directional); }},
    {"spot", [] { return litSphereScene(256, LightType::Spot); }},
    {"ambient_only", [] { return litSphereScene(256, LightType::Ambient); }},
    {"off_centre_frustum",
     [] {
         Scene s = litSphereScene(256, LightType::Point);
         s.projection = {ProjectionType::Frustum, 40, -0.05, 0.2, -0.15, 0.1, 0.5, 20};
         return s;
     }},
    {"orthographic",
     [] {
         Scene s = litSphereScene(256, LightType::Point);
         s.projection = {ProjectionType::Orthographic, 40, -1.4, 1.4, -1.4, 1.4, 0.5, 20};
         return s;
     }},
    {"ellipsoid",
     [] {
         SceneObject o;
         o.scale = {1.3, 0.7, 0.9};
         return withObjects(litSphereScene(256, LightType::Point), {o});
     }},
    {"two_overlapping_spheres",
     [] {
         SceneObject a, b;
         a.center = {-0.45, 0, 0.5};
         a.radius = 0.7;
         b.center = {0.45, 0.1, -0.4};
         b.material.diffuse = {0.2, 0.3, 0.8};
         return withObjects(litSphereScene(256, LightType::Point), {a, b});
     }},
};

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

INSTANTIATE_TEST_SUITE_P(Scenes, PhongAgainstReference, testing::ValuesIn(kCases),
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
    for (std::size_t i = 0; i < errors.size(); ++i) out += "n=" + std::to_string(3 + i) + ": " + std::to_string(errors[i]) + "  ";
    return out;
}

// Smooth modes interpolate over triangles of edge h ~ 2⁻ⁿ with O(h²) error: ~4× per level; the issue
// asks for at least 3×.
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
