// Scene files read (DESIGN §4) without GL: DESIGN's example is the defaults, each light type's defaults,
// every field read, one material read as the scene reads it, files on disk (missing, a folder, unreadable,
// too large: each named) and the matrices derived from a scene. Bad values: scene_check_test.cpp.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "input_error.h"
#include "scene/scene_test_support.h"
#include "shadelab/errors.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_file.h"

namespace shadelab {
namespace {

using namespace scene_test;

namespace fs = std::filesystem;

Light parseOneLight(const std::string& lightJson) {
    Scene scene = parseScene(R"({"lights": [)" + lightJson + "]}");
    EXPECT_EQ(scene.lights.size(), 1u);
    return scene.lights.at(0);
}

// ---- defaults ----

TEST(SceneDefaults, DesignExampleIsTheDefaults) {
    expectSameScene(parseScene(kDesignExample), Scene{});
}

TEST(SceneDefaults, EmptyObjectIsTheDefaults) {
    Scene scene = parseScene("{}");
    expectSameScene(scene, Scene{});
    ASSERT_EQ(scene.objects.size(), 1u);
    ASSERT_EQ(scene.lights.size(), 1u);
    expectSameLight(scene.lights[0], Scene::defaultLight());
}

TEST(SceneDefaults, DefaultLightIsTheDesignPointLight) {
    Light light = Scene::defaultLight();
    EXPECT_EQ(light.type, LightType::Point);
    EXPECT_EQ(light.position, glm::dvec3(3, 3, 5));
    EXPECT_EQ(light.ambient, glm::dvec3(0.1));
    EXPECT_EQ(light.diffuse, glm::dvec3(1));
    EXPECT_EQ(light.specular, glm::dvec3(1));
    EXPECT_EQ(light.attenuation, glm::dvec3(1, 0, 0));
}

TEST(SceneDefaults, EmptyArraysStayEmpty) {
    Scene scene = parseScene(R"({"objects": [], "lights": []})");
    EXPECT_TRUE(scene.objects.empty());
    EXPECT_TRUE(scene.lights.empty());
}

TEST(SceneDefaults, OmittedObjectAndMaterialFieldsTakeDefaults) {
    Scene scene = parseScene(R"({"objects": [{"radius": 2}, {"material": {"shininess": 8}}]})");
    ASSERT_EQ(scene.objects.size(), 2u);
    SceneObject expected;
    expected.radius = 2;
    expectSameObject(scene.objects[0], expected);
    expected = SceneObject{};
    expected.material.shininess = 8;
    expectSameObject(scene.objects[1], expected);
}

TEST(SceneDefaults, PointLightDefaults) {
    Light light = parseOneLight(R"({"type": "point", "position": [1, 2, 3]})");
    EXPECT_EQ(light.type, LightType::Point);
    EXPECT_EQ(light.position, glm::dvec3(1, 2, 3));
    EXPECT_EQ(light.ambient, glm::dvec3(0));
    EXPECT_EQ(light.diffuse, glm::dvec3(1));
    EXPECT_EQ(light.specular, glm::dvec3(1));
    EXPECT_EQ(light.attenuation, glm::dvec3(1, 0, 0));
    EXPECT_EQ(light.exponent, 0);
}

TEST(SceneDefaults, AmbientLightHasNoDiffuseOrSpecular) {
    Light light = parseOneLight(R"({"type": "ambient", "ambient": [0.2, 0.3, 0.4]})");
    EXPECT_EQ(light.type, LightType::Ambient);
    EXPECT_EQ(light.ambient, glm::dvec3(0.2, 0.3, 0.4));
    EXPECT_EQ(light.diffuse, glm::dvec3(0));
    EXPECT_EQ(light.specular, glm::dvec3(0));
    EXPECT_EQ(parseOneLight(R"({"type": "ambient"})").ambient, glm::dvec3(0));
}

TEST(SceneDefaults, DirectionalLightDefaults) {
    Light light = parseOneLight(R"({"type": "directional", "direction": [0, -1, 0]})");
    EXPECT_EQ(light.type, LightType::Directional);
    EXPECT_EQ(light.direction, glm::dvec3(0, -1, 0));
    EXPECT_EQ(light.ambient, glm::dvec3(0));
    EXPECT_EQ(light.diffuse, glm::dvec3(1));
    EXPECT_EQ(light.specular, glm::dvec3(1));
}

TEST(SceneDefaults, SpotLightDefaultsAndValues) {
    Light light = parseOneLight(
        R"({"type": "spot", "position": [0, 0, 5], "direction": [0, 0, -1], "cutoff_deg": 30})");
    EXPECT_EQ(light.type, LightType::Spot);
    EXPECT_EQ(light.cutoffDeg, 30);
    EXPECT_EQ(light.exponent, 0);
    EXPECT_EQ(light.attenuation, glm::dvec3(1, 0, 0));
    EXPECT_EQ(light.diffuse, glm::dvec3(1));
    light = parseOneLight(R"({"type": "spot", "position": [0, 0, 5], "direction": [0, 0, -1],
        "cutoff_deg": 90, "exponent": 8, "attenuation": [0, 0, 1], "specular": [0.5, 0.5, 0.5]})");
    EXPECT_EQ(light.cutoffDeg, 90);
    EXPECT_EQ(light.exponent, 8);
    EXPECT_EQ(light.attenuation, glm::dvec3(0, 0, 1));
    EXPECT_EQ(light.specular, glm::dvec3(0.5));
}

TEST(SceneDefaults, BoxProjectionPlanesDefaultToTheUnitSquare) {
    Scene scene = parseScene(R"({"projection": {"type": "orthographic", "left": -2, "near": 1, "far": 3}})");
    EXPECT_EQ(scene.projection.type, ProjectionType::Orthographic);
    EXPECT_EQ(scene.projection.left, -2);
    EXPECT_EQ(scene.projection.right, 1);
    EXPECT_EQ(scene.projection.bottom, -1);
    EXPECT_EQ(scene.projection.top, 1);
    EXPECT_EQ(scene.projection.near, 1);
    EXPECT_EQ(scene.projection.far, 3);
}

TEST(SceneParse, ReadsEveryField) {
    Scene scene = parseScene(R"({
      "image": {"width": 320, "height": 200, "background": [0.1, 0.2, 0.3]},
      "camera": {"eye": [1, 2, 3], "target": [0, 1, 0], "up": [0, 0, 1]},
      "projection": {"type": "frustum", "left": -0.5, "right": 0.5, "bottom": -0.25, "top": 0.25,
                     "near": 1, "far": 50},
      "shading": "toon", "lighting": "phong",
      "objects": [{"center": [1, 0, -1], "radius": 0.5, "scale": [2, -1, 1], "subdivisions": 0,
                   "material": {"ambient": [0, 0, 0], "diffuse": [1, 2, 3], "specular": [0, 0, 0],
                                "shininess": 1}}],
      "lights": [{"type": "ambient", "ambient": [0.5, 0.5, 0.5]},
                 {"type": "directional", "direction": [1, 1, 1], "diffuse": [2, 2, 2]}]
    })");
    EXPECT_EQ(scene.width, 320);
    EXPECT_EQ(scene.height, 200);
    EXPECT_EQ(scene.background, glm::dvec3(0.1, 0.2, 0.3));
    EXPECT_EQ(scene.eye, glm::dvec3(1, 2, 3));
    EXPECT_EQ(scene.target, glm::dvec3(0, 1, 0));
    EXPECT_EQ(scene.up, glm::dvec3(0, 0, 1));
    EXPECT_EQ(scene.projection.type, ProjectionType::Frustum);
    EXPECT_EQ(scene.projection.left, -0.5);
    EXPECT_EQ(scene.projection.top, 0.25);
    EXPECT_EQ(scene.projection.far, 50);
    EXPECT_EQ(scene.shading, ShadingMode::Toon);
    EXPECT_EQ(scene.lighting, LightingModel::Phong);
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].scale, glm::dvec3(2, -1, 1));
    EXPECT_EQ(scene.objects[0].subdivisions, 0);
    EXPECT_EQ(scene.objects[0].material.diffuse, glm::dvec3(1, 2, 3));
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[1].diffuse, glm::dvec3(2));
}

TEST(SceneParse, ProjectionTypeNames) {
    EXPECT_EQ(toString(ProjectionType::Perspective), "perspective");
    EXPECT_EQ(toString(ProjectionType::Frustum), "frustum");
    EXPECT_EQ(toString(ProjectionType::Orthographic), "orthographic");
}

TEST(SceneParse, ManyObjectsAreFine) {
    std::string json = R"({"objects": [)";
    for (int i = 0; i < 10000; ++i) json += (i ? ",{}" : "{}");
    EXPECT_EQ(parseScene(json + "]}").objects.size(), 10000u);
}

// parseMaterial (the page's material sliders) reads one material as parseScene reads it in a scene, with
// the same message at the object's place.
TEST(SceneMaterial, ReadsAsTheSceneReadsItAndNamesTheObjectsPlace) {
    const std::string material =
        R"({"ambient": [0.1, 0.2, 0.3], "diffuse": [0.4, 0.5, 0.6], "specular": [1, 1, 1], "shininess": 31.6})";
    const Scene scene = parseScene(R"({"objects": [{}, {"material": )" + material + "}]}");
    const Material parsed = parseMaterial(material, 1);
    EXPECT_EQ(parsed.ambient, scene.objects[1].material.ambient);
    EXPECT_EQ(parsed.diffuse, scene.objects[1].material.diffuse);
    EXPECT_EQ(parsed.specular, scene.objects[1].material.specular);
    EXPECT_EQ(parsed.shininess, 31.6);
    for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
             {R"({"shininess": 0.5})", "panel: objects[6].material.shininess: must be >= 1, got 0.5"},
             {R"({"shine": 2})", "panel: objects[6].material.shine: unknown key"},
             {R"({"diffuse": [1, 2]})", "panel: objects[6].material.diffuse: "},
             {"[]", "panel: objects[6].material: must be an object"}}) {
        try {
            parseMaterial(text, 6, "panel");
            ADD_FAILURE() << text << ": no error";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind(message, 0), 0u) << e.what();
        }
    }
}

// ---- files ----

class SceneFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "shadelab_scene_test.XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr) << "mkdtemp failed";
        dir_ = pattern;
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path write(const std::string& name, const std::string& text) {
        fs::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }

    std::string loadError(const fs::path& path) {
        const std::string message = test::inputErrorOf([&] { (void)loadScene(path); });
        if (message.empty()) ADD_FAILURE() << "no InputError for " << path;
        return message;
    }

    fs::path dir_;
};

TEST_F(SceneFileTest, LoadsAFile) {
    Scene scene = loadScene(write("scene.json", R"({"image": {"width": 64}})"));
    EXPECT_EQ(scene.width, 64);
}

TEST_F(SceneFileTest, ErrorsNameTheFile) {
    fs::path path = write("bad.json", R"({"shading": "phongg"})");
    EXPECT_TRUE(containsAll(loadError(path), {path.string() + ": shading: unknown value"}));
}

TEST_F(SceneFileTest, MissingFile) {
    fs::path path = dir_ / "missing.json";
    EXPECT_TRUE(containsAll(loadError(path), {path.string(), "cannot read scene file", "No such file"}));
}

TEST_F(SceneFileTest, Directory) {
    EXPECT_TRUE(containsAll(loadError(dir_), {dir_.string(), "cannot read scene file", "directory"}));
}

TEST_F(SceneFileTest, Unreadable) {
    fs::path path = write("secret.json", "{}");
    fs::permissions(path, fs::perms::none);
    if (::access(path.c_str(), R_OK) == 0) GTEST_SKIP() << "root reads any file (ReadError covers root)";
    EXPECT_TRUE(containsAll(loadError(path), {path.string(), "cannot read scene file", "ermission denied"}));
}

// A file that opens but cannot be read (reading /proc/self/mem at offset 0 fails with EIO), for any user.
TEST_F(SceneFileTest, ReadError) {
    EXPECT_TRUE(containsAll(loadError("/proc/self/mem"), {"/proc/self/mem", "cannot read scene file"}));
}

TEST_F(SceneFileTest, HugeFileIsRefused) {
    fs::path path = write("huge.json", "{" + std::string(17u << 20, ' ') + "}");
    EXPECT_TRUE(
        containsAll(loadError(path), {path.string(), "cannot read scene file", "larger than 16 MiB"}));
}

// ---- derived matrices ----

bool allFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

TEST(SceneView, Perspective) {
    Scene scene = parseScene(R"({"image": {"width": 1024, "height": 512},
        "camera": {"eye": [1, 2, 6], "target": [0, 0.5, 0], "up": [0, 1, 0]},
        "projection": {"fovy_deg": 50, "near": 0.25, "far": 40}})");
    SceneView view = sceneView(scene);
    EXPECT_FALSE(view.orthographic);
    EXPECT_EQ(view.viewFromWorld, viewFromWorld(cameraFrame(scene.eye, scene.target, scene.up)));
    ViewVolume expected = viewVolumeFromFovy(50, 2.0, 0.25, 40);
    EXPECT_EQ(view.volume.left, expected.left);
    EXPECT_EQ(view.volume.right, expected.right);
    EXPECT_EQ(view.volume.top, expected.top);
    EXPECT_EQ(view.volume.near, 0.25);
    EXPECT_EQ(view.volume.far, 40);
    EXPECT_NEAR(view.volume.right, 2 * view.volume.top, 1e-15);
    EXPECT_EQ(view.clipFromView, perspectiveClipFromView(expected));
    EXPECT_TRUE(allFinite(view.viewFromWorld));
    EXPECT_TRUE(allFinite(view.clipFromView));
}

// "perspective_matrix": "unnegated" is the WebGL matrix times −1 (the lecture's matrix before its −1): a
// point in front of the eye gets w = z < 0 and fails the clipper's w > 0, where the WebGL matrix gives it
// w = −z > 0. Orthographic: unchanged.
TEST(SceneView, UnnegatedPerspectiveMatrixPutsEveryPointInFrontAtNegativeW) {
    for (const char* projection : {R"({"fovy_deg": 50, "near": 0.25, "far": 40})",
                                   R"({"type": "frustum", "left": -0.3, "right": 0.1, "bottom": -0.2,
                                       "top": 0.4, "near": 0.5, "far": 9})"}) {
        Scene scene = parseScene(std::string(R"({"projection": )") + projection + "}");
        const SceneView webgl = sceneView(scene);
        scene.perspectiveMatrix = PerspectiveMatrix::Unnegated;
        const SceneView unnegated = sceneView(scene);
        EXPECT_EQ(unnegated.clipFromView, -webgl.clipFromView) << projection;
        for (const glm::dvec3 p : {glm::dvec3(0, 0, -1), glm::dvec3(0.1, -0.2, -5), glm::dvec3(3, 1, -30)}) {
            EXPECT_TRUE(webgl.passesW(p));
            EXPECT_FALSE(unnegated.passesW(p));
            EXPECT_EQ((unnegated.clipFromView * glm::dvec4(p, 1)).w, p.z) << "w = z before the -1";
        }
    }
    Scene ortho =
        parseScene(R"({"projection": {"type": "orthographic", "left": -2, "right": 2, "bottom": -1.5,
        "top": 1.5, "near": 1, "far": 7}})");
    const glm::dmat4 webgl = sceneView(ortho).clipFromView;
    ortho.perspectiveMatrix = PerspectiveMatrix::Unnegated;
    EXPECT_EQ(sceneView(ortho).clipFromView, webgl);
}

TEST(SceneView, Frustum) {
    Scene scene = parseScene(R"({"projection": {"type": "frustum", "left": -0.3, "right": 0.1,
        "bottom": -0.2, "top": 0.4, "near": 0.5, "far": 9}})");
    SceneView view = sceneView(scene);
    EXPECT_FALSE(view.orthographic);
    ViewVolume expected{-0.3, 0.1, -0.2, 0.4, 0.5, 9};
    EXPECT_EQ(view.volume.left, expected.left);
    EXPECT_EQ(view.volume.bottom, expected.bottom);
    EXPECT_EQ(view.clipFromView, perspectiveClipFromView(expected));
    EXPECT_TRUE(allFinite(view.clipFromView));
}

TEST(SceneView, Orthographic) {
    Scene scene = parseScene(R"({"projection": {"type": "orthographic", "left": -2, "right": 2,
        "bottom": -1.5, "top": 1.5, "near": 1, "far": 7}})");
    SceneView view = sceneView(scene);
    EXPECT_TRUE(view.orthographic);
    ViewVolume expected{-2, 2, -1.5, 1.5, 1, 7};
    EXPECT_EQ(view.volume.top, expected.top);
    EXPECT_EQ(view.clipFromView, orthographicClipFromView(expected));
    EXPECT_TRUE(allFinite(view.clipFromView));
}

TEST(SceneView, DegenerateCameraIsAnInputError) {
    Scene scene;
    scene.up = glm::dvec3(0, 0, 1); // parallel to the default view direction (0, 0, -1)
    try {
        sceneView(scene);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("camera: ", 0), 0u) << e.what();
    }
}

TEST(SceneView, WorldFromObjectScalesThenTranslates) {
    SceneObject object;
    object.center = {1, 2, 3};
    object.radius = 2;
    object.scale = {1, -0.5, 3};
    glm::dmat4 m = worldFromObject(object);
    EXPECT_EQ(glm::dvec3(m * glm::dvec4(0, 0, 0, 1)), glm::dvec3(1, 2, 3));
    EXPECT_EQ(glm::dvec3(m * glm::dvec4(1, 0, 0, 1)), glm::dvec3(1 + 2 * 1, 2, 3));
    EXPECT_EQ(glm::dvec3(m * glm::dvec4(0, 1, 0, 1)), glm::dvec3(1, 2 + 2 * -0.5, 3));
    EXPECT_EQ(glm::dvec3(m * glm::dvec4(0, 0, 1, 1)), glm::dvec3(1, 2, 3 + 2 * 3));
}

} // namespace
} // namespace shadelab
