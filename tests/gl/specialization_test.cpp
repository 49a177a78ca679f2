// Scene-specialized programs against the uber program: the same equation with absent terms left out,
// so on every scene the two pictures agree within 1/255 (float sums in another order), and programs are
// cached by their key.
#include <functional>

#include "gl/gl_test_support.h"
#include "shadelab/errors.h"
#include "shadelab/gl/program.h"

namespace shadelab::test {
namespace {

struct CrossCheckCase {
    const char* name;
    std::function<void(Scene&)> change;
};

// Test names and failure messages show the case by its name, not as bytes.
inline void PrintTo(const CrossCheckCase& c, std::ostream* os) {
    *os << c.name;
}

Light light(LightType type, glm::dvec3 position, glm::dvec3 color) {
    Light l;
    l.type = type;
    l.position = position;
    l.direction = -position;
    l.diffuse = l.specular = color;
    if (type == LightType::Spot) {
        l.cutoffDeg = 25;
        l.exponent = 4;
    }
    return l;
}

const CrossCheckCase kCases[] = {
    {"default_point", [](Scene&) {}},
    {"one_directional",
     [](Scene& s) {
         s.lights = {light(LightType::Directional, {1, 1, 2}, {1, 1, 1})};
     }},
    {"attenuated_spot",
     [](Scene& s) {
         s.lights = {light(LightType::Spot, {1, 1, 3}, {1, 0.9, 0.8})};
         s.lights[0].attenuation = {0.5, 0.1, 0.02};
     }},
    {"four_mixed_lights",
     [](Scene& s) {
         Light ambient;
         ambient.type = LightType::Ambient;
         ambient.ambient = {0.15, 0.1, 0.1};
         ambient.diffuse = ambient.specular = glm::dvec3(0);
         s.lights = {ambient, light(LightType::Directional, {-1, 1, 1}, {0.3, 0.3, 0.6}),
                     light(LightType::Point, {2, 2, 3}, {0.9, 0.8, 0.7}),
                     light(LightType::Spot, {-1, -2, 3}, {0.2, 0.9, 0.3})};
         s.lights[2].attenuation = {1, 0.05, 0.01};
     }},
    {"no_specular", [](Scene& s) { s.objects[0].material.specular = glm::dvec3(0); }},
    {"mirrored_ellipsoid",
     [](Scene& s) {
         s.objects[0].scale = {-1.2, 0.8, 1};
     }},
    {"ambient_only",
     [](Scene& s) {
         s.lights[0].type = LightType::Ambient;
         s.lights[0].ambient = {0.5, 0.5, 0.5};
     }},
    {"no_lights", [](Scene& s) { s.lights.clear(); }},
    {"eight_lights_two_objects",
     [](Scene& s) {
         s.lights.clear();
         for (int i = 0; i < kMaxLights; ++i)
             s.lights.push_back(light(i % 2 ? LightType::Point : LightType::Spot,
                                      {3 * std::cos(i * 0.8), 3 * std::sin(i * 0.8), 2}, glm::dvec3(0.2)));
         SceneObject second;
         second.center = {0.8, 0.3, -1};
         second.material.specular = glm::dvec3(0);
         s.objects.push_back(second);
     }},
};

class Specialization : public testing::TestWithParam<CrossCheckCase> {};

TEST_P(Specialization, AgreesWithTheUberProgramWithin1Of255) {
    SHADELAB_REQUIRE_GL(renderer);
    for (ShadingMode mode : kShadingModes) {
        for (LightingModel model : kLightingModels) {
            Scene scene = litSphereScene(96, LightType::Point);
            scene.objects[0].subdivisions = 4;
            scene.shading = mode;
            scene.lighting = model;
            GetParam().change(scene);
            renderer->setSpecialize(false);
            const Image uber = renderer->render(scene);
            renderer->setSpecialize(true);
            const Image specialized = renderer->render(scene);
            // Every pixel within 1/255 (the limit), toon bands included: no outlier budget.
            const Comparison c = compareImages(specialized, uber, Tolerance{1, 0.05, 0});
            EXPECT_TRUE(c.passed) << toString(mode) << "/" << toString(model) << ": " << c.summary();
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, Specialization, testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

// Flat shading from shared vertices through a geometry shader gives the picture of the duplicated-vertex
// layout: the same centroid and face normal, derived on the GPU in float (1/255 for rounding).
TEST_P(Specialization, FlatGeometryShaderMatchesDuplicatedVertices) {
    SHADELAB_REQUIRE_GL(renderer);
    for (LightingModel model : kLightingModels) {
        Scene scene = litSphereScene(96, LightType::Point);
        scene.objects[0].subdivisions = 3;
        scene.shading = ShadingMode::Flat;
        scene.lighting = model;
        GetParam().change(scene);
        const Image duplicated = renderer->render(scene);
        renderer->setFlatGeometryShader(true);
        if (renderer->api() == Api::Gles) { // DESIGN §7: refused by name, never drawn another way
            try {
                renderer->render(scene);
                ADD_FAILURE() << "OpenGL ES drew the geometry-shader layout it does not have";
            } catch (const RuntimeError& e) {
                EXPECT_NE(std::string(e.what()).find("OpenGL ES 3.0 has no geometry stage"),
                          std::string::npos)
                    << e.what();
            }
            renderer->setFlatGeometryShader(false);
            continue;
        }
        const Image geometryShader = renderer->render(scene);
        renderer->setFlatGeometryShader(false);
        const Comparison c = compareImages(geometryShader, duplicated, Tolerance{1, 0.05, 0});
        EXPECT_TRUE(c.passed) << toString(model) << ": " << c.summary();
    }
}

TEST(SpecializationCache, SwitchingBackNeverRecompiles) {
    SHADELAB_REQUIRE_GL(renderer);
    renderer->setSpecialize(true);
    Scene a = litSphereScene(16, LightType::Point);
    Scene b = litSphereScene(16, LightType::Spot);
    renderer->render(a);
    renderer->render(b);
    const int built = renderer->programsBuilt();
    for (int i = 0; i < 5; ++i) {
        renderer->render(a);
        renderer->render(b);
    }
    EXPECT_EQ(renderer->programsBuilt(), built);
    a.lights.push_back(a.lights[0]); // two point lights: a new key
    renderer->render(a);
    EXPECT_EQ(renderer->programsBuilt(), built + 1);
}

TEST(SpecializationKey, LeavesOutWhatTheSceneDoesNotUse) {
    Scene scene = litSphereScene(16, LightType::Point);
    scene.lights[0].attenuation = {1, 0, 0};
    scene.lights[0].ambient = glm::dvec3(0);
    gl::ProgramVariant v = gl::ProgramVariant::forScene(scene, true);
    EXPECT_TRUE(v.specialized);
    EXPECT_EQ(v.point, 1);
    EXPECT_EQ(v.directional + v.spot, 0);
    EXPECT_FALSE(v.attenuation);
    EXPECT_FALSE(v.ambient);
    EXPECT_TRUE(v.specular);
    EXPECT_EQ(v.name(), "phong/blinn-phong+d0p1s0-ambient-attenuation");
    scene.objects[0].material.specular = glm::dvec3(0);
    EXPECT_FALSE(gl::ProgramVariant::forScene(scene, true).specular);
    const gl::ProgramVariant uber = gl::ProgramVariant::forScene(scene, false);
    EXPECT_FALSE(uber.specialized);
    EXPECT_EQ(uber.name(), "phong/blinn-phong");
    EXPECT_EQ(uber.defines().find("SPECIALIZED"), std::string::npos);
    EXPECT_NE(v.defines().find("#define NUM_POINT 1"), std::string::npos);
}

} // namespace
} // namespace shadelab::test
