// Scene files (DESIGN §4) without GL: defaults, the light-entry rules, every class of bad input (each error
// must name the JSON path and the offending value), hostile input, and the matrices derived from a scene.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "input_error.h"
#include "shadelab/errors.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_file.h"

namespace glm {
// Readable failures for EXPECT_EQ on vectors (gtest finds PrintTo by argument-dependent lookup).
inline void PrintTo(const dvec3& v, std::ostream* os) {
    *os << "[" << v.x << ", " << v.y << ", " << v.z << "]";
}
} // namespace glm

namespace shadelab {
namespace {

namespace fs = std::filesystem;

// The example of DESIGN §4, verbatim: it must describe exactly the defaults.
constexpr const char* kDesignExample = R"({
  "image":      { "width": 512, "height": 512, "background": [0, 0, 0] },
  "camera":     { "eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0] },
  "projection": { "type": "perspective", "fovy_deg": 40, "near": 0.5, "far": 20 },
  "shading":    "phong",
  "lighting":   "blinn-phong",
  "objects": [
    { "center": [0, 0, 0], "radius": 1, "scale": [1, 1, 1], "subdivisions": 5,
      "material": { "ambient": [0.1, 0.1, 0.1], "diffuse": [0.7, 0.2, 0.2],
                    "specular": [1, 1, 1], "shininess": 32 } }
  ],
  "lights": [
    { "type": "point", "position": [3, 3, 5], "ambient": [0.1, 0.1, 0.1],
      "diffuse": [1, 1, 1], "specular": [1, 1, 1], "attenuation": [1, 0, 0] }
  ]
})";

// The InputError message parseScene throws for `json`, or a test failure when it throws none.
std::string parseError(const std::string& json) {
    const std::string message = test::inputErrorOf([&] { (void)parseScene(json, "scene.json"); });
    if (message.empty()) ADD_FAILURE() << "no InputError for: " << json.substr(0, 200);
    return message;
}

std::string validateError(const Scene& scene) {
    const std::string message = test::inputErrorOf([&] { validateScene(scene); });
    if (message.empty()) ADD_FAILURE() << "validateScene accepted the scene";
    return message;
}

::testing::AssertionResult containsAll(const std::string& message, const std::vector<std::string>& parts) {
    for (const std::string& part : parts)
        if (message.find(part) == std::string::npos)
            return ::testing::AssertionFailure() << "message \"" << message << "\" lacks \"" << part << "\"";
    return ::testing::AssertionSuccess();
}

void expectSameLight(const Light& a, const Light& b) {
    EXPECT_EQ(a.type, b.type);
    EXPECT_EQ(a.ambient, b.ambient);
    EXPECT_EQ(a.diffuse, b.diffuse);
    EXPECT_EQ(a.specular, b.specular);
    EXPECT_EQ(a.position, b.position);
    EXPECT_EQ(a.direction, b.direction);
    EXPECT_EQ(a.cutoffDeg, b.cutoffDeg);
    EXPECT_EQ(a.exponent, b.exponent);
    EXPECT_EQ(a.attenuation, b.attenuation);
}

void expectSameObject(const SceneObject& a, const SceneObject& b) {
    EXPECT_EQ(a.center, b.center);
    EXPECT_EQ(a.radius, b.radius);
    EXPECT_EQ(a.scale, b.scale);
    EXPECT_EQ(a.subdivisions, b.subdivisions);
    EXPECT_EQ(a.material.ambient, b.material.ambient);
    EXPECT_EQ(a.material.diffuse, b.material.diffuse);
    EXPECT_EQ(a.material.specular, b.material.specular);
    EXPECT_EQ(a.material.shininess, b.material.shininess);
}

void expectSameScene(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.background, b.background);
    EXPECT_EQ(a.eye, b.eye);
    EXPECT_EQ(a.target, b.target);
    EXPECT_EQ(a.up, b.up);
    EXPECT_EQ(a.projection.type, b.projection.type);
    EXPECT_EQ(a.projection.fovyDeg, b.projection.fovyDeg);
    EXPECT_EQ(a.projection.left, b.projection.left);
    EXPECT_EQ(a.projection.right, b.projection.right);
    EXPECT_EQ(a.projection.bottom, b.projection.bottom);
    EXPECT_EQ(a.projection.top, b.projection.top);
    EXPECT_EQ(a.projection.near, b.projection.near);
    EXPECT_EQ(a.projection.far, b.projection.far);
    EXPECT_EQ(a.shading, b.shading);
    EXPECT_EQ(a.lighting, b.lighting);
    EXPECT_EQ(a.term, b.term);
    EXPECT_EQ(a.toonBands, b.toonBands);
    EXPECT_EQ(a.tolerancePx, b.tolerancePx);
    EXPECT_EQ(a.depth, b.depth);
    EXPECT_EQ(a.vertexNormals, b.vertexNormals);
    EXPECT_EQ(a.normalMatrix, b.normalMatrix);
    EXPECT_EQ(a.perspectiveMatrix, b.perspectiveMatrix);
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (std::size_t i = 0; i < a.objects.size(); ++i) expectSameObject(a.objects[i], b.objects[i]);
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (std::size_t i = 0; i < a.lights.size(); ++i) expectSameLight(a.lights[i], b.lights[i]);
}

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

// ---- errors: each row is the input and the pieces its message must contain (path, value, expectation) ----

struct ErrorCase {
    const char* name;
    std::string json;
    std::vector<std::string> expected;
};

// Test names and failure messages show the case by its name, not as bytes.
inline void PrintTo(const ErrorCase& c, std::ostream* os) {
    *os << c.name;
}

std::string light(const std::string& body) {
    return R"({"lights": [)" + body + "]}";
}
std::string object(const std::string& body) {
    return R"({"objects": [)" + body + "]}";
}

const std::vector<ErrorCase> kErrorCases = {
    // JSON syntax: the source, the byte and nlohmann's explanation.
    {"Malformed", R"({"image": })", {"scene.json: invalid JSON at byte 11: ", "syntax error"}},
    {"EmptyInput", "", {"scene.json: invalid JSON at byte 1: ", "unexpected end of input"}},
    {"TrailingGarbage", "{} x", {"scene.json: invalid JSON at byte", "expected end of input"}},
    {"InvalidUtf8", "{\"shading\": \"\xff\"}", {"scene.json: invalid JSON", "UTF-8"}},
    {"DuplicateKey",
     object(R"({"radius": 1, "radius": -1})"),
     {"scene.json: objects[0].radius: duplicate key"}},
    // Non-finite numbers: nlohmann refuses to overflow to inf; we name where it happened.
    {"Overflow",
     object(R"({"radius": 1e999})"),
     {"scene.json: objects[0].radius: must be finite, got 1e999"}},
    {"NegativeOverflowInArray",
     R"({"image": {"background": [0, -1e999, 0]}})",
     {"image.background[1]: must be finite, got -1e999"}},
    // Wrong types.
    {"TopLevelArray", "[]", {"scene.json: the top level: must be an object, got array of 0 elements"}},
    {"ImageNotObject", R"({"image": 5})", {"scene.json: image: must be an object, got number 5"}},
    {"WidthString", R"({"image": {"width": "512"}})", {"image.width: must be a number, got string \"512\""}},
    {"WidthFraction", R"({"image": {"width": 512.5}})", {"image.width: must be a whole number, got 512.5"}},
    {"BackgroundTooShort",
     R"({"image": {"background": [0, 0]}})",
     {"image.background: must be an array of 3 numbers, got array of 2 elements"}},
    {"BackgroundElementNull",
     R"({"image": {"background": [0, null, 0]}})",
     {"image.background[1]: must be a number, got null"}},
    {"EyeNotArray",
     R"({"camera": {"eye": {"x": 1}}})",
     {"camera.eye: must be an array of 3 numbers, got object"}},
    {"ShadingNumber", R"({"shading": 3})", {"shading: must be a string, got number 3"}},
    {"ObjectsNotArray", R"({"objects": {}})", {"objects: must be an array, got object"}},
    {"ObjectNotObject", object("[1]"), {"objects[0]: must be an object, got array of 1 element"}},
    {"RadiusBoolean", object(R"({"radius": true})"), {"objects[0].radius: must be a number, got true"}},
    {"MaterialNotObject",
     object(R"({"material": "red"})"),
     {"objects[0].material: must be an object, got string"}},
    {"LightNotObject", R"({"lights": [null]})", {"lights[0]: must be an object, got null"}},
    {"LightTypeNotString", light(R"({"type": 1})"), {"lights[0].type: must be a string, got number 1"}},
    // Unknown keys at every level, with the keys that would be accepted.
    {"UnknownTopLevelKey",
     R"({"shadding": "phong"})",
     {"scene.json: shadding: unknown key; expected one of image, camera, projection, perspective_matrix, "
      "shading, lighting, term, toon_bands, tolerance_px, depth, vertex_normals, normal_matrix, overlay, "
      "view, view_at, view_observer, objects, lights"}},
    {"ObserverElevationPastThePole",
     R"({"view": "outside", "view_observer": [10, 90, 1]})",
     {"scene.json: view_observer[1]: the observer's elevation must be between -85 and 85 degrees, got 90"}},
    {"ObserverZoomZero",
     R"({"view_observer": [10, 20, 0]})",
     {"scene.json: view_observer[2]: the observer's zoom must be between 0.05 and 20 (1: everything "
      "framed), got 0"}},
    {"ObserverNotThreeNumbers",
     R"({"view_observer": [10, 20]})",
     {"scene.json: view_observer: must be an array of 3 numbers"}},
    {"OverlayUnknown",
     R"({"overlay": "wires"})",
     {"scene.json: overlay: unknown value \"wires\"; expected one of none, wireframe, normals, lights"}},
    {"UnknownImageKey",
     R"({"image": {"depth": 8}})",
     {"image.depth: unknown key; expected one of width, height"}},
    {"UnknownCameraKey",
     R"({"camera": {"fov": 40}})",
     {"camera.fov: unknown key; expected one of eye, target, up"}},
    {"UnknownProjectionKey",
     R"({"projection": {"fovy": 40}})",
     {"projection.fovy: unknown key; expected one of type, fovy_deg, near, far"}},
    {"BoxKeyOnPerspective",
     R"({"projection": {"left": -1}})",
     {"projection.left: does not apply to a perspective projection; expected one of type, fovy_deg, near, "
      "far"}},
    {"FovyOnOrthographic",
     R"({"projection": {"type": "orthographic", "fovy_deg": 40}})",
     {"projection.fovy_deg: does not apply to an orthographic projection; expected one of type, left, right, "
      "bottom, top, near, far"}},
    {"UnknownObjectKey",
     object(R"({"centre": [0, 0, 0]})"),
     {"objects[0].centre: unknown key; expected one of center, radius, scale, subdivisions, material"}},
    {"UnknownMaterialKey",
     object(R"({"material": {"shininez": 32}})"),
     {"scene.json: objects[0].material.shininez: unknown key; expected one of ambient, diffuse, specular, "
      "shininess"}},
    {"UnknownLightKey",
     light(R"({"type": "point", "position": [0, 0, 0], "colour": [1, 1, 1]})"),
     {"lights[0].colour: unknown key; expected one of type, position, attenuation, ambient, diffuse, "
      "specular"}},
    {"KeyWithSpecialCharacters", R"({"a.b\n": 1})", {R"(["a.b\n"]: unknown key)"}},
    // Enumerations: the value and the accepted spellings.
    {"UnknownShading",
     R"({"shading": "phongg"})",
     {R"(scene.json: shading: unknown value "phongg"; expected one of flat, gouraud, phong, toon)"}},
    {"UnknownLighting",
     R"({"lighting": "blinn"})",
     {R"(lighting: unknown value "blinn"; expected one of phong, blinn-phong)"}},
    {"UnknownTerm",
     R"({"term": "spec"})",
     {R"(term: unknown value "spec"; expected one of all, ambient, diffuse, specular)"}},
    {"UnknownNormalMatrix",
     R"({"normal_matrix": "inverse"})",
     {R"(normal_matrix: unknown value "inverse"; expected one of inverse-transpose, model)"}},
    {"UnknownPerspectiveMatrix",
     R"({"perspective_matrix": "opengl"})",
     {R"(perspective_matrix: unknown value "opengl"; expected one of webgl, unnegated)"}},
    {"UnknownProjectionType",
     R"({"projection": {"type": "fisheye"}})",
     {R"(projection.type: unknown value "fisheye"; expected one of perspective, frustum, orthographic)"}},
    {"UnknownLightType",
     light(R"({"type": "laser"})"),
     {R"(lights[0].type: unknown value "laser"; expected one of ambient, directional, point, spot)"}},
    {"LongValueIsTruncated",
     std::string(R"({"shading": ")") + std::string(5000, 'x') + "\"}",
     {R"(shading: unknown value "xxxxxxxx)", "...\"; expected one of"}},
    // Light entries: required keys per type, and keys that belong to another type.
    {"LightWithoutType", light(R"({"position": [0, 0, 0]})"), {"lights[0].type: required"}},
    {"PointWithoutPosition",
     light(R"({"type": "point"})"),
     {"lights[0].position: required for a point light"}},
    {"SpotWithoutPosition",
     light(R"({"type": "spot", "direction": [0, 0, -1], "cutoff_deg": 30})"),
     {"lights[0].position: required for a spot light"}},
    {"SpotWithoutDirection",
     light(R"({"type": "spot", "position": [0, 0, 0], "cutoff_deg": 30})"),
     {"lights[0].direction: required for a spot light"}},
    {"SpotWithoutCutoff",
     light(R"({"type": "spot", "position": [0, 0, 0], "direction": [0, 0, -1]})"),
     {"lights[0].cutoff_deg: required for a spot light"}},
    {"DirectionalWithoutDirection",
     light(R"({"type": "directional"})"),
     {"lights[0].direction: required for a directional light"}},
    {"CutoffOnPointLight",
     light(R"({"type": "point", "position": [0, 0, 0], "cutoff_deg": 30})"),
     {"lights[0].cutoff_deg: does not apply to a point light"}},
    {"AttenuationOnDirectionalLight",
     light(R"({"type": "directional", "direction": [0, 0, -1], "attenuation": [1, 0, 0]})"),
     {"lights[0].attenuation: does not apply to a directional light"}},
    {"PositionOnDirectionalLight",
     light(R"({"type": "directional", "direction": [0, 0, -1], "position": [0, 0, 0]})"),
     {"lights[0].position: does not apply to a directional light"}},
    {"DiffuseOnAmbientLight",
     light(R"({"type": "ambient", "diffuse": [1, 1, 1]})"),
     {"lights[0].diffuse: does not apply to an ambient light"}},
    {"ExponentOnPointLight",
     light(R"({"type": "point", "position": [0, 0, 0], "exponent": 2})"),
     {"lights[0].exponent: does not apply to a point light"}},
    // Ranges.
    {"WidthZero", R"({"image": {"width": 0}})", {"image.width: must be between 1 and 16384, got 0"}},
    {"HeightTooLarge",
     R"({"image": {"height": 16385}})",
     {"image.height: must be between 1 and 16384, got 16385"}},
    {"WidthBeyondInt",
     R"({"image": {"width": 1e12}})",
     {"image.width: must be between 1 and 16384, got 1e+12"}},
    {"NegativeBackground",
     R"({"image": {"background": [0, 0, -0.5]}})",
     {"image.background[2]: must be >= 0, got -0.5"}},
    {"EyeEqualsTarget",
     R"({"camera": {"eye": [1, 2, 3], "target": [1, 2, 3]}})",
     {"scene.json: camera: ", "target"}},
    {"UpParallelToView",
     R"({"camera": {"eye": [0, 5, 0], "target": [0, 0, 0], "up": [0, 2, 0]}})",
     {"scene.json: camera: ", "parallel"}},
    {"FovyZero", R"({"projection": {"fovy_deg": 0}})", {"projection.fovy_deg: must be > 0, got 0"}},
    {"Fovy180", R"({"projection": {"fovy_deg": 180}})", {"projection.fovy_deg: must be < 180, got 180"}},
    {"NearZero", R"({"projection": {"near": 0}})", {"projection.near: must be > 0, got 0"}},
    {"NearNegative", R"({"projection": {"near": -1}})", {"projection.near: must be > 0, got -1"}},
    {"FarBeforeNear",
     R"({"projection": {"near": 5, "far": 2}})",
     {"projection.far: must be > near (5), got 2"}},
    {"NearBeyondDefaultFar",
     R"({"projection": {"near": 30}})",
     {"projection.far: must be > near (30), got 20"}},
    {"LeftEqualsRight",
     R"({"projection": {"type": "frustum", "left": 1, "right": 1}})",
     {"projection.right: must differ from left (1), got 1"}},
    {"BottomEqualsTop",
     R"({"projection": {"type": "orthographic", "bottom": 0.5, "top": 0.5}})",
     {"projection.top: must differ from bottom (0.5), got 0.5"}},
    // Values 32-bit float cannot carry (the GPU's matrices and uniforms): each names its field, its own value
    // and the fix.
    {"FrustumWindowDenormal",
     R"({"projection": {"type": "frustum", "left": -1e-40, "right": 1e-40, "bottom": -1e-40, "top": 1e-40}})",
     {"projection.left: must be 0 or between 1e-30 and 1e+30 in magnitude", "got -1e-40",
      "change the scene's units"}},
    {"FrustumWindow1e300",
     R"({"projection": {"type": "frustum", "left": -1, "right": 1e-300}})",
     {"projection.right: ", "got 1e-300"}},
    {"OrthographicLeftShownWithItsSign",
     R"({"projection": {"type": "orthographic", "left": -1e-300, "right": 1}})",
     {"projection.left: ", "got -1e-300"}},
    {"WidthReportsTheFieldAndTheDifference",
     R"({"projection": {"type": "orthographic", "left": -1e30, "right": 1e30}})",
     {"projection.right: got 1e+30, which makes right - left 2e+30", "between 1e-30 and 1e+30"}},
    {"FrustumSlopeBeyondFloat",
     R"({"projection": {"type": "frustum", "left": -1e-20, "right": 1e-20, "near": 1e20, "far": 1e21}})",
     {"projection.right: got 1e-20, which with left -1e-20 and near 1e+20", "2 near / (right - left) 1e+40",
      "widen the window or lower near"}},
    {"RadiusDenormal",
     object(R"({"radius": 1e-40})"),
     {"objects[0].radius: must be between 1e-30", "got 1e-40"}},
    {"SemiAxisBeyondFloat",
     object(R"({"scale": [1, 1, 1e-155]})"),
     {"objects[0].scale[2]: got 1e-155, which makes the semi-axis radius x scale[2] 1e-155",
      "between 1e-30"}},
    {"ThinObjectBeyondTheRayCastsReach",
     object(R"({"scale": [1, 1, 1e-20]})"),
     {"objects[0].scale[2]: got 1e-20", "reaches 5 from the eye", "5e+20 of those semi-axes",
      "at least 5e-18 or bring the eye closer"}},
    {"CenterBeyondFloatFromTheEye",
     object(R"({"center": [0, 0, -1e31]})"),
     {"objects[0].center: lies 1e+31 from the eye [0, 0, 4]", "got [0, 0, -1e+31]", "move it or the eye"}},
    {"LightBeyondFloatFromTheEye",
     light(R"({"type": "point", "position": [1e39, 0, 4]})"),
     {"lights[0].position: lies 1e+39 from the eye", "got [1e+39, 0, 4]", "directional light"}},
    {"AttenuationDenormal",
     light(R"({"type": "point", "position": [0, 0, 9], "attenuation": [1, 0, 1e-40]})"),
     {"lights[0].attenuation[2]: must be 0 or at least 1e-30", "got 1e-40", "use 0"}},
    {"RadiusZero", object(R"({"radius": 0})"), {"objects[0].radius: must be > 0, got 0"}},
    {"RadiusNegativeSecondObject",
     object(R"({}, {"radius": -2})"),
     {"objects[1].radius: must be > 0, got -2"}},
    {"ScaleComponentZero",
     object(R"({"scale": [1, 0, 1]})"),
     {"objects[0].scale[1]: must be non-zero, got 0"}},
    {"SubdivisionsNegative",
     object(R"({"subdivisions": -1})"),
     {"objects[0].subdivisions: must be between 0 and 10, got -1"}},
    {"SubdivisionsTooHigh", object(R"({"subdivisions": 11})"), {"objects[0].subdivisions: ", "11", "10"}},
    {"SubdivisionsFraction",
     object(R"({"subdivisions": 2.5})"),
     {"objects[0].subdivisions: must be a whole number, got 2.5"}},
    {"SubdivisionsBeyondInt",
     object(R"({"subdivisions": 1e12})"),
     {"objects[0].subdivisions: must be between 0 and 10, got 1e+12"}},
    {"NegativeMaterialColour",
     object(R"({"material": {"diffuse": [-0.1, 0, 0]}})"),
     {"objects[0].material.diffuse[0]: must be >= 0, got -0.1"}},
    {"ShininessBelowOne",
     object(R"({"material": {"shininess": 0.5}})"),
     {"objects[0].material.shininess: must be >= 1, got 0.5"}},
    {"NegativeAttenuation",
     light(R"({"type": "ambient"}, {"type": "point", "position": [0, 0, 0], "attenuation": [1, 0, -1]})"),
     {"scene.json: lights[1].attenuation[2]: must be >= 0, got -1"}},
    {"ZeroAttenuation",
     light(R"({"type": "point", "position": [0, 0, 0], "attenuation": [0, 0, 0]})"),
     {"lights[0].attenuation: components must have a positive sum, got [0, 0, 0]"}},
    {"CutoffAbove90",
     light(R"({"type": "spot", "position": [0, 0, 0], "direction": [0, 0, -1], "cutoff_deg": 91})"),
     {"lights[0].cutoff_deg: must be <= 90, got 91"}},
    {"CutoffNegative",
     light(R"({"type": "spot", "position": [0, 0, 0], "direction": [0, 0, -1], "cutoff_deg": -1})"),
     {"lights[0].cutoff_deg: must be >= 0, got -1"}},
    {"ExponentNegative",
     light(R"({"type": "spot", "position": [0, 0, 0], "direction": [0, 0, -1], "cutoff_deg": 10,
               "exponent": -1})"),
     {"lights[0].exponent: must be >= 0, got -1"}},
    {"DirectionZero",
     light(R"({"type": "directional", "direction": [0, 0, 0]})"),
     {"lights[0].direction: must be non-zero, got [0, 0, 0]"}},
    {"NegativeLightColour",
     light(R"({"type": "directional", "direction": [0, 0, -1], "specular": [1, -2, 1]})"),
     {"lights[0].specular[1]: must be >= 0, got -2"}},
    {"TooManyLights",
     light(R"({"type": "ambient"},{"type": "ambient"},{"type": "ambient"},{"type": "ambient"},
              {"type": "ambient"},{"type": "ambient"},{"type": "ambient"},{"type": "ambient"},
              {"type": "ambient"})"),
     {"scene.json: lights: at most 8 lights are supported, got 9"}},
};

class SceneError : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(SceneError, NamesPathAndValue) {
    std::string message = parseError(GetParam().json);
    EXPECT_TRUE(containsAll(message, GetParam().expected));
    EXPECT_LT(message.size(), 400u) << "messages stay short whatever the input";
}

INSTANTIATE_TEST_SUITE_P(Scene, SceneError, ::testing::ValuesIn(kErrorCases),
                         [](const ::testing::TestParamInfo<ErrorCase>& info) { return info.param.name; });

// ---- hostile input ----

TEST(SceneHostile, DeepNestingIsRejectedBeforeParsing) {
    std::string json = R"({"objects": )" + std::string(1'000'000, '[');
    EXPECT_TRUE(containsAll(parseError(json), {"scene.json: invalid JSON at byte", "nested deeper than 64"}));
}

TEST(SceneHostile, NestingLimitIsExact) {
    // The root object is level 1, so 63 arrays inside it reach 64: parsed, then refused as an unknown key.
    auto nested = [](int arrays) {
        return R"({"x": )" + std::string(arrays, '[') + std::string(arrays, ']') + "}";
    };
    EXPECT_TRUE(containsAll(parseError(nested(63)), {"x: unknown key"}));
    EXPECT_TRUE(containsAll(parseError(nested(64)), {"nested deeper than 64"}));
}

TEST(SceneHostile, BracketsInsideStringsDoNotCount) {
    std::string json = R"({"shading": "\")" + std::string(1000, '[') + R"("})";
    EXPECT_TRUE(containsAll(parseError(json), {"shading: unknown value"}));
}

TEST(SceneHostile, HugeArrayIsRefusedByItsSize) {
    std::string json = R"({"image": {"background": [0)";
    for (int i = 0; i < 1'000'000; ++i) json += ",0";
    EXPECT_TRUE(
        containsAll(parseError(json + "]}}"),
                    {"image.background: must be an array of 3 numbers, got array of 1000001 elements"}));
}

TEST(SceneHostile, HugeLightArrayIsRefusedByItsCount) {
    std::string json = R"({"lights": [{})";
    for (int i = 0; i < 100'000; ++i) json += ",{}";
    EXPECT_TRUE(containsAll(parseError(json + "]}"), {"lights: at most 8 lights are supported, got 100001"}));
}

TEST(SceneHostile, SourceNamesTheText) {
    try {
        parseScene(R"({"x": 1})", "dir/my scene.json");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("dir/my scene.json: x: unknown key", 0), 0u) << e.what();
    }
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

// ---- validateScene: the same checks on a scene built or changed in code, without a source prefix ----

TEST(SceneValidate, AcceptsDefaultsAndTheDesignExample) {
    EXPECT_NO_THROW(validateScene(Scene{}));
    EXPECT_NO_THROW(validateScene(parseScene(kDesignExample)));
}

TEST(SceneValidate, NamesTheField) {
    struct Case {
        const char* expected;
        void (*change)(Scene&);
    };
    const Case cases[] = {
        {"image.width: must be between 1 and 16384, got 0", [](Scene& s) { s.width = 0; }},
        {"image.background[0]: must be >= 0, got -1", [](Scene& s) { s.background.x = -1; }},
        {"camera: ", [](Scene& s) { s.target = s.eye; }},
        {"camera.up[1]: must be finite, got nan", [](Scene& s) { s.up.y = std::nan(""); }},
        {"projection.far: must be > near (0.5), got 0.5", [](Scene& s) { s.projection.far = 0.5; }},
        {"projection.fovy_deg: must be < 180, got 200", [](Scene& s) { s.projection.fovyDeg = 200; }},
        {"projection.right: must differ from left (-1), got -1",
         [](Scene& s) {
             s.projection.type = ProjectionType::Orthographic;
             s.projection.right = -1;
         }},
        {"objects[1].radius: must be > 0, got -1",
         [](Scene& s) {
             s.objects.push_back(SceneObject{});
             s.objects[1].radius = -1;
         }},
        {"objects[0].scale[2]: must be non-zero, got 0", [](Scene& s) { s.objects[0].scale.z = 0; }},
        {"objects[0].subdivisions: ", [](Scene& s) { s.objects[0].subdivisions = 12; }},
        {"objects[0].material.shininess: must be finite, got inf",
         [](Scene& s) { s.objects[0].material.shininess = INFINITY; }},
        {"lights: at most 8 lights are supported, got 9", [](Scene& s) { s.lights.resize(9); }},
        {"lights[0].attenuation: components must have a positive sum",
         [](Scene& s) { s.lights[0].attenuation = glm::dvec3(0); }},
        {"lights[0].cutoff_deg: must be <= 90, got 95",
         [](Scene& s) {
             s.lights[0].type = LightType::Spot;
             s.lights[0].cutoffDeg = 95;
         }},
        {"lights[0].direction: must be non-zero",
         [](Scene& s) {
             s.lights[0].type = LightType::Directional;
             s.lights[0].direction = glm::dvec3(0);
         }},
    };
    for (const Case& c : cases) {
        Scene scene;
        c.change(scene);
        std::string message = validateError(scene);
        EXPECT_EQ(message.rfind(c.expected, 0), 0u)
            << "expected \"" << c.expected << "\", got \"" << message << "\"";
    }
}

TEST(SceneValidate, IgnoresFieldsTheLightTypeDoesNotUse) {
    Scene scene;
    scene.lights[0].type = LightType::Directional;
    scene.lights[0].attenuation = glm::dvec3(0); // unused by a directional light
    scene.lights[0].cutoffDeg = 500;             // unused by a directional light
    EXPECT_NO_THROW(validateScene(scene));
}

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

// The scene-wide limits are validateScene's, not parseScene's: a file may exceed them and a flag applied
// after parsing (--depth reversed here) bring it within. Its values alone pass (the fuzzer's contract:
// fuzz/scene_fuzzer.cpp, which found this scene's shape).
TEST(SceneLimits, ParsedValuesPassAndTheLimitsWaitForTheComposedScene) {
    const Scene scene = parseScene(R"({"projection": {"near": 1e-4, "far": 1e7},
                                       "objects": [{"center": [2e6, 0, 0], "subdivisions": 0}]})",
                                   "deep.json");
    EXPECT_NO_THROW(validateSceneValues(scene));
    EXPECT_THROW(checkSceneLimits(scene), InputError);
    EXPECT_THROW(validateScene(scene), InputError);
    Scene reversed = scene;
    reversed.depth = DepthMode::Reversed;
    EXPECT_NO_THROW(validateScene(reversed));
}

} // namespace
} // namespace shadelab
