// Bad scenes refused (DESIGN §4) without GL: every class of bad input in a scene file, each message naming
// the JSON path and the offending value (a table); hostile input (deep nesting, huge arrays); validateScene's
// same checks on a scene built or changed in code; and the scene-wide limits, which wait for the composed
// scene.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "input_error.h"
#include "scene/scene_test_support.h"
#include "shadelab/errors.h"
#include "shadelab/scene/scene.h"

namespace shadelab {
namespace {

using namespace scene_test;

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
