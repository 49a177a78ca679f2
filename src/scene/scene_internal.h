// What the scene's source files share; not a public header. The scene is read in two steps, each with its
// file — scene_json.cpp (the file's bytes → a JSON tree, refusing hostile text) and scene_parse.cpp (the
// tree → a Scene: structure and types; an object's shape is scene_shapes.cpp's) — while scene_check.cpp
// holds every range, scene_messages.cpp the pieces of the messages, scene_write.cpp the way back to JSON,
// and scene.cpp the vocabularies, defaults and matrices.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include "shadelab/errors.h"
#include "shadelab/scene/scene.h"
#include "shadelab/scene/scene_values.h"
#include "shadelab/shading/lighting.h"

namespace shadelab::detail {

using Json = nlohmann::json;

// ---- message pieces (scene_messages.cpp) ----

// What std::to_chars(value) gives: the shortest form that reads back as `value`.
std::string formatNumber(double value);
std::string formatVec(const glm::dvec3& v); // "[1, 0, -2.5]"
// JSON paths: keyPath("objects[0]", "material") is "objects[0].material"; a key that is not plain is quoted
// in brackets (`["a b"]`).
std::string keyPath(std::string_view parent, std::string_view key);
std::string indexPath(std::string_view parent, std::size_t index); // "objects[2]"
// Throws InputError "<path>: <message>" (the message alone when path is empty).
[[noreturn]] void fail(std::string_view path, std::string_view message);
// Rethrows an error from camera.h or sphere.h, adding `path` unless its message already starts with it.
[[noreturn]] void failWithin(std::string_view path, const InputError& error);
// "<path>: must be between lo and hi, got <shown>".
[[noreturn]] void failOutOfRange(IntRange range, std::string_view shown, std::string_view path);
// A value as a message names it: "null", "string \"x\"", "number 2", "array of 3 elements", "object".
std::string describe(const Json& value);
std::string joinKeys(std::span<const std::string_view> keys); // "a, b, c"

// ---- range checks (scene_check.cpp), called by parseScene as it reads and again by validateScene ----

inline constexpr IntRange kToonBandRange{kMinToonBands, kMaxToonBands};

void checkFinite(double value, std::string_view path);
void checkIntRange(int value, IntRange range, std::string_view path);
void checkViewAt(double at);
void checkObserver(const Observer& observer); // "view_observer"
void checkSceneSize(const Scene& scene);      // image.width, image.height
void checkImage(const Scene& scene);          // size and background
void checkCamera(const Scene& scene);
void checkProjection(const Projection& p);
void checkObject(const SceneObject& object, const std::string& path);
void checkObjectCount(std::size_t count);
void checkLightCount(std::size_t count);
// Only the fields the light's type uses are checked: the others are ignored by the lighting code.
void checkLight(const Light& light, const std::string& path);
void checkPlacement(const Scene& scene);

bool hasPosition(LightType type);
bool hasDirection(LightType type);

// ---- an object's shape (scene_shapes.cpp) ----

// A shape's levels: the sphere's 0..kMaxSubdivisions, the teapot's 0..kMaxTeapotLevel (a mesh has none:
// an empty range).
IntRange levelRange(Shape shape);
// A level of `shape` (not "auto"): the sphere's check names the memory a level above the maximum needs.
void checkLevel(Shape shape, int level, std::string_view path);
void checkSubdivisions(Shape shape, int level, std::string_view path); // a level, or kAutoSubdivisions
// "mesh": a non-empty relative path without NUL (DESIGN §4).
void checkMeshPath(std::string_view file, std::string_view path);
// The split's @level on every object (view.h): within the teapot's range where the scene holds a teapot.
void checkSplitLevels(const Scene& scene);
// An object's "shape", or "mesh" and "closed", with the refusals of keys that do not apply; its level is
// read after (scene_parse.cpp), in the shape's range.
void readShapeKeys(const Json& json, const std::string& path, SceneObject& object);

// ---- reading a JSON tree (scene_parse.cpp; lesson.cpp reads lessons with them too) ----

// The scene's top-level keys, in the order DESIGN §4 lists them.
inline constexpr std::array<std::string_view, 18> kSceneKeys = {
    "image",        "camera",   "projection",     "perspective_matrix",
    "shading",      "lighting", "term",           "toon_bands",
    "tolerance_px", "depth",    "vertex_normals", "normal_matrix",
    "overlay",      "view",     "view_at",        "view_observer",
    "objects",      "lights"};
void requireObject(const Json& value, std::string_view path);
// "<path>.<key>: unknown key; expected one of ..." for the first key not in `allowed`.
void checkKeys(const Json& object, std::string_view path, std::span<const std::string_view> allowed);
const Json* member(const Json& object, std::string_view key); // nullptr when absent
const std::string& readString(const Json& value, std::string_view path);
// A whole scene from its tree: parseScene without the text's parsing and without the source's name.
Scene sceneFromJson(const Json& root);

// ---- scene text (scene_json.cpp) ----

// A regular file, or "-" for standard input; an InputError naming the path for anything else.
std::string readSceneFile(const std::filesystem::path& path);
// The text as a JSON tree: nesting bounded, duplicate keys refused, every syntax error named with its
// byte and, where a number is out of range, its JSON path.
Json parseJson(std::string_view text);
// `source`'s text as a tree, an InputError prefixed with "<source>: ": the one parse of a file that may be a
// scene or a lesson (lesson.cpp reads which it is from the tree).
Json parseJsonFrom(std::string_view text, std::string_view source);
// sceneFromJson with its errors prefixed with "<source>: ", as parseScene gives them.
Scene sceneFromTree(const Json& tree, std::string_view source);
// A tree that is a lesson rather than a scene: an object with "steps" (lesson.cpp).
bool isLessonTree(const Json& tree);

} // namespace shadelab::detail
