// An object's shape in a scene (DESIGN §4): "shape" (sphere, teapot), or "mesh" (a model file) with
// "closed"; each shape's levels; and the checks parseScene and validateScene share for them. A mesh
// object's shape and triangles are its file's, so "shape" and "subdivisions" beside "mesh" are refused with
// the fix rather than ignored.
#include <algorithm>
#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene_internal.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/geometry/teapot.h"
#include "shadelab/io/text.h"
#include "shadelab/vocabulary.h"

namespace shadelab::detail {

namespace {

void refuseBesideMesh(const Json& json, const std::string& path) {
    if (member(json, "shape"))
        fail(keyPath(path, "shape"),
             "does not apply to a \"mesh\" object (the file gives its shape); remove it, or remove \"mesh\"");
    if (member(json, "subdivisions"))
        fail(keyPath(path, "subdivisions"),
             "does not apply to a \"mesh\" object (its triangles are the file's); remove it");
}

// "mesh" is the key of a model file, not a value of "shape": say so, beside the shapes there are.
Shape readShape(const Json& value, const std::string& path) {
    const std::string& name = readString(value, path);
    if (name == toString(Shape::Mesh))
        fail(path, "unknown value \"mesh\"; expected one of " + joinNames(kShapes) +
                       " (a model file is an object with \"mesh\": \"models/thing.obj\" and no \"shape\")");
    return parseNameOrThrow(name, path, kShapes);
}

} // namespace

void readShapeKeys(const Json& json, const std::string& path, SceneObject& object) {
    const Json* mesh = member(json, "mesh");
    if (mesh) {
        refuseBesideMesh(json, path);
        const std::string meshPath = keyPath(path, "mesh");
        if (!mesh->is_string())
            fail(meshPath,
                 "must be a file name such as \"models/thing.obj\" (relative to the scene file), got " +
                     describe(*mesh));
        object.shape = Shape::Mesh;
        object.mesh = mesh->get<std::string>();
        checkMeshPath(object.mesh, meshPath);
    } else if (const Json* shape = member(json, "shape")) {
        object.shape = readShape(*shape, keyPath(path, "shape"));
    }
    if (const Json* closed = member(json, "closed")) {
        if (!mesh)
            fail(keyPath(path, "closed"),
                 "applies only to a \"mesh\" object (the sphere is closed, the teapot is open); remove it");
        if (!closed->is_boolean())
            fail(keyPath(path, "closed"), "must be true or false, got " + describe(*closed));
        object.closed = closed->get<bool>();
    }
}

IntRange levelRange(Shape shape) {
    switch (shape) {
    case Shape::Sphere:
        return kSubdivisionRange;
    case Shape::Teapot:
        return {0, kMaxTeapotLevel};
    case Shape::Mesh:
        break;
    }
    return {0, -1};
}

// The level's one check is the mesh builder's (sphere.h, teapot.h): above the sphere's maximum it names the
// memory the level would take, which is the useful part.
void checkLevel(Shape shape, int level, std::string_view path) {
    if (shape == Shape::Teapot)
        checkTeapotLevel(level, path);
    else
        checkSubdivisionLevel(level, path);
}

void checkSubdivisions(Shape shape, int level, std::string_view path) {
    if (level != kAutoSubdivisions) checkLevel(shape, level, path);
}

// Relative, so that a scene and its models move together (the demo saves the scene as it was spelled);
// the folder it is relative to is the loader's (loadSceneModels).
void checkMeshPath(std::string_view file, std::string_view path) {
    if (file.empty())
        fail(path, "must be a file name such as \"models/thing.obj\" (relative to the scene file), got an "
                   "empty string");
    if (file.find('\0') != std::string_view::npos)
        fail(path, "must be a file name, got " + quotedValue(file) + ", which holds a NUL character");
    if (file.front() == '/')
        fail(path, "must be relative to the scene file's folder, got the absolute path " + quotedValue(file) +
                       "; move the model beside the scene, e.g. \"models/thing.obj\"");
}

void checkSplitLevels(const Scene& scene) {
    if (scene.view.kind != ViewKind::Split) return;
    const auto teapot = std::find_if(scene.objects.begin(), scene.objects.end(),
                                     [](const SceneObject& o) { return o.shape == Shape::Teapot; });
    if (teapot == scene.objects.end()) return;
    for (const SplitSide* side : {&scene.view.left, &scene.view.right})
        if (side->level && *side->level > kMaxTeapotLevel)
            fail("view", "a side's @" + std::to_string(*side->level) + " is beyond the teapot's levels " +
                             toString(levelRange(Shape::Teapot)) + " (" +
                             indexPath("objects", std::size_t(teapot - scene.objects.begin())) +
                             " is a teapot); use @" + std::to_string(kMaxTeapotLevel) + " or lower");
}

} // namespace shadelab::detail
