// libFuzzer target for the model readers (shadelab/scene/model.h). The first byte picks the format (.obj,
// .gltf, .glb), the rest are the file's bytes. The one side file there is: "m.mtl" (a small material) beside
// an OBJ, "b.bin" (one triangle's positions, normals and indices) beside a glTF; any other name cannot be
// read, as a missing file. parseModel either returns a model or throws InputError; anything else (another
// exception, a sanitizer report, a hang) is a crash. A model it returns keeps what finishModel promises: at
// least one triangle, every index in range, finite positions, unit normals, a face normal per triangle and a
// vertex normal per vertex, at most kMaxModelVertices vertices.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <optional>
#include <string>
#include <string_view>

#include "shadelab/errors.h"
#include "shadelab/scene/model.h"

namespace {

using namespace shadelab;

[[noreturn]] void crash(std::string_view what, std::string_view detail) {
    std::fprintf(stderr, "model_fuzzer: %.*s: %.*s\n", int(what.size()), what.data(), int(detail.size()),
                 detail.data());
    std::abort();
}

constexpr const char* kNames[] = {"fuzz.obj", "fuzz.gltf", "fuzz.glb"};

// Three float VEC3 positions, three float VEC3 normals, three uint32 indices: 84 bytes, as a seed's
// bufferViews 0 (0..35), 1 (36..71) and 2 (72..83) read them.
std::string triangleBuffer() {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const float normals[9] = {0, 0, 1, 0, 0, 1, 0, 0, 1};
    const std::uint32_t indices[3] = {0, 1, 2};
    std::string bytes(sizeof positions + sizeof normals + sizeof indices, '\0');
    std::memcpy(bytes.data(), positions, sizeof positions);
    std::memcpy(bytes.data() + sizeof positions, normals, sizeof normals);
    std::memcpy(bytes.data() + sizeof positions + sizeof normals, indices, sizeof indices);
    return bytes;
}

std::optional<std::string> sideFile(void* context, std::string_view relativeName) {
    const bool obj = *static_cast<const bool*>(context);
    if (obj && relativeName == "m.mtl")
        return std::string("newmtl red\nKa 0.1 0 0\nKd 0.8 0.1 0.1\nKs 0.5 0.5 0.5\nNs 32\n");
    if (!obj && relativeName == "b.bin") return triangleBuffer();
    return std::nullopt;
}

bool unit(const glm::dvec3& n) {
    return std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z) &&
           std::abs(glm::length(n) - 1) < 1e-9;
}

void checkModel(const Model& model) {
    const TriangleMesh& mesh = model.mesh;
    if (mesh.triangles.empty()) crash("an accepted model without triangles", model.path);
    if (mesh.positions.size() > kMaxModelVertices) crash("more than kMaxModelVertices vertices", model.path);
    if (mesh.faceNormals.size() != mesh.triangles.size())
        crash("not one face normal per triangle", model.path);
    if (mesh.vertexNormals.size() != mesh.positions.size())
        crash("not one vertex normal per vertex", model.path);
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            if (t[k] >= mesh.positions.size()) crash("a vertex index out of range", std::to_string(t[k]));
    for (const glm::dvec3& p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            crash("a position that is not finite", model.path);
    for (const glm::dvec3& n : mesh.faceNormals)
        if (!unit(n)) crash("a face normal that is not a unit vector", model.path);
    for (const glm::dvec3& n : mesh.vertexNormals)
        if (!unit(n)) crash("a vertex normal that is not a unit vector", model.path);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::size_t format = data[0] % 3;
    bool obj = format == 0;
    const std::string_view bytes(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        checkModel(*parseModel(bytes, kNames[format], &sideFile, &obj));
    } catch (const InputError&) {
        // The expected refusal of bad input.
    } catch (const std::exception& e) {
        crash("an exception other than InputError", e.what());
    } catch (...) {
        crash("an exception other than InputError", "(not a std::exception)");
    }
    return 0;
}
