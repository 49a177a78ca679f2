// Models from files (scene/model.h, DESIGN §1 "Meshes from files"): OBJ with MTL, glTF and GLB read to the
// same mesh; the file's material and a scene's own; normals made area-weighted; every kind of bad input
// refused with the file and the line or JSON path; what may be opened; a scene's models read once.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "input_error.h"
#include "shadelab/errors.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/scene/model.h"
#include "shadelab/scene/scene.h"

namespace shadelab {
namespace {

namespace fs = std::filesystem;

std::string number(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

// The level-2 sphere with its exact normals, as an OBJ with one normal per position.
std::string sphereObj(const SphereMesh& mesh, const std::string& header = "") {
    std::string text = header;
    for (const glm::dvec3& p : mesh.positions)
        text += "v " + number(p.x) + " " + number(p.y) + " " + number(p.z) + "\n";
    for (const glm::dvec3& n : mesh.vertexNormals)
        text += "vn " + number(n.x) + " " + number(n.y) + " " + number(n.z) + "\n";
    for (const glm::uvec3& t : mesh.triangles)
        text += "f " + std::to_string(t.x + 1) + "//" + std::to_string(t.x + 1) + " " +
                std::to_string(t.y + 1) + "//" + std::to_string(t.y + 1) + " " + std::to_string(t.z + 1) +
                "//" + std::to_string(t.z + 1) + "\n";
    return text;
}

std::string base64(const std::string& bytes) {
    static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t a = std::uint8_t(bytes[i]),
                            b = i + 1 < bytes.size() ? std::uint8_t(bytes[i + 1]) : 0,
                            c = i + 2 < bytes.size() ? std::uint8_t(bytes[i + 2]) : 0;
        const std::uint32_t triple = (a << 16) | (b << 8) | c;
        out += kDigits[(triple >> 18) & 63];
        out += kDigits[(triple >> 12) & 63];
        out += i + 1 < bytes.size() ? kDigits[(triple >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kDigits[triple & 63] : '=';
    }
    return out;
}

template <class T> void append(std::string& bytes, T value) {
    bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// The same mesh as glTF: float positions and normals, 32-bit indices, one buffer; `uri` is the buffer's
// (a data URI, or a side file's name); baseColorFactor gives the diffuse colour.
struct Gltf {
    std::string json, buffer;
};
Gltf sphereGltf(const SphereMesh& mesh, const std::string& uri = "") {
    Gltf out;
    for (const glm::dvec3& p : mesh.positions)
        for (int k = 0; k < 3; ++k) append(out.buffer, float(p[k]));
    for (const glm::dvec3& n : mesh.vertexNormals)
        for (int k = 0; k < 3; ++k) append(out.buffer, float(n[k]));
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) append(out.buffer, std::uint32_t(t[k]));
    const std::size_t v = mesh.positions.size(), i = mesh.triangles.size() * 3;
    const std::string bufferUri =
        uri.empty() ? "data:application/octet-stream;base64," + base64(out.buffer) : uri;
    out.json =
        R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
      "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.25, 0.5, 0.75, 1]}}],
      "buffers": [{"byteLength": )" +
        std::to_string(out.buffer.size()) + R"(, "uri": ")" + bufferUri + R"("}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" +
        std::to_string(12 * v) + R"(},
                      {"buffer": 0, "byteOffset": )" +
        std::to_string(12 * v) + R"(, "byteLength": )" + std::to_string(12 * v) + R"(},
                      {"buffer": 0, "byteOffset": )" +
        std::to_string(24 * v) + R"(, "byteLength": )" + std::to_string(4 * i) + R"(}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
        std::to_string(v) + R"(, "type": "VEC3",
                     "min": [-1, -1, -1], "max": [1, 1, 1]},
                    {"bufferView": 1, "componentType": 5126, "count": )" +
        std::to_string(v) + R"(, "type": "VEC3"},
                    {"bufferView": 2, "componentType": 5125, "count": )" +
        std::to_string(i) + R"(, "type": "SCALAR"}]})";
    return out;
}

std::string glb(const std::string& json, const std::string& buffer) {
    std::string j = json, b = buffer;
    while (j.size() % 4) j += ' ';
    while (b.size() % 4) b += '\0';
    std::string out;
    append(out, std::uint32_t(0x46546C67));
    append(out, std::uint32_t(2));
    append(out, std::uint32_t(12 + 8 + j.size() + 8 + b.size()));
    append(out, std::uint32_t(j.size()));
    append(out, std::uint32_t(0x4E4F534A));
    out += j;
    append(out, std::uint32_t(b.size()));
    append(out, std::uint32_t(0x004E4942));
    out += b;
    return out;
}

// Side files served from a map, as the page serves dropped files.
using Files = std::map<std::string, std::string>;
std::optional<std::string> fromMap(void* context, std::string_view name) {
    const Files& files = *static_cast<const Files*>(context);
    const auto found = files.find(std::string(name));
    if (found == files.end()) return std::nullopt;
    return found->second;
}
std::shared_ptr<const Model> parse(const std::string& bytes, const std::string& name, Files files = {}) {
    return parseModel(bytes, name, &fromMap, &files);
}

// The same triangles, corner by corner, whatever the vertices' numbering (a reader numbers them as the
// file's corners first use them).
void expectSameMesh(const TriangleMesh& a, const TriangleMesh& b, double tolerance) {
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    for (std::size_t t = 0; t < a.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const unsigned va = a.triangles[t][k], vb = b.triangles[t][k];
            EXPECT_LE(glm::length(a.positions[va] - b.positions[vb]), tolerance) << t;
            EXPECT_LE(glm::length(a.vertexNormals[va] - b.vertexNormals[vb]), tolerance) << t;
        }
}

std::string refusal(const std::string& bytes, const std::string& name, Files files = {}) {
    return test::inputErrorOf([&] { (void)parse(bytes, name, files); });
}

class TempFolder {
public:
    TempFolder()
        : path_(fs::temp_directory_path() /
                ("shadelab-model-" + std::to_string(::getpid()) + "-" + std::to_string(counter_++))) {
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempFolder() { fs::remove_all(path_); }
    const fs::path& path() const { return path_; }
    fs::path write(const std::string& name, const std::string& bytes) const {
        const fs::path file = path_ / name;
        fs::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary) << bytes;
        return file;
    }

private:
    static inline int counter_ = 0;
    fs::path path_;
};

TEST(Model, ObjGltfAndGlbReadTheSameMesh) {
    const SphereMesh sphere = buildSphere(2, VertexNormals::Exact);
    const auto obj = parse(sphereObj(sphere), "sphere.obj");
    // Written with 17 digits; tinyobjloader's number parser is not correctly rounded (1 ulp).
    expectSameMesh(obj->mesh, sphere, 1e-15);
    EXPECT_FALSE(obj->normalsMade);
    const Gltf gltf = sphereGltf(sphere);
    const auto embedded = parse(gltf.json, "sphere.gltf");
    expectSameMesh(embedded->mesh, obj->mesh, 1e-7); // glTF stores float
    const Gltf side = sphereGltf(sphere, "sphere.bin");
    expectSameMesh(parse(side.json, "sphere.gltf", {{"sphere.bin", side.buffer}})->mesh, obj->mesh, 1e-7);
    // A GLB's own binary chunk: the buffer without a uri.
    std::string json = gltf.json;
    const std::size_t at = json.find(", \"uri\": \"");
    json.erase(at, json.find('"', at + 10) + 1 - at);
    expectSameMesh(parse(glb(json, gltf.buffer), "sphere.glb")->mesh, obj->mesh, 1e-7);
    ASSERT_TRUE(embedded->material);
    EXPECT_EQ(embedded->material->diffuse, glm::dvec3(0.25, 0.5, 0.75));
    EXPECT_EQ(embedded->material->specular, Material{}.specular); // the rest: the defaults
}

TEST(Model, TheMtlGivesTheMaterial) {
    const SphereMesh sphere = buildSphere(1, VertexNormals::Exact);
    const std::string mtl = "newmtl clay\nKa 0.1 0.2 0.3\nKd 0.4 0.5 0.6\nKs 0.7 0.8 0.9\nNs 64\n";
    const auto model =
        parse(sphereObj(sphere, "mtllib clay.mtl\nusemtl clay\n"), "clay.obj", {{"clay.mtl", mtl}});
    ASSERT_TRUE(model->material);
    const Material expected{{0.1, 0.2, 0.3}, {0.4, 0.5, 0.6}, {0.7, 0.8, 0.9}, 64};
    EXPECT_LE(glm::length(model->material->ambient - expected.ambient), 1e-15); // 1 ulp: see above
    EXPECT_LE(glm::length(model->material->diffuse - expected.diffuse), 1e-15);
    EXPECT_LE(glm::length(model->material->specular - expected.specular), 1e-15);
    EXPECT_EQ(model->material->shininess, 64);
    const auto matte =
        parse(sphereObj(sphere, "mtllib m.mtl\nusemtl m\n"), "m.obj", {{"m.mtl", "newmtl m\nNs 0\n"}});
    EXPECT_EQ(matte->material->shininess, 1); // Ns 0, common in exported files: the lowest shininess
}

// Made normals weigh each face by its area: at the corner two faces share, a large face (area 2) and a
// small one (area 0.005) at right angles give a normal near the large face's, not halfway.
TEST(Model, MadeNormalsAreAreaWeighted) {
    const std::string obj = "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0 0 0.1\nv 0 0.1 0\n"
                            "f 1 2 3\nf 1 4 5\n";
    const auto model = parse(obj, "corner.obj");
    EXPECT_TRUE(model->normalsMade);
    const glm::dvec3 large(0, 0, 1), small(-1, 0, 0);
    const glm::dvec3 expected = glm::normalize(2.0 * 2 * large + 2.0 * 0.005 * small);
    const auto& positions = model->mesh.positions;
    const std::size_t shared =
        std::size_t(std::find(positions.begin(), positions.end(), glm::dvec3(0)) - positions.begin());
    ASSERT_LT(shared, positions.size());
    EXPECT_LE(glm::length(model->mesh.vertexNormals[shared] - expected), 1e-12);
    EXPECT_GT(glm::length(model->mesh.vertexNormals[shared] - glm::normalize(large + small)), 0.5);
}

// A zero-area triangle (two corners alike, or three in a line) has no normal: it is left out and counted.
TEST(Model, ZeroAreaTrianglesAreDroppedAndCounted) {
    const auto model = parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 1 3\nf 1 2 4\n", "some.obj");
    ASSERT_EQ(model->mesh.triangles.size(), 1u);
    const glm::uvec3 kept = model->mesh.triangles[0];
    EXPECT_EQ(kept, glm::uvec3(0, 1, 2)); // numbered as the corners first use them, on every compiler
    EXPECT_EQ(model->mesh.positions[kept.x], glm::dvec3(0, 0, 0));
    EXPECT_EQ(model->mesh.positions[kept.y], glm::dvec3(1, 0, 0));
    EXPECT_EQ(model->mesh.positions[kept.z], glm::dvec3(0, 1, 0));
    EXPECT_EQ(model->trianglesDropped, 2u);
    EXPECT_EQ(model->mesh.faceNormals.size(), 1u);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(model->mesh.vertexNormals[kept[k]], glm::dvec3(0, 0, 1)) << k;

    // The scene's warnings say so, naming the object and the file.
    Scene scene;
    scene.objects.resize(2);
    scene.objects[1].model = model;
    const std::vector<std::string> warnings = sceneWarnings(scene);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0],
              "objects[1].mesh: 2 zero-area triangles of some.obj left out (they have no normal)");
}

// A glTF mesh is placed by its node's world matrix: the parent's times the child's translation · rotation ·
// scale, in that order; normals by the inverse transpose (a non-uniform scale tells it from the matrix
// itself); a mirroring scale turns the winding back to counter-clockwise seen from outside.
TEST(Model, GltfNodesPlaceTheirMeshes) {
    const SphereMesh sphere = buildSphere(1, VertexNormals::Exact);
    std::string json = sphereGltf(sphere).json;
    const std::string node = R"("nodes": [{"mesh": 0}])";
    json.replace(json.find(node), node.size(),
                 R"("nodes": [{"children": [1], "translation": [1, 2, 3]},
                              {"mesh": 0, "rotation": [0, 0, 0.70710678118654752, 0.70710678118654752],
                               "scale": [2, 1, -0.5]}])");
    const auto model = parse(json, "placed.gltf");
    // Scaled by (2, 1, -0.5), a quarter turn about z ((x, y) to (-y, x)), moved by (1, 2, 3).
    TriangleMesh expected;
    for (const glm::dvec3& p : sphere.positions)
        expected.positions.emplace_back(1 - p.y, 2 + 2 * p.x, 3 - 0.5 * p.z);
    for (const glm::dvec3& n : sphere.vertexNormals)
        expected.vertexNormals.push_back(glm::normalize(glm::dvec3(-n.y, n.x / 2, -2 * n.z)));
    for (const glm::uvec3& t : sphere.triangles) expected.triangles.emplace_back(t.x, t.z, t.y);
    expectSameMesh(model->mesh, expected, 1e-6); // glTF stores float
    for (std::size_t t = 0; t < model->mesh.triangles.size(); ++t) {
        const glm::uvec3 c = model->mesh.triangles[t];
        const glm::dvec3 centroid =
            (model->mesh.positions[c.x] + model->mesh.positions[c.y] + model->mesh.positions[c.z]) / 3.0;
        EXPECT_GT(glm::dot(model->mesh.faceNormals[t], centroid - glm::dvec3(1, 2, 3)), 0) << t; // outward
    }
}

TEST(Model, BadObjIsRefusedWithTheFileAndTheLine) {
    const std::string cube = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    struct Case {
        std::string text, pieces[2];
    };
    const Case cases[] = {
        {cube + "f 1 2 4\n", {"bad.obj: line 4:", "vertex index 4 is out of range (3 vertices"}},
        {cube + "f 0 1 2\n", {"bad.obj: line 4:", "vertex index 0 is out of range"}},
        {cube + "f 1 2 -4\n", {"bad.obj: line 4:", "index -4 is out of range"}},
        {"v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", {"bad.obj: line 2:", "\"nan\" is not a finite number"}},
        {"v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n", {"bad.obj: line 2:", "not a finite number"}},
        {"v 0 0 0\nv 1 0\n", {"bad.obj: line 2:", "needs 3 numbers, got 2"}},
        {cube + "f 1 2\n", {"bad.obj: line 4:", "a face needs at least 3 corners"}},
        {cube + "f 1 1 2\n", {"bad.obj:", "no triangle has an area"}},
        {"v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", {"bad.obj:", "all 1 are degenerate"}},
        {cube, {"bad.obj:", "no triangles"}},
        {"mtllib ../secret.mtl\n" + cube + "f 1 2 3\n", {"bad.obj: line 1:", "leaves the model's folder"}},
        {"mtllib /etc/passwd\n" + cube + "f 1 2 3\n", {"bad.obj: line 1:", "is an absolute path"}},
        {"mtllib missing.mtl\n" + cube + "f 1 2 3\n", {"bad.obj: line 1:", "cannot read \"missing.mtl\""}},
        {cube + "vn 0 0 0\nf 1//1 2//1 3//1\n", {"bad.obj:", "a vertex normal is zero"}},
        {cube + "vn 0 0 1\nf 1//1 2//1 3//2\n", {"bad.obj: line 5:", "normal index 2 is out of range"}},
        // Found by the model fuzzer: tinyobjloader reads an empty index after '/' from the next corner, and
        // ends a line at a lone CR, where a check that split at LF alone saw one line.
        {cube + "vn 0 0 1\nf 1// 2// 3//1\n", {"bad.obj: line 5:", "ends with '/'"}},
        {"v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 9\r", {"bad.obj: line 4:", "vertex index 9 is out of range"}},
    };
    for (const Case& c : cases) {
        const std::string message = refusal(c.text, "bad.obj");
        for (const std::string& piece : c.pieces)
            EXPECT_NE(message.find(piece), std::string::npos) << message;
    }
}

TEST(Model, BadGltfIsRefusedWithItsJsonPath) {
    const SphereMesh sphere = buildSphere(0, VertexNormals::Exact);
    const Gltf good = sphereGltf(sphere);
    auto with = [&](const std::string& from, const std::string& to) {
        std::string json = good.json;
        const std::size_t at = json.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return json.replace(at, from.size(), to);
    };
    struct Case {
        std::string json, pieces[2];
    };
    const Case cases[] = {
        {with("\"count\": 12, \"type\": \"SCALAR\"", "\"count\": 13, \"type\": \"SCALAR\""),
         {"bad.gltf: accessors[2]:", "count 13 reaches past its buffer view (48 bytes)"}},
        {with("\"indices\": 2", "\"indices\": 7"), {"bad.gltf:", "indices accessor out of bounds"}},
        {with("\"componentType\": 5125", "\"componentType\": 5126"),
         {"bad.gltf: accessors[2]:", "indices must be"}},
        {with("data:application/octet-stream;base64,", "data:text/plain,"), {"bad.gltf:", "is not base64"}},
        {sphereGltf(sphere, "../outside.bin").json, {"bad.gltf: buffers:", "leaves the model's folder"}},
        {sphereGltf(sphere, "missing.bin").json, {"bad.gltf: buffers:", "cannot read \"missing.bin\""}},
        {"{\"asset\": {\"version\": \"2.0\"}}", {"bad.gltf:", "no triangles"}},
        {"not json", {"bad.gltf:", ""}},
        // Found by reading the reader: an offset near 2^64 wrapped the bounds' sum to a small number.
        {with("\"bufferView\": 2, \"componentType\": 5125",
              "\"bufferView\": 2, \"byteOffset\": 18446744073709551604, \"componentType\": 5125"),
         {"bad.gltf: accessors[2]:", "byteOffset 18446744073709551604 is past its buffer view"}},
        // A node reached twice (each of a chain naming the next twice is 2^depth visits).
        {with("\"nodes\": [{\"mesh\": 0}]",
              "\"nodes\": [{\"mesh\": 0, \"children\": [1, 1]}, {\"mesh\": 0}]"),
         {"bad.gltf: nodes[1]:", "is reached twice"}},
    };
    for (const Case& c : cases) {
        const std::string message = refusal(c.json, "bad.gltf");
        for (const std::string& piece : c.pieces)
            EXPECT_NE(message.find(piece), std::string::npos) << message;
    }
    // An index past the vertices, in range of its buffer: bytes of the index buffer changed.
    std::string buffer = good.buffer;
    const std::uint32_t past = 99;
    std::memcpy(buffer.data() + 24 * sphere.positions.size(), &past, 4);
    const std::string message =
        refusal(with(good.json.substr(good.json.find("data:"),
                                      good.json.find('"', good.json.find("data:")) - good.json.find("data:")),
                     "data:application/octet-stream;base64," + base64(buffer)),
                "bad.gltf");
    EXPECT_NE(message.find("meshes[0].primitives[0].indices: index 99 is out of range (4 vertices)"),
              std::string::npos)
        << message;
}

TEST(Model, OnlyRegularFilesInTheModelsFolderAreOpened) {
    const TempFolder folder;
    EXPECT_NE(test::inputErrorOf([&] { (void)loadModel(folder.path()); }).find("is a folder"),
              std::string::npos);
    EXPECT_NE(test::inputErrorOf([&] { (void)loadModel(folder.path() / "none.obj"); }).find("no such file"),
              std::string::npos);
    const fs::path fifo = folder.path() / "pipe.obj";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    // Refused from its type, before it is opened: opening a FIFO nobody writes would block. Read in a child
    // with an alarm, so that a reader that opened it fails this test in 5 s instead of hanging it.
    EXPECT_EXIT(
        {
            ::alarm(5);
            const std::string message = test::inputErrorOf([&] { (void)loadModel(fifo); });
            std::fputs(message.c_str(), stderr);
            std::exit(0);
        },
        ::testing::ExitedWithCode(0), "pipe.obj: is not a regular file");
    EXPECT_NE(test::inputErrorOf([&] { (void)loadModel("/dev/null"); }).find("not a regular file"),
              std::string::npos);
    // A side file that is a link out of the folder.
    const TempFolder outside;
    outside.write("secret.mtl", "newmtl s\nKd 1 0 0\n");
    fs::create_symlink(outside.path() / "secret.mtl", folder.path() / "link.mtl");
    const fs::path obj = folder.write("linked.obj", "mtllib link.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_NE(test::inputErrorOf([&] { (void)loadModel(obj); }).find("leads out of the model's folder"),
              std::string::npos);
    // Beside it, the same MTL is read.
    folder.write("here.mtl", "newmtl s\nKd 1 0 0\n");
    const auto model =
        loadModel(folder.write("here.obj", "mtllib here.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    EXPECT_EQ(model->material->diffuse, glm::dvec3(1, 0, 0));
}

TEST(Model, ASceneReadsEachFileOnceAndItsOwnMaterialWins) {
    const TempFolder folder;
    folder.write("models/tri.mtl", "newmtl m\nKd 0 1 0\n");
    folder.write("models/tri.obj", "mtllib tri.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    Scene scene = parseScene(R"({"objects": [{"mesh": "models/tri.obj"}, {"mesh": "models/tri.obj",
        "material": {"diffuse": [1, 0, 0]}}, {"mesh": "models/none.obj"}]})");
    const SceneObject third = scene.objects[2];
    scene.objects.pop_back();
    loadSceneModels(scene, folder.path());
    ASSERT_TRUE(scene.objects[0].model);
    EXPECT_EQ(scene.objects[0].model, scene.objects[1].model);         // one file, read once
    EXPECT_EQ(scene.objects[0].material.diffuse, glm::dvec3(0, 1, 0)); // the file's
    EXPECT_EQ(scene.objects[1].material.diffuse, glm::dvec3(1, 0, 0)); // the scene's own
    EXPECT_NO_THROW(validateScene(scene));
    scene.objects.push_back(third);
    const std::string message = test::inputErrorOf([&] { loadSceneModels(scene, folder.path()); });
    EXPECT_NE(message.find("objects[2].mesh: "), std::string::npos) << message;
    EXPECT_NE(message.find("none.obj: cannot read: no such file"), std::string::npos) << message;
}

} // namespace
} // namespace shadelab
