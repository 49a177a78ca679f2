// glTF 2.0 (.gltf with embedded or side buffers, .glb), read by Debian's tinygltf: the default scene's
// meshes, each primitive's POSITION, NORMAL and indices, placed by its node's world matrix; a primitive's
// material gives its baseColorFactor as the diffuse colour. tinygltf parses the JSON and decodes the
// buffers; every accessor is checked here against its buffer before a byte is read, naming its JSON path.
// As model_libraries.cpp compiles tinygltf: no image reading or writing.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene/model_internal.h"
#include "shadelab/errors.h"
#include "shadelab/io/text.h"

namespace shadelab::detail {
namespace {

// The side files through the model's reader. tinygltf's callbacks return false on failure; the first
// reason is kept and thrown once tinygltf returns.
struct Files {
    SideFileReader reader;
    void* context;
    std::string_view name;
    std::string error;
};

bool anyFileExists(const std::string&, void*) {
    return true; // readFile says whether it can be read, and why not
}
std::string samePath(const std::string& path, void*) {
    return path;
}
bool readFile(std::vector<unsigned char>* out, std::string* err, const std::string& uri, void* context) {
    auto& files = *static_cast<Files*>(context);
    try {
        if (uri.rfind("data:", 0) == 0)
            throw InputError(printable(files.name) + ": a buffer's data: URI is not base64; write it as "
                                                     "data:application/octet-stream;base64,...");
        const std::string bytes = readSideFile(files.reader, files.context, uri, files.name, "buffers");
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const InputError& e) {
        if (files.error.empty()) files.error = e.what();
        if (err) *err = e.what();
        return false;
    }
}
bool writeNothing(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
    return false;
}
bool ignoreImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
                 void*) {
    return true; // no textures are drawn
}

class Reader {
public:
    Reader(const tinygltf::Model& gltf, std::string_view name) : gltf_(gltf), name_(name) {}

    RawMesh read() {
        const int sceneIndex = gltf_.defaultScene >= 0 ? gltf_.defaultScene : 0;
        if (sceneIndex < int(gltf_.scenes.size())) {
            for (const int node : gltf_.scenes[std::size_t(sceneIndex)].nodes) visit(node, glm::dmat4(1), 0);
        } else {
            for (std::size_t m = 0; m < gltf_.meshes.size(); ++m) addMesh(int(m), glm::dmat4(1));
        }
        if (!hasNormals_) raw_.normals.clear(); // a primitive without normals: all are made (DESIGN §1)
        return std::move(raw_);
    }

private:
    [[noreturn]] void fail(const std::string& path, const std::string& what) const {
        throw InputError(printable(name_) + ": " + path + ": " + what);
    }

    static glm::dmat4 localMatrix(const tinygltf::Node& node) {
        if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());
        glm::dmat4 m(1);
        if (node.translation.size() == 3) m[3] = glm::dvec4(glm::make_vec3(node.translation.data()), 1);
        glm::dmat4 r(1);
        if (node.rotation.size() == 4) {
            const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
            r = glm::dmat4(glm::mat3_cast(glm::normalize(q)));
        }
        glm::dmat4 s(1);
        if (node.scale.size() == 3)
            for (int k = 0; k < 3; ++k) s[k][k] = node.scale[std::size_t(k)];
        return m * r * s;
    }

    void visit(int node, const glm::dmat4& parent, int depth) {
        const std::string path = "nodes[" + std::to_string(node) + "]";
        if (node < 0 || node >= int(gltf_.nodes.size())) fail(path, "no such node");
        if (depth > 64) fail(path, "nodes nested more than 64 deep (a cycle?)");
        // glTF's nodes form trees (a node has one parent at most): a node reached twice would be read again
        // each time, 2^depth times for a chain of nodes each naming the next twice.
        if (visited_.empty()) visited_.assign(gltf_.nodes.size(), false);
        if (visited_[std::size_t(node)])
            fail(path, "is reached twice (two parents, or twice in the scene): glTF's nodes form trees");
        visited_[std::size_t(node)] = true;
        const tinygltf::Node& n = gltf_.nodes[std::size_t(node)];
        const glm::dmat4 world = parent * localMatrix(n);
        if (n.mesh >= 0) addMesh(n.mesh, world);
        for (const int child : n.children) visit(child, world, depth + 1);
    }

    // Accessor `index`'s elements as doubles, `components` each, checked against its view and buffer.
    std::vector<double> elements(int index, const std::string& path, int type, bool indices) const {
        const std::string at = "accessors[" + std::to_string(index) + "]";
        if (index < 0 || index >= int(gltf_.accessors.size()))
            fail(path, "no such accessor " + std::to_string(index));
        const tinygltf::Accessor& a = gltf_.accessors[std::size_t(index)];
        if (a.sparse.isSparse) fail(at, "sparse accessors are not read; write the values out");
        if (a.type != type) fail(at, "has the wrong type for " + path);
        const int component = a.componentType;
        const std::size_t size =
            component == TINYGLTF_COMPONENT_TYPE_FLOAT || component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT
                ? 4
            : component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
            : component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE  ? 1
                                                                  : 0;
        if (size == 0 || indices == (component == TINYGLTF_COMPONENT_TYPE_FLOAT))
            fail(at, indices ? "indices must be unsigned byte, short or int" : "must be float (5126)");
        const std::size_t count = a.count, perElement = type == TINYGLTF_TYPE_VEC3 ? 3 : 1;
        if (a.bufferView < 0 || a.bufferView >= int(gltf_.bufferViews.size()))
            fail(at, "has no buffer view (" + std::to_string(a.bufferView) + ")");
        const tinygltf::BufferView& view = gltf_.bufferViews[std::size_t(a.bufferView)];
        if (view.buffer < 0 || view.buffer >= int(gltf_.buffers.size()))
            fail("bufferViews[" + std::to_string(a.bufferView) + "]", "no such buffer");
        const std::vector<unsigned char>& buffer = gltf_.buffers[std::size_t(view.buffer)].data;
        const std::size_t elementBytes = size * perElement;
        const std::size_t stride = view.byteStride ? view.byteStride : elementBytes;
        if (stride < elementBytes) fail(at, "its view's byteStride is smaller than an element");
        const auto need = [&](std::size_t n) {
            return n == 0 ? 0 : a.byteOffset + stride * (n - 1) + elementBytes;
        };
        if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
            fail("bufferViews[" + std::to_string(a.bufferView) + "]",
                 "reaches past its buffer (" + std::to_string(buffer.size()) + " bytes)");
        // Checked alone first: a byteOffset near 2^64 would wrap need() around to a small number.
        if (a.byteOffset > view.byteLength)
            fail(at, "byteOffset " + std::to_string(a.byteOffset) + " is past its buffer view (" +
                         std::to_string(view.byteLength) + " bytes)");
        if (count > view.byteLength || need(count) > view.byteLength)
            fail(at, "count " + std::to_string(count) + " reaches past its buffer view (" +
                         std::to_string(view.byteLength) + " bytes)");
        std::vector<double> out(count * perElement);
        const unsigned char* base = buffer.data() + view.byteOffset + a.byteOffset;
        for (std::size_t e = 0; e < count; ++e)
            for (std::size_t k = 0; k < perElement; ++k) {
                const unsigned char* p = base + e * stride + k * size;
                double value = 0;
                if (component == TINYGLTF_COMPONENT_TYPE_FLOAT) {
                    float f;
                    std::memcpy(&f, p, 4);
                    if (!std::isfinite(f))
                        fail(at, "element " + std::to_string(e) + " is not a finite number");
                    value = f;
                } else if (size == 4) {
                    std::uint32_t u;
                    std::memcpy(&u, p, 4);
                    value = u;
                } else if (size == 2) {
                    std::uint16_t u;
                    std::memcpy(&u, p, 2);
                    value = u;
                } else {
                    value = *p;
                }
                out[e * perElement + k] = value;
            }
        return out;
    }

    void addMesh(int meshIndex, const glm::dmat4& worldFromMesh) {
        const std::string meshPath = "meshes[" + std::to_string(meshIndex) + "]";
        if (meshIndex < 0 || meshIndex >= int(gltf_.meshes.size())) fail(meshPath, "no such mesh");
        const glm::dmat3 linear(worldFromMesh);
        const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(linear));
        const auto& primitives = gltf_.meshes[std::size_t(meshIndex)].primitives;
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = primitives[p];
            const std::string path = meshPath + ".primitives[" + std::to_string(p) + "]";
            if (primitive.mode != -1 && primitive.mode != TINYGLTF_MODE_TRIANGLES) continue; // points, lines
            const auto position = primitive.attributes.find("POSITION");
            if (position == primitive.attributes.end()) fail(path, "has no POSITION attribute");
            const std::vector<double> positions =
                elements(position->second, path + ".attributes.POSITION", TINYGLTF_TYPE_VEC3, false);
            const std::size_t first = raw_.positions.size(), count = positions.size() / 3;
            // Checked as the vertices are added (finishModel checks the sum too late): primitives or nodes
            // naming one accessor many times would otherwise grow the arrays without bound.
            if (count > kMaxModelVertices - std::min(first, kMaxModelVertices))
                fail(path,
                     "more than " + std::to_string(kMaxModelVertices) +
                         " vertices in all; at most that many are allowed: decimate or split the model");
            for (std::size_t v = 0; v < count; ++v)
                raw_.positions.push_back(
                    glm::dvec3(worldFromMesh *
                               glm::dvec4(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2], 1)));
            const auto normal = primitive.attributes.find("NORMAL");
            hasNormals_ = hasNormals_ && normal != primitive.attributes.end();
            if (normal != primitive.attributes.end()) {
                const std::vector<double> normals =
                    elements(normal->second, path + ".attributes.NORMAL", TINYGLTF_TYPE_VEC3, false);
                if (normals.size() != positions.size()) fail(path, "NORMAL and POSITION counts differ");
                for (std::size_t v = 0; v < count; ++v)
                    raw_.normals.push_back(
                        normalMatrix * glm::dvec3(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]));
            }
            std::vector<double> indices;
            if (primitive.indices >= 0) {
                indices = elements(primitive.indices, path + ".indices", TINYGLTF_TYPE_SCALAR, true);
            } else {
                indices.resize(count);
                for (std::size_t v = 0; v < count; ++v) indices[v] = double(v);
            }
            if (indices.size() % 3 != 0)
                fail(path, "TRIANGLES needs a multiple of 3 indices, got " + std::to_string(indices.size()));
            for (std::size_t i = 0; i < indices.size(); ++i)
                if (indices[i] >= double(count))
                    fail(path + ".indices", "index " + formatIndex(indices[i]) + " is out of range (" +
                                                std::to_string(count) + " vertices)");
            // A mirroring node turns counter-clockwise triangles clockwise: wound back.
            const bool mirrored = glm::determinant(linear) < 0;
            for (std::size_t i = 0; i < indices.size(); i += 3) {
                const auto a = glm::uint(first + std::size_t(indices[i]));
                const auto b = glm::uint(first + std::size_t(indices[i + 1]));
                const auto c = glm::uint(first + std::size_t(indices[i + 2]));
                raw_.triangles.emplace_back(a, mirrored ? c : b, mirrored ? b : c);
            }
            if (!raw_.material && primitive.material >= 0 &&
                primitive.material < int(gltf_.materials.size())) {
                const std::vector<double>& base =
                    gltf_.materials[std::size_t(primitive.material)].pbrMetallicRoughness.baseColorFactor;
                Material material;
                if (base.size() >= 3) material.diffuse = {base[0], base[1], base[2]};
                raw_.material = material;
            }
        }
    }

    static std::string formatIndex(double value) { return std::to_string(std::uint64_t(value)); }

    const tinygltf::Model& gltf_;
    std::string_view name_;
    RawMesh raw_;
    bool hasNormals_ = true;    // every primitive so far has NORMAL
    std::vector<bool> visited_; // per node: read already
};

} // namespace

Model parseGltf(std::string_view bytes, std::string_view name, bool binary, SideFileReader sideFile,
                void* context) {
    if (bytes.size() > 0xffffffffu) throw InputError(printable(name) + ": larger than 4 GiB");
    Files files{sideFile, context, name, {}};
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&anyFileExists, &samePath, &readFile, &writeNothing, &files});
    loader.SetImageLoader(&ignoreImage, nullptr);
    tinygltf::Model gltf;
    std::string err, warn;
    const bool read =
        binary ? loader.LoadBinaryFromMemory(&gltf, &err, &warn,
                                             reinterpret_cast<const unsigned char*>(bytes.data()),
                                             unsigned(bytes.size()), "")
               : loader.LoadASCIIFromString(&gltf, &err, &warn, bytes.data(), unsigned(bytes.size()), "");
    if (!files.error.empty()) throw InputError(files.error);
    if (!read)
        throw InputError(printable(name) + ": " + printable(err.empty() ? "not a glTF 2.0 file" : err));
    return finishModel(Reader(gltf, name).read(), name);
}

} // namespace shadelab::detail
