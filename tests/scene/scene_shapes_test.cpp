// An object's shape in a scene file (DESIGN §4): "shape" (sphere, teapot), "mesh" (a model file) and
// "closed" read, refused with the path, the value and the fix, written back by sceneToJson; the work limits
// counting a teapot's and a mesh's triangles and reference rays; the teapot's "auto" level; --subdivisions
// and a split's @level within the teapot's range.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "input_error.h"
#include "scene/scene_test_support.h"
#include "shadelab/errors.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/geometry/teapot.h"
#include "shadelab/scene/auto_level.h"
#include "shadelab/scene/model.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_flags.h"
#include "shadelab/scene/scene_values.h"

namespace shadelab {
namespace {

using namespace scene_test;

std::string objects(const std::string& body) {
    return R"({"objects": [)" + body + "]}";
}

std::string parseError(const std::string& json) {
    const std::string message = test::inputErrorOf([&] { (void)parseScene(json, "scene.json"); });
    if (message.empty()) ADD_FAILURE() << "no InputError for: " << json;
    return message;
}

// Every piece in `message`, each reported on its own.
void expectPieces(const std::string& message, const std::vector<std::string>& pieces) {
    for (const std::string& piece : pieces)
        EXPECT_NE(message.find(piece), std::string::npos) << "\"" << piece << "\" missing from: " << message;
}

// A model of `triangles` triangles (all the limits read of it), as loadSceneModels would attach it.
std::shared_ptr<const Model> modelOf(std::size_t triangles) {
    auto model = std::make_shared<Model>();
    model->path = "models/thing.obj";
    model->mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    model->mesh.triangles.assign(triangles, glm::uvec3(0, 1, 2));
    return model;
}

SceneObject meshObject(std::shared_ptr<const Model> model) {
    SceneObject object;
    object.shape = Shape::Mesh;
    object.mesh = "models/thing.obj";
    object.model = std::move(model);
    return object;
}

SceneObject teapot(int level) {
    SceneObject object;
    object.shape = Shape::Teapot;
    object.subdivisions = level;
    return object;
}

// ---- reading ----

TEST(SceneShapes, ShapeDefaultsToTheSphereAndReadsTheTeapot) {
    const Scene plain = parseScene(objects("{}"));
    EXPECT_EQ(plain.objects[0].shape, Shape::Sphere);
    EXPECT_TRUE(plain.objects[0].materialGiven);
    const Scene scene = parseScene(objects(R"({"shape": "sphere", "subdivisions": 10},
        {"shape": "teapot", "subdivisions": 8}, {"shape": "teapot", "subdivisions": "auto"})"));
    EXPECT_EQ(scene.objects[0].shape, Shape::Sphere);
    EXPECT_EQ(scene.objects[0].subdivisions, 10);
    EXPECT_EQ(scene.objects[1].shape, Shape::Teapot);
    EXPECT_EQ(scene.objects[1].subdivisions, 8);
    EXPECT_EQ(scene.objects[2].subdivisions, kAutoSubdivisions);
    EXPECT_TRUE(scene.objects[1].materialGiven) << "a teapot writes its default material back";
}

TEST(SceneShapes, MeshReadsTheFileClosedAndWhetherAMaterialWasGiven) {
    const Scene scene = parseScene(objects(R"({"mesh": "models/thing.obj", "center": [1, 2, 3]},
        {"mesh": "thing.glb", "closed": true, "material": {"shininess": 7}})"));
    const SceneObject& open = scene.objects[0];
    EXPECT_EQ(open.shape, Shape::Mesh);
    EXPECT_EQ(open.mesh, "models/thing.obj");
    EXPECT_EQ(open.center, glm::dvec3(1, 2, 3));
    EXPECT_FALSE(open.closed);
    EXPECT_FALSE(open.materialGiven) << "the file's material is taken when the scene gives none";
    EXPECT_EQ(open.model, nullptr) << "parsing reads no file";
    EXPECT_FALSE(isClosed(open));
    const SceneObject& closed = scene.objects[1];
    EXPECT_TRUE(closed.closed);
    EXPECT_TRUE(closed.materialGiven);
    EXPECT_EQ(closed.material.shininess, 7);
    EXPECT_TRUE(isClosed(closed));
}

struct Refusal {
    const char* name;
    std::string json;
    std::vector<std::string> pieces; // the path, the value where there is one, the fix
};

inline void PrintTo(const Refusal& r, std::ostream* os) {
    *os << r.name;
}

const std::vector<Refusal> kRefusals = {
    {"SubdivisionsBesideMesh",
     objects(R"({}, {"mesh": "a.obj", "subdivisions": 3})"),
     {"scene.json: objects[1].subdivisions: does not apply to a \"mesh\" object (its triangles are the "
      "file's); remove it"}},
    {"ShapeBesideMesh",
     objects(R"({"mesh": "a.obj", "shape": "teapot"})"),
     {"objects[0].shape: does not apply to a \"mesh\" object", "remove it"}},
    {"ClosedOnTheSphere",
     objects(R"({"closed": true})"),
     {"objects[0].closed: applies only to a \"mesh\"", "remove it"}},
    {"ClosedOnTheTeapot",
     objects(R"({"shape": "teapot", "closed": false})"),
     {"objects[0].closed: applies only to a \"mesh\"", "the teapot is open"}},
    {"ClosedNotABoolean",
     objects(R"({"mesh": "a.obj", "closed": 1})"),
     {"objects[0].closed: must be true or false, got number 1"}},
    {"ShapeUnknown",
     objects(R"({"shape": "cube"})"),
     {"objects[0].shape: unknown value \"cube\"; expected one of sphere, teapot"}},
    {"ShapeMeshIsAKeyNotAShape",
     objects(R"({"shape": "mesh"})"),
     {"objects[0].shape: unknown value \"mesh\"", "sphere, teapot", "\"mesh\": \"models/thing.obj\""}},
    {"ShapeNotAString", objects(R"({"shape": 1})"), {"objects[0].shape: must be a string, got number 1"}},
    {"MeshEmpty",
     objects(R"({"mesh": ""})"),
     {"objects[0].mesh: must be a file name", "got an empty string"}},
    {"MeshNotAString", objects(R"({"mesh": ["a.obj"]})"), {"objects[0].mesh: must be a file name", "array"}},
    {"MeshAbsolute",
     objects(R"({"mesh": "/etc/a.obj"})"),
     {"objects[0].mesh: must be relative to the scene file's folder", "\"/etc/a.obj\"", "models/thing.obj"}},
    {"MeshWithNul", objects(R"({"mesh": "a\u0000.obj"})"), {"objects[0].mesh: ", "NUL"}},
    {"TeapotAboveItsLevels",
     objects(R"({"shape": "teapot", "subdivisions": 9})"),
     {"objects[0].subdivisions: must be between 0 and 8, got 9"}},
    {"TeapotWordNotAuto",
     objects(R"({"shape": "teapot", "subdivisions": "fine"})"),
     {"objects[0].subdivisions: must be a level 0..8 or \"auto\", got string \"fine\""}},
    {"UnknownKeyListsTheNewOnes",
     objects(R"({"shpae": "teapot"})"),
     {"objects[0].shpae: unknown key; expected one of center, radius, scale, subdivisions, material, shape, "
      "mesh, closed"}},
};

class SceneShapeRefusal : public testing::TestWithParam<Refusal> {};

TEST_P(SceneShapeRefusal, NamesThePathTheValueAndTheFix) {
    expectPieces(parseError(GetParam().json), GetParam().pieces);
}

INSTANTIATE_TEST_SUITE_P(Table, SceneShapeRefusal, testing::ValuesIn(kRefusals),
                         [](const testing::TestParamInfo<Refusal>& info) { return info.param.name; });

TEST(SceneShapes, TheSphereKeepsItsLevelsAboveTheTeapots) {
    EXPECT_NO_THROW((void)parseScene(objects(R"({"subdivisions": 9})")));
    EXPECT_NO_THROW((void)parseScene(objects(R"({"shape": "sphere", "subdivisions": 10})")));
}

// ---- writing back ----

TEST(SceneShapes, RoundTripsEveryShape) {
    Scene scene = parseScene(objects(R"({"shape": "teapot", "subdivisions": 3, "radius": 0.5},
        {"shape": "teapot", "subdivisions": "auto"},
        {"mesh": "models/thing.obj"},
        {"mesh": "models/thing.obj", "closed": true, "material": {"diffuse": [0, 1, 0]}},
        {"subdivisions": 2})"));
    EXPECT_NO_THROW(validateSceneValues(scene)) << "what parseScene accepts, the values' check does";
    const std::string text = sceneToJson(scene);
    EXPECT_EQ(parseScene(text, "round-trip"), scene) << text;
    // A mesh object's material is the file's unless the scene gave one: written only then.
    const nlohmann::json tree = nlohmann::json::parse(text);
    const nlohmann::json& written = tree.at("objects");
    EXPECT_EQ(written[0].at("shape"), "teapot");
    EXPECT_FALSE(written[2].contains("material"));
    EXPECT_FALSE(written[2].contains("shape"));
    EXPECT_FALSE(written[2].contains("subdivisions"));
    EXPECT_EQ(written[2].at("closed"), false);
    EXPECT_TRUE(written[3].contains("material"));
    EXPECT_FALSE(written[4].contains("shape")) << "a sphere is written as before shapes existed";
}

// Scenes saved before shapes existed (the demo's screenshots, the references' JSON) read the same, and a
// sphere-only scene is written with exactly the keys it had.
TEST(SceneShapes, ASphereIsWrittenWithItsOldKeys) {
    const nlohmann::json object = nlohmann::json::parse(sceneToJson(Scene{})).at("objects").at(0);
    std::vector<std::string> keys;
    for (auto it = object.begin(); it != object.end(); ++it) keys.push_back(it.key());
    EXPECT_EQ(keys, (std::vector<std::string>{"center", "material", "radius", "scale", "subdivisions"}));
}

// ---- limits ----

TEST(SceneShapes, AMeshNotLoadedIsRefusedByTheLimitsNotByTheValues) {
    const Scene scene = parseScene(objects(R"({}, {"mesh": "models/thing.obj"})"), "scene.json");
    EXPECT_NO_THROW(validateSceneValues(scene)) << "parse-only uses (the fuzzer) read no file";
    expectPieces(test::inputErrorOf([&] { validateScene(scene); }),
                 {"objects[1].mesh: \"models/thing.obj\" is not loaded", "loadSceneModels"});
    Scene loaded = scene;
    loaded.objects[1].model = modelOf(12);
    EXPECT_NO_THROW(validateScene(loaded));
}

TEST(SceneShapes, TrianglesPerFrameCountTheTeapotsOwn) {
    const std::size_t perTeapot = teapotTriangleCount(kMaxTeapotLevel);
    const std::size_t fit = kMaxTrianglesPerFrame / perTeapot;
    Scene scene;
    scene.width = scene.height = 16;
    scene.objects.assign(fit, teapot(kMaxTeapotLevel));
    EXPECT_NO_THROW(validateScene(scene)) << fit << " teapots of " << perTeapot;
    scene.objects.push_back(teapot(kMaxTeapotLevel));
    expectPieces(
        test::inputErrorOf([&] { validateScene(scene); }),
        {"objects: the scene draws " + std::to_string((fit + 1) * perTeapot) + " triangles per frame",
         "teapot"});
}

TEST(SceneShapes, TrianglesPerFrameCountTheMeshsFileAndBothSidesOfASplit) {
    constexpr std::size_t kTriangles = std::size_t(1) << 20;
    const auto model = modelOf(kTriangles); // shared, as loadSceneModels shares one file's model
    Scene scene;
    scene.width = scene.height = 16;
    scene.objects.assign(kMaxTrianglesPerFrame / kTriangles, meshObject(model));
    EXPECT_NO_THROW(validateScene(scene));
    scene.objects.push_back(meshObject(model));
    expectPieces(test::inputErrorOf([&] { validateScene(scene); }),
                 {"objects: the scene draws " + std::to_string(kMaxTrianglesPerFrame + kTriangles)});
    scene.objects.resize(kMaxTrianglesPerFrame / kTriangles / 2 + 1);
    EXPECT_NO_THROW(validateScene(scene));
    scene.view = parseViewOrThrow("split:phong@2,gouraud@3", "view"); // a mesh has no level: drawn twice
    expectPieces(test::inputErrorOf([&] { validateScene(scene); }), {"view: the scene draws", "split"});
}

// The reference's rays: a sphere one test per pixel, a teapot 256, a mesh 6·⌈log₂ T⌉ (its tree's walk).
TEST(SceneShapes, ReferenceRayTestsWeighATeapotAndAMeshByTheirCost) {
    Scene scene;
    scene.width = scene.height = 4096; // 2^24 pixels: 256 tests per pixel reach the 2^32 budget
    scene.objects = {teapot(0)};
    EXPECT_NO_THROW(checkSceneLimits(scene)); // 256: exactly the budget
    scene.objects.push_back(SceneObject{});
    scene.objects[1].subdivisions = 0;
    expectPieces(test::inputErrorOf([&] { checkSceneLimits(scene); }),
                 {"objects: the analytic reference would test", "a teapot 256 times, a mesh 6 x log2"});
    const SceneObject mesh = meshObject(modelOf(std::size_t(1) << 15)); // 6 · 15 = 90 per pixel
    scene.objects = {mesh, mesh};                                       // 180
    EXPECT_NO_THROW(checkSceneLimits(scene));
    scene.objects.push_back(mesh); // 270 > 256
    EXPECT_THROW(checkSceneLimits(scene), InputError);
}

// ---- the teapot's "auto" level ----

TEST(SceneShapes, TheTeapotsBoundingRadiusHoldsItsSurface) {
    const double bound = teapotBoundingRadius();
    double largest = 0;
    for (const TeapotPatch& patch : teapotPatches())
        for (int i = 0; i <= 16; ++i)
            for (int j = 0; j <= 16; ++j)
                largest = std::max(largest, glm::length(evaluatePatch(patch, i / 16.0, j / 16.0).position));
    EXPECT_LE(largest, bound);
    EXPECT_GT(largest, 0.95 * bound) << "a bound, but a tight one (the spout's tip is a control point)";
    EXPECT_EQ(boundingRadius(teapot(3)), bound);
    EXPECT_EQ(boundingRadius(SceneObject{}), 1.0);
    SceneObject mesh = meshObject(modelOf(1));
    EXPECT_EQ(boundingRadius(mesh), 1.0);
    auto far = std::make_shared<Model>(*modelOf(1));
    far->mesh.positions[1] = {0, 3, 4};
    mesh.model = far;
    EXPECT_EQ(boundingRadius(mesh), 5.0);
}

TEST(SceneShapes, TeapotAutoLevelMeetsTheToleranceAndGrowsWithSize) {
    Scene scene;
    scene.projection.type = ProjectionType::Orthographic; // no slant: the bound is R_px·error/B exactly
    SceneObject object = teapot(kAutoSubdivisions);
    int previous = 0;
    bool reachedTop = false;
    for (double radius = 1e-4; radius < 1e4; radius *= 1.5) {
        object.radius = radius;
        const int level = autoSubdivisionLevel(scene, object);
        EXPECT_GE(level, previous) << "radius " << radius;
        EXPECT_GE(level, 0);
        EXPECT_LE(level, kMaxTeapotLevel);
        const double pixelsPerUnit = projectedRadiusPx(scene, object) / teapotBoundingRadius();
        if (level < kMaxTeapotLevel) {
            EXPECT_LE(teapotMeshError(level) * pixelsPerUnit, scene.tolerancePx) << "radius " << radius;
        }
        if (level > 0) {
            EXPECT_GT(teapotMeshError(level - 1) * pixelsPerUnit, scene.tolerancePx) << "the smallest";
        }
        reachedTop = reachedTop || level == kMaxTeapotLevel;
        previous = level;
    }
    EXPECT_TRUE(reachedTop);
    EXPECT_EQ(subdivisionLevel(scene, object), autoSubdivisionLevel(scene, object));
    scene.projection.type = ProjectionType::Perspective;
    object.radius = 1;
    object.center = scene.eye; // the eye inside: the finest level the teapot has
    EXPECT_EQ(autoSubdivisionLevel(scene, object), kMaxTeapotLevel);
}

TEST(SceneShapes, AMeshHasNoLevel) {
    const Scene scene;
    SceneObject mesh = meshObject(modelOf(1));
    mesh.subdivisions = kAutoSubdivisions;
    EXPECT_EQ(autoSubdivisionLevel(scene, mesh), 0);
    mesh.subdivisions = 7;
    EXPECT_EQ(subdivisionLevel(scene, mesh), 0);
}

// ---- flags and split levels ----

TEST(SceneShapes, SubdivisionsFlagStaysWithinTheTeapotsLevelsAndLeavesMeshesAlone) {
    Scene scene = parseScene(objects(R"({}, {"shape": "teapot"}, {"mesh": "a.obj"})"));
    scene.objects[2].model = modelOf(4);
    SceneOverrides overrides;
    overrides.subdivisions = "9";
    expectPieces(test::inputErrorOf([&] { (void)applyOverrides(scene, overrides, ""); }),
                 {"--subdivisions: must be between 0 and 8, got 9", "objects[1] is a teapot"});
    overrides.subdivisions = "8";
    const Scene eight = applyOverrides(scene, overrides, "");
    EXPECT_EQ(eight.objects[0].subdivisions, 8);
    EXPECT_EQ(eight.objects[1].subdivisions, 8);
    EXPECT_EQ(eight.objects[2].subdivisions, scene.objects[2].subdivisions) << "a mesh has no level";
}

TEST(SceneShapes, ASplitsLevelStaysWithinTheTeapotsLevels) {
    expectPieces(parseError(R"({"view": "split:phong@9,phong@2", "objects": [{}, {"shape": "teapot"}]})"),
                 {"view: a side's @9 is beyond the teapot's levels 0..8", "objects[1] is a teapot", "@8"});
    EXPECT_NO_THROW((void)parseScene(R"({"view": "split:phong@9,phong@2", "objects": [{}]})"));
    Scene scene;
    scene.objects = {teapot(2)};
    scene.view = parseViewOrThrow("split:phong@10,gouraud", "view");
    expectPieces(test::inputErrorOf([&] { validateSceneValues(scene); }), {"view: a side's @10"});
}

} // namespace
} // namespace shadelab
