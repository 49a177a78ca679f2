// Scene-specialized programs against the uber program: the same equation with absent terms left out
// (and, with values compiled in, the same floats as constants), so on every scene the pictures agree
// within 1/255 (float sums in another order), and programs are cached by their key.
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>

#include "gl/gl_test_support.h"
#include "shadelab/errors.h"
#include "shadelab/gl/program.h"
#include "shadelab/io/text.h"
#include "tolerances.h"

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
            renderer->setSpecialization(gl::Specialization::None);
            const Image uber = renderer->render(scene);
            for (const auto& [specialization, label] : kSpecializationLabels) {
                if (specialization == gl::Specialization::None) continue;
                renderer->setSpecialization(specialization);
                const Image specialized = renderer->render(scene);
                // Every pixel within 1/255, toon bands included: no outlier budget.
                const Comparison c = compareImages(specialized, uber, kSamePictureTwoWays);
                EXPECT_TRUE(c.passed)
                    << toString(mode) << "/" << toString(model) << " " << label << ": " << c.summary();
            }
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
        const Comparison c = compareImages(geometryShader, duplicated, kSamePictureTwoWays);
        EXPECT_TRUE(c.passed) << toString(model) << ": " << c.summary();
    }
}

// The renderer resolves each object's program and mesh once per scene (Renderer::drawPlan) and sets an
// object's light values only when its material differs from the object drawn before it with the same
// program. So: a sequence of frames, each changing one thing (a material, a light's colour, the camera,
// the middle one of three objects in a row, a level), drawn with each specialization, must give each
// frame's own picture — the uber program's of that scene, drawn afterwards, within 1/255. A plan kept past
// a change, or light values left from another object, shows as that frame's old colours.
TEST(SpecializationCache, EveryChangeBetweenFramesIsDrawn) {
    SHADELAB_REQUIRE_GL(renderer);
    std::vector<Scene> frames;
    Scene scene = litSphereScene(64, LightType::Point);
    scene.shading = ShadingMode::Phong;
    scene.objects[0].radius = 0.45;
    scene.objects[0].subdivisions = 3;
    for (double x : {-1.0, 0.0, 1.0}) { // three objects of one material in a row
        SceneObject object = scene.objects[0];
        object.center = {x, 0, 0};
        scene.objects.push_back(object);
    }
    scene.objects.erase(scene.objects.begin());
    frames.push_back(scene);
    scene.objects[1].material.diffuse = {0.1, 0.9, 0.2}; // the middle one alone
    frames.push_back(scene);
    scene.objects[1].material.diffuse = scene.objects[0].material.diffuse; // back to the frame before
    frames.push_back(scene);
    scene.lights[0].diffuse = {1, 0.3, 0.3};
    frames.push_back(scene);
    scene.eye = {1, 1, 4};
    frames.push_back(scene);
    scene.objects[2].subdivisions = 0;
    frames.push_back(scene);
    scene.objects[0].material.shininess = 3;
    frames.push_back(scene);
    for (const auto& [specialization, label] : kSpecializationLabels) {
        if (specialization == gl::Specialization::None) continue;
        std::vector<Image> drawn;
        renderer->setSpecialization(specialization);
        for (const Scene& frame : frames) drawn.push_back(renderer->render(frame));
        renderer->setSpecialization(gl::Specialization::None);
        for (std::size_t i = 0; i < frames.size(); ++i) {
            const Comparison c = compareImages(drawn[i], renderer->render(frames[i]), kSamePictureTwoWays);
            EXPECT_TRUE(c.passed) << label << ", frame " << i << ": " << c.summary();
            if (i > 0) {
                EXPECT_FALSE(compareImages(drawn[i], drawn[i - 1], kIdentical).passed)
                    << label << ", frame " << i << " drew the frame before's picture";
            }
        }
    }
    renderer->setSpecialization(gl::Specialization::Values);
}

TEST(SpecializationCache, SwitchingBackNeverRecompiles) {
    SHADELAB_REQUIRE_GL(renderer);
    renderer->setSpecialization(gl::Specialization::Lights);
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
    // A colour or the shininess is a uniform of a program specialized to the lights: nothing to build.
    a.objects[0].material.shininess = 7;
    a.lights[0].diffuse = {0.5, 0.25, 1};
    renderer->render(a);
    EXPECT_EQ(renderer->programsBuilt(), built + 1);
    renderer->setSpecialization(gl::Specialization::Values);
}

// With values compiled in, a program is built per distinct set of values — two objects of one material
// share theirs — and switching back to values seen before builds nothing.
TEST(SpecializationCache, ValuesBuildAProgramPerDistinctMaterial) {
    SHADELAB_REQUIRE_GL(renderer);
    renderer->setSpecialization(gl::Specialization::Values);
    Scene scene = litSphereScene(16, LightType::Point);
    scene.shading = ShadingMode::Gouraud; // a variant no other test of this process builds
    scene.lighting = LightingModel::Phong;
    scene.objects.push_back(scene.objects[0]);
    scene.objects[1].center = {0.5, 0, -1};
    const int before = renderer->programsBuilt();
    renderer->render(scene);
    EXPECT_EQ(renderer->programsBuilt(), before + 1) << "two objects of one material";
    scene.objects[1].material.shininess = 5;
    renderer->render(scene);
    EXPECT_EQ(renderer->programsBuilt(), before + 2) << "a second material";
    for (int i = 0; i < 3; ++i) renderer->render(scene);
    scene.objects[1].material.shininess = scene.objects[0].material.shininess;
    renderer->render(scene);
    EXPECT_EQ(renderer->programsBuilt(), before + 2) << "values seen before";
}

// The constants shaders/lighting.glsl shares with src/shading/lighting.cpp come from C++, each read back as
// C++'s value rounded to float, in every variant.
TEST(SpecializationKey, DefinesCarryLightingsConstants) {
    auto valueOf = [](const std::string& defines, const std::string& name) {
        const std::string key = "#define " + name + " ";
        const std::size_t at = defines.find(key);
        if (at == std::string::npos) return std::nan("");
        return double(std::strtof(defines.c_str() + at + key.size(), nullptr));
    };
    for (const bool specialize : {false, true}) {
        const std::string defines =
            gl::ProgramVariant::forScene(litSphereScene(16, LightType::Spot), specialize).defines();
        EXPECT_EQ(valueOf(defines, "TINY_COMPONENT"), double(float(kTinyComponent)));
        EXPECT_EQ(valueOf(defines, "MIN_ATTENUATION_DENOMINATOR"), double(float(kMinAttenuationDenominator)));
        EXPECT_EQ(valueOf(defines, "MIN_LENGTH_SQUARED"), double(float(kMinLengthSquared)));
        EXPECT_EQ(valueOf(defines, "TOON_HIGHLIGHT"), double(float(kToonHighlight)));
        EXPECT_EQ(valueOf(defines, "MAX_LIGHTS"), kMaxLights);
        for (const LightType type : kLightTypes)
            EXPECT_EQ(valueOf(defines, "LIGHT_" + upperAscii(toString(type))), int(type)) << toString(type);
    }
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

// Every number withValues compiles in reads back as the float the uniform would have carried: 0.1 and
// 0.7 are not floats, 1e18 is the colour cap, 1/3 the toon band width of three bands.
TEST(SpecializationKey, ValuesReadBackAsTheUniformsFloats) {
    Scene scene = litSphereScene(16, LightType::Spot);
    scene.shading = ShadingMode::Toon;
    scene.toonBands = 3;
    Material& m = scene.objects[0].material;
    m.ambient = {0.1, 0.2, 0.3};
    m.diffuse = {0.7, 1e30, 0};
    m.shininess = 33.3;
    scene.lights[0].ambient = {0.05, 0, 1};
    scene.lights[0].attenuation = {0.5, 0.1, 0.02};
    const gl::ProgramVariant v = gl::ProgramVariant::forScene(scene, true).withValues(scene, m);
    EXPECT_EQ(v.name(), "toon/blinn-phong+d0p0s1+values");
    const LightValues l = lightValues(scene.lights[0], m);
    const glm::vec3 ambient = ambientProduct(scene.lights, m);
    const std::vector<float> expected = {
        float(m.shininess),  ambient.x,           ambient.y,          ambient.z,          3.0f,
        float(1.0 / 3),      l.diffuseProduct.x,  l.diffuseProduct.y, l.diffuseProduct.z, l.specularProduct.x,
        l.specularProduct.y, l.specularProduct.z, l.attenuation.x,    l.attenuation.y,    l.attenuation.z,
        l.cosCutoff,         l.exponent};
    EXPECT_EQ(l.diffuseProduct.y, 1e18f) << "capped";
    // The numbers of the values' lines, in order (VALUES_COMPILED_IN has none; vec3 and LightValues are
    // words).
    std::vector<float> read;
    const std::string text = v.values;
    for (std::size_t i = 0; i < text.size();) {
        const bool startsNumber = std::isdigit(static_cast<unsigned char>(text[i])) &&
                                  (i == 0 || !std::isalnum(static_cast<unsigned char>(text[i - 1])));
        if (!startsNumber) {
            ++i;
            continue;
        }
        std::size_t used = 0;
        read.push_back(std::stof(text.substr(i), &used));
        i += used;
    }
    ASSERT_EQ(read.size(), expected.size()) << text;
    for (std::size_t i = 0; i < read.size(); ++i)
        EXPECT_EQ(read[i], expected[i]) << "number " << i << " of\n" << text;
    EXPECT_EQ(gl::ProgramVariant::forScene(scene, false).withValues(scene, m).values, "") << "uber: none";
}

} // namespace
} // namespace shadelab::test
