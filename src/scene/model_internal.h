// What the model readers share (scene/model.h): the raw arrays a file gives, checked and completed in one
// place (finishModel), and the rule for a name a model refers to.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "shadelab/scene/model.h"

namespace shadelab::detail {

// A file's triangles as read: positions, one normal per position or none, corner indices (each reader
// checks its own indices, naming the line or accessor; finishModel checks them again, without a place).
struct RawMesh {
    std::vector<glm::dvec3> positions;
    std::vector<glm::dvec3> normals; // empty, or one per position
    std::vector<glm::uvec3> triangles;
    std::optional<Material> material;
};

// Checks and completes a raw mesh into a model: every value finite, every index in range, at most
// kMaxModelVertices vertices, zero-area triangles dropped (their count reported by the caller's message
// when none is left), face normals, and vertex normals made area-weighted where the file has none.
// Throws InputError "<name>: <origin>: <what>; <fix>".
Model finishModel(RawMesh raw, std::string_view name);

// A name a model refers to (mtllib, a glTF buffer's uri) must stay in the model's folder: relative, no ".."
// component, no drive or scheme. Returns the reason it does not, or nothing.
std::optional<std::string> outsideTheFolder(std::string_view relativeName);

// The side files' reader as the model's parser calls it: the bytes, or InputError naming `field` (a line or
// a JSON path) and the file.
std::string readSideFile(SideFileReader reader, void* context, std::string_view relativeName,
                         std::string_view name, std::string_view field);

Model parseObj(std::string_view text, std::string_view name, SideFileReader sideFile, void* context);
Model parseGltf(std::string_view bytes, std::string_view name, bool binary, SideFileReader sideFile,
                void* context);

} // namespace shadelab::detail
