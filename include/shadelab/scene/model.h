// Meshes read from files (docs/DESIGN.md §1, "Meshes from files"): Wavefront OBJ with its MTL materials
// (Debian's tinyobjloader) and glTF 2.0, .gltf or .glb (Debian's tinygltf). A model has no analytic
// surface: its reference is per-fragment lighting of its own interpolated normals.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "shadelab/geometry/triangle_mesh.h"
#include "shadelab/scene/scene.h"

namespace shadelab {

struct Model {
    std::string path;                 // the file read, as opened
    TriangleMesh mesh;                // object space as in the file; made normals area-weighted
    std::optional<Material> material; // the file's first material (MTL, or glTF's baseColorFactor)
    bool normalsMade = false;         // the file had no normals
    std::size_t trianglesDropped = 0; // zero-area triangles left out (they have no normal)
};

// The most vertices one model may have, and the largest file read (docs/ci-engineers.md "Limits").
inline constexpr std::size_t kMaxModelVertices = std::size_t(1) << 24;
inline constexpr std::uintmax_t kMaxModelBytes = std::uintmax_t(1) << 30;

// Reads `file` by its extension (.obj, .gltf, .glb). Throws InputError naming the file and the line (OBJ)
// or the JSON path / accessor (glTF), what is wrong and the fix: out-of-range indices, NaN or Inf, zero-area
// or degenerate input, no triangles, too many vertices, a folder, FIFO or device, a mtllib or buffer uri
// outside the model's folder, a data: URI that is not base64.
std::shared_ptr<const Model> loadModel(const std::filesystem::path& file);

// The same from bytes in memory (the page's dropped files, the fuzzer): `name` decides the format by its
// extension and names the file in messages; `sideFile` returns the bytes of a file the model refers to (an
// MTL, a glTF buffer) by its name relative to the model, or nothing when there is none.
using SideFileReader = std::optional<std::string> (*)(void* context, std::string_view relativeName);
std::shared_ptr<const Model> parseModel(std::string_view bytes, std::string_view name,
                                        SideFileReader sideFile = nullptr, void* context = nullptr);

// Loads each mesh object's model (paths relative to `sceneFolder`), each file once however many objects
// name it, and gives an object without a "material" of its own the file's material. Throws InputError naming
// the object ("objects[2].mesh: ...").
void loadSceneModels(Scene& scene, const std::filesystem::path& sceneFolder);
// The same, with the models already read kept in `cache` (by path) for the next scene: a lesson's steps.
using ModelCache = std::map<std::string, std::shared_ptr<const Model>>;
void loadSceneModels(Scene& scene, const std::filesystem::path& sceneFolder, ModelCache& cache);

} // namespace shadelab
