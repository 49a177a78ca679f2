// Scenes written (DESIGN §4): what the demo saves beside a screenshot reads back as the same scene, every
// field exactly; the toon bands read and range-checked; saveScene writes a file that loads back and leaves
// no temporary file.
#include <filesystem>
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "scene/scene_test_support.h"
#include "shadelab/errors.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_file.h"

namespace shadelab {
namespace {

using namespace scene_test;

// ---- serialization: what the demo saves beside a screenshot must render the same picture ----

namespace {

// The serializer writes only the projection fields its type reads; the others come back as defaults.
void expectRoundTripped(shadelab::Scene a, const shadelab::Scene& b) {
    const shadelab::Projection defaults;
    if (a.projection.type == shadelab::ProjectionType::Perspective) {
        a.projection.left = defaults.left;
        a.projection.right = defaults.right;
        a.projection.bottom = defaults.bottom;
        a.projection.top = defaults.top;
    } else {
        a.projection.fovyDeg = defaults.fovyDeg;
    }
    expectSameScene(a, b);
}

} // namespace

TEST(SceneJson, RoundTripsEveryFieldExactly) {
    using namespace shadelab;
    Scene scene;
    scene.width = 321;
    scene.height = 123;
    scene.background = {0.1, 1.0 / 3, 0.7};
    scene.eye = {0.3, -2.0 / 7, 5.5};
    scene.up = {0.1, 1, 0};
    scene.projection = {ProjectionType::Frustum, 40, -0.3, 0.2, -0.1, 0.25, 0.123456789, 99.5};
    scene.shading = ShadingMode::Toon;
    scene.lighting = LightingModel::Phong;
    scene.term = LightingTerm::Specular;
    scene.toonBands = 7;
    scene.tolerancePx = 0.25;
    scene.depth = DepthMode::ReversedInfinite;
    scene.vertexNormals = VertexNormals::Exact;
    scene.normalMatrix = NormalMatrixRule::Model;
    scene.perspectiveMatrix = PerspectiveMatrix::Unnegated;
    scene.view.kind = ViewKind::Outside;
    scene.view.observer = {-123.25, 1.0 / 3, 0.75};
    SceneObject ellipsoid;
    ellipsoid.center = {1e-7, 2, -3};
    ellipsoid.scale = {-1.5, 0.25, 3};
    ellipsoid.subdivisions = 2;
    ellipsoid.material.shininess = 123.456;
    scene.objects.push_back(ellipsoid);
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {1, 2, 3};
    spot.direction = {-1, -2, -3};
    spot.cutoffDeg = 17.5;
    spot.exponent = 3;
    spot.attenuation = {0.5, 0.25, 0.125};
    Light ambient;
    ambient.type = LightType::Ambient;
    ambient.ambient = {0.2, 0.2, 0.3};
    ambient.diffuse = ambient.specular = glm::dvec3(0);
    Light directional;
    directional.type = LightType::Directional;
    directional.direction = {0, -1, 0};
    scene.lights = {Scene::defaultLight(), spot, ambient, directional};
    expectRoundTripped(scene, parseScene(sceneToJson(scene), "round-trip"));
    for (ProjectionType type : {ProjectionType::Perspective, ProjectionType::Orthographic}) {
        scene.projection.type = type;
        expectRoundTripped(scene, parseScene(sceneToJson(scene), "round-trip"));
    }
}

TEST(SceneJson, ToonBandsAreReadAndRangeChecked) {
    using namespace shadelab;
    EXPECT_EQ(parseScene(R"({"toon_bands": 6})").toonBands, 6);
    EXPECT_EQ(parseScene("{}").toonBands, kToonBands);
    for (const char* bad : {R"({"toon_bands": 1})", R"({"toon_bands": 17})", R"({"toon_bands": 2.5})"}) {
        try {
            parseScene(bad, "s.json");
            ADD_FAILURE() << bad << " was accepted";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("s.json: toon_bands"), std::string::npos) << e.what();
        }
    }
}

TEST(SceneJson, SaveSceneWritesAFileThatLoadsBack) {
    using namespace shadelab;
    const auto dir =
        std::filesystem::temp_directory_path() / ("shadelab-scene-save-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    Scene scene;
    scene.shading = ShadingMode::Gouraud;
    saveScene(scene, dir / "s.json");
    EXPECT_EQ(loadScene(dir / "s.json").shading, ShadingMode::Gouraud);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1); // no temporary file left
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace shadelab
