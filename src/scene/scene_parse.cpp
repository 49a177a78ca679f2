// JSON tree → Scene (DESIGN §4): structure and types, every error naming the JSON path, the value and what
// is expected. The ranges are scene_check.cpp's, checked per entity as it is read; the text before the tree
// is scene_json.cpp's.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene_internal.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/scene_file.h"
#include "shadelab/vocabulary.h"

namespace shadelab {

using namespace detail;

namespace detail {

void requireObject(const Json& value, std::string_view path) {
    if (!value.is_object())
        fail(path.empty() ? "the top level" : path, "must be an object, got " + describe(value));
}

void checkKeys(const Json& object, std::string_view path, std::span<const std::string_view> allowed) {
    for (auto it = object.begin(); it != object.end(); ++it)
        if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end())
            fail(keyPath(path, it.key()), "unknown key; expected one of " + joinKeys(allowed));
}

const Json* member(const Json& object, std::string_view key) {
    auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

const std::string& readString(const Json& value, std::string_view path) {
    if (!value.is_string()) fail(path, "must be a string, got " + describe(value));
    return value.get_ref<const std::string&>();
}

} // namespace detail

namespace {

// "an ambient light", "a point light".
std::string withArticle(std::string_view noun) {
    bool vowel = !noun.empty() && std::string_view("aeiou").find(noun.front()) != std::string_view::npos;
    return (vowel ? "an " : "a ") + std::string(noun);
}

std::string lightName(LightType type) {
    return withArticle(std::string(toString(type)) + " light");
}

// ---- tree → values (types and structure; ranges are the check* functions above) ----

// For objects whose keys depend on their type (projections, lights): a key that another type takes is not a
// typo but a misunderstanding, so say that it does not apply rather than that it is unknown.
void checkKeysOfType(const Json& object, std::string_view path, std::span<const std::string_view> allowed,
                     std::span<const std::string_view> anyType, std::string_view typeName) {
    auto contains = [](std::span<const std::string_view> keys, std::string_view key) {
        return std::find(keys.begin(), keys.end(), key) != keys.end();
    };
    for (auto it = object.begin(); it != object.end(); ++it) {
        if (contains(allowed, it.key())) continue;
        std::string problem =
            contains(anyType, it.key()) ? "does not apply to " + std::string(typeName) : "unknown key";
        fail(keyPath(path, it.key()), problem + "; expected one of " + joinKeys(allowed));
    }
}

double readNumber(const Json& value, std::string_view path) {
    if (!value.is_number()) fail(path, "must be a number, got " + describe(value));
    double number = value.get<double>();
    checkFinite(number, path);
    return number;
}

// Whole numbers beyond int are reported against the field's range before converting (which would overflow).
int readInt(const Json& value, std::string_view path, IntRange range) {
    double number = readNumber(value, path);
    if (number != std::floor(number)) fail(path, "must be a whole number, got " + formatNumber(number));
    if (number < std::numeric_limits<int>::min() || number > std::numeric_limits<int>::max())
        failOutOfRange(range, formatNumber(number), path);
    return static_cast<int>(number);
}

glm::dvec3 readVec3(const Json& value, std::string_view path) {
    if (!value.is_array() || value.size() != 3)
        fail(path, "must be an array of 3 numbers, got " + describe(value));
    glm::dvec3 v;
    for (int i = 0; i < 3; ++i) v[i] = readNumber(value[i], indexPath(path, i));
    return v;
}

template <class Enum, std::size_t N>
Enum readEnum(const Json& value, std::string_view path, const std::array<Enum, N>& values) {
    return parseNameOrThrow(readString(value, path), path, values);
}

// Optional fields: the output keeps its default when the key is absent. Returns whether it was present.
bool readField(const Json& object, std::string_view path, std::string_view key, double& out) {
    const Json* value = member(object, key);
    if (value) out = readNumber(*value, keyPath(path, key));
    return value != nullptr;
}

bool readField(const Json& object, std::string_view path, std::string_view key, glm::dvec3& out) {
    const Json* value = member(object, key);
    if (value) out = readVec3(*value, keyPath(path, key));
    return value != nullptr;
}

void readIntField(const Json& object, std::string_view path, std::string_view key, IntRange range, int& out) {
    if (const Json* value = member(object, key)) out = readInt(*value, keyPath(path, key), range);
}

void readImage(const Json& image, Scene& scene) {
    static constexpr std::array<std::string_view, 3> kKeys = {"width", "height", "background"};
    requireObject(image, "image");
    checkKeys(image, "image", kKeys);
    readIntField(image, "image", "width", kImageSizeRange, scene.width);
    readIntField(image, "image", "height", kImageSizeRange, scene.height);
    readField(image, "image", "background", scene.background);
    checkImage(scene);
}

void readCamera(const Json& camera, Scene& scene) {
    static constexpr std::array<std::string_view, 3> kKeys = {"eye", "target", "up"};
    requireObject(camera, "camera");
    checkKeys(camera, "camera", kKeys);
    readField(camera, "camera", "eye", scene.eye);
    readField(camera, "camera", "target", scene.target);
    readField(camera, "camera", "up", scene.up);
    checkCamera(scene);
}

// left/right/bottom/top may be omitted for frustum and orthographic and then default to -1, 1, -1, 1 (the
// Projection defaults): the unit square, a sensible orthographic view of the default unit sphere.
Projection readProjection(const Json& json) {
    static constexpr std::array<std::string_view, 4> kPerspectiveKeys = {"type", "fovy_deg", "near", "far"};
    static constexpr std::array<std::string_view, 7> kBoxKeys = {"type", "left", "right", "bottom",
                                                                 "top",  "near", "far"};
    requireObject(json, "projection");
    Projection p;
    if (const Json* type = member(json, "type"))
        p.type = readEnum(*type, "projection.type", kProjectionTypes);
    static constexpr std::array<std::string_view, 8> kAnyKeys = {"type",   "fovy_deg", "left", "right",
                                                                 "bottom", "top",      "near", "far"};
    bool perspective = p.type == ProjectionType::Perspective;
    checkKeysOfType(json, "projection",
                    perspective ? std::span<const std::string_view>(kPerspectiveKeys) : kBoxKeys, kAnyKeys,
                    withArticle(std::string(toString(p.type)) + " projection"));
    readField(json, "projection", "fovy_deg", p.fovyDeg);
    readField(json, "projection", "left", p.left);
    readField(json, "projection", "right", p.right);
    readField(json, "projection", "bottom", p.bottom);
    readField(json, "projection", "top", p.top);
    readField(json, "projection", "near", p.near);
    readField(json, "projection", "far", p.far);
    checkProjection(p);
    return p;
}

Material readMaterial(const Json& json, const std::string& path) {
    static constexpr std::array<std::string_view, 4> kKeys = {"ambient", "diffuse", "specular", "shininess"};
    requireObject(json, path);
    checkKeys(json, path, kKeys);
    Material m;
    readField(json, path, "ambient", m.ambient);
    readField(json, path, "diffuse", m.diffuse);
    readField(json, path, "specular", m.specular);
    readField(json, path, "shininess", m.shininess);
    return m;
}

// "subdivisions": a level in the shape's range (the sphere's 0..10, the teapot's 0..8) or "auto".
void readLevel(const Json& json, const std::string& path, SceneObject& object) {
    const Json* level = member(json, "subdivisions");
    if (!level) return;
    const std::string levelPath = keyPath(path, "subdivisions");
    const IntRange range = levelRange(object.shape);
    if (level->is_string()) {
        if (level->get<std::string>() != "auto")
            fail(levelPath, "must be a level " + toString(range) + " or \"auto\", got " + describe(*level));
        object.subdivisions = kAutoSubdivisions;
        return;
    }
    object.subdivisions = readInt(*level, levelPath, range);
    // In a file "auto" is spelled out; kAutoSubdivisions is only the in-memory sentinel.
    if (object.subdivisions < 0) checkLevel(object.shape, object.subdivisions, levelPath);
}

SceneObject readObject(const Json& json, const std::string& path) {
    // The sphere's keys first, in DESIGN §4's order, then the shape's.
    static constexpr std::array<std::string_view, 8> kKeys = {"center",   "radius", "scale", "subdivisions",
                                                              "material", "shape",  "mesh",  "closed"};
    requireObject(json, path);
    checkKeys(json, path, kKeys);
    SceneObject object;
    readShapeKeys(json, path, object);
    readField(json, path, "center", object.center);
    readField(json, path, "radius", object.radius);
    readField(json, path, "scale", object.scale);
    if (object.shape != Shape::Mesh) readLevel(json, path, object);
    const Json* material = member(json, "material");
    if (material) object.material = readMaterial(*material, keyPath(path, "material"));
    // Only a mesh object takes its file's material in the absence of its own (loadSceneModels); the others
    // have the default material, which sceneToJson writes out.
    object.materialGiven = material != nullptr || object.shape != Shape::Mesh;
    checkObject(object, path);
    return object;
}

const Json& requireArray(const Json& value, std::string_view path) {
    if (!value.is_array()) fail(path, "must be an array, got " + describe(value));
    return value;
}

std::vector<SceneObject> readObjects(const Json& json) {
    checkObjectCount(requireArray(json, "objects").size());
    std::vector<SceneObject> objects;
    for (std::size_t i = 0; i < requireArray(json, "objects").size(); ++i)
        objects.push_back(readObject(json[i], indexPath("objects", i)));
    return objects;
}

std::span<const std::string_view> lightKeys(LightType type) {
    static constexpr std::array<std::string_view, 2> kAmbient = {"type", "ambient"};
    static constexpr std::array<std::string_view, 5> kDirectional = {"type", "direction", "ambient",
                                                                     "diffuse", "specular"};
    static constexpr std::array<std::string_view, 6> kPoint = {"type",    "position", "attenuation",
                                                               "ambient", "diffuse",  "specular"};
    static constexpr std::array<std::string_view, 9> kSpot = {"type",       "position", "direction",
                                                              "cutoff_deg", "exponent", "attenuation",
                                                              "ambient",    "diffuse",  "specular"};
    switch (type) {
    case LightType::Ambient:
        return kAmbient;
    case LightType::Directional:
        return kDirectional;
    case LightType::Point:
        return kPoint;
    case LightType::Spot:
        break;
    }
    return kSpot;
}

void readRequired(const Json& json, const std::string& path, std::string_view key, LightType type,
                  glm::dvec3& out) {
    if (!readField(json, path, key, out)) fail(keyPath(path, key), "required for " + lightName(type));
}

Light readLight(const Json& json, const std::string& path) {
    requireObject(json, path);
    const Json* typeJson = member(json, "type");
    if (!typeJson) fail(keyPath(path, "type"), "required; expected one of " + joinNames(kLightTypes));
    Light light;
    light.type = readEnum(*typeJson, keyPath(path, "type"), kLightTypes);
    checkKeysOfType(json, path, lightKeys(light.type), lightKeys(LightType::Spot), lightName(light.type));
    if (light.type == LightType::Ambient) light.diffuse = light.specular = glm::dvec3(0);
    if (hasPosition(light.type)) readRequired(json, path, "position", light.type, light.position);
    if (hasDirection(light.type)) readRequired(json, path, "direction", light.type, light.direction);
    if (light.type == LightType::Spot && !readField(json, path, "cutoff_deg", light.cutoffDeg))
        fail(keyPath(path, "cutoff_deg"), "required for a spot light");
    readField(json, path, "exponent", light.exponent);
    readField(json, path, "attenuation", light.attenuation);
    readField(json, path, "ambient", light.ambient);
    readField(json, path, "diffuse", light.diffuse);
    readField(json, path, "specular", light.specular);
    checkLight(light, path);
    return light;
}

std::vector<Light> readLights(const Json& json) {
    checkLightCount(requireArray(json, "lights").size());
    std::vector<Light> lights;
    for (std::size_t i = 0; i < json.size(); ++i)
        lights.push_back(readLight(json[i], indexPath("lights", i)));
    return lights;
}

} // namespace

Scene detail::sceneFromJson(const Json& root) {
    requireObject(root, "");
    checkKeys(root, "", kSceneKeys);
    Scene scene;
    if (const Json* image = member(root, "image")) readImage(*image, scene);
    if (const Json* camera = member(root, "camera")) readCamera(*camera, scene);
    if (const Json* projection = member(root, "projection")) scene.projection = readProjection(*projection);
    if (const Json* shading = member(root, "shading"))
        scene.shading = readEnum(*shading, "shading", kAllShadingModes);
    if (const Json* lighting = member(root, "lighting"))
        scene.lighting = readEnum(*lighting, "lighting", kLightingModels);
    if (const Json* term = member(root, "term")) scene.term = readEnum(*term, "term", kLightingTerms);
    if (const Json* matrix = member(root, "perspective_matrix"))
        scene.perspectiveMatrix = readEnum(*matrix, "perspective_matrix", kPerspectiveMatrices);
    if (const Json* rule = member(root, "normal_matrix"))
        scene.normalMatrix = readEnum(*rule, "normal_matrix", kNormalMatrixRules);
    readIntField(root, "", "toon_bands", kToonBandRange, scene.toonBands);
    checkIntRange(scene.toonBands, kToonBandRange, "toon_bands");
    readField(root, "", "tolerance_px", scene.tolerancePx);
    checkTolerancePx(scene.tolerancePx, "tolerance_px");
    if (const Json* depth = member(root, "depth")) scene.depth = readEnum(*depth, "depth", kDepthModes);
    if (const Json* normals = member(root, "vertex_normals"))
        scene.vertexNormals = readEnum(*normals, "vertex_normals", kVertexNormals);
    if (const Json* overlay = member(root, "overlay"))
        scene.overlay = readEnum(*overlay, "overlay", kOverlays);
    if (const Json* view = member(root, "view"))
        scene.view = parseViewOrThrow(readString(*view, "view"), "view");
    if (const Json* at = member(root, "view_at")) {
        scene.view.at = readNumber(*at, "view_at");
        checkViewAt(*scene.view.at);
    }
    if (const Json* observer = member(root, "view_observer")) {
        const glm::dvec3 values = readVec3(*observer, "view_observer");
        scene.view.observer = {values.x, values.y, values.z};
        checkObserver(scene.view.observer);
    }
    if (const Json* objects = member(root, "objects")) scene.objects = readObjects(*objects);
    if (const Json* lights = member(root, "lights")) scene.lights = readLights(*lights);
    checkPlacement(scene);
    checkSplitLevels(scene);
    return scene;
}

Json detail::parseJsonFrom(std::string_view text, std::string_view source) {
    try {
        return parseJson(text);
    } catch (const InputError& e) {
        throw InputError(std::string(source) + ": " + e.what());
    }
}

Scene detail::sceneFromTree(const Json& tree, std::string_view source) {
    try {
        return sceneFromJson(tree);
    } catch (const InputError& e) {
        throw InputError(std::string(source) + ": " + e.what());
    }
}

Scene parseScene(std::string_view jsonText, std::string_view source) {
    return sceneFromTree(parseJsonFrom(jsonText, source), source);
}

Material parseMaterial(std::string_view jsonText, std::size_t object, std::string_view source) {
    try {
        const std::string path = indexPath("objects", object);
        SceneObject checked; // the default object, whose other values pass
        checked.material = readMaterial(parseJson(jsonText), keyPath(path, "material"));
        checkObject(checked, path);
        return checked.material;
    } catch (const InputError& e) {
        throw InputError(std::string(source) + ": " + e.what());
    }
}

Scene loadScene(const std::filesystem::path& path) {
    const Json tree = parseJsonFrom(readSceneFile(path), path.string());
    if (isLessonTree(tree))
        throw InputError(
            printable(path.string()) +
            ": a lesson (it has \"steps\"), not a scene: `shadelab LESSON` steps through it in the "
            "window, `shadelab slides LESSON --out-dir DIR` exports it, `shadelab check LESSON` "
            "reads it");
    return sceneFromTree(tree, path.string());
}

} // namespace shadelab
