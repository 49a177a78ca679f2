// The bundled models/ folder (models/README.md): every model in it loads; the sphere's OBJ, glTF and GLB
// give one mesh, DESIGN §1's level-3 sphere with its exact normals; the cube is closed and its MTL gives its
// material; the torus gets made normals; and scripts/make_models.py writes the folder byte for byte, so a
// stale or hand-edited file fails here.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "shadelab/geometry/sphere.h"
#include "shadelab/scene/model.h"

namespace shadelab {
namespace {

namespace fs = std::filesystem;

const fs::path kRoot = fs::path(SHADELAB_TEST_DATA) / "..";
const fs::path kModels = kRoot / "models";

std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool isModel(const fs::path& file) {
    const std::string extension = file.extension().string();
    return extension == ".obj" || extension == ".gltf" || extension == ".glb";
}

// The same triangles, corner by corner: positions and vertex normals within `tolerance`.
void expectSameMesh(const TriangleMesh& a, const TriangleMesh& b, double tolerance) {
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    for (std::size_t t = 0; t < a.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const unsigned va = a.triangles[t][k], vb = b.triangles[t][k];
            ASSERT_LE(glm::length(a.positions[va] - b.positions[vb]), tolerance) << "triangle " << t;
            ASSERT_LE(glm::length(a.vertexNormals[va] - b.vertexNormals[vb]), tolerance) << "triangle " << t;
        }
}

TEST(ModelsFolder, EveryModelLoads) {
    std::set<std::string> loaded;
    for (const fs::directory_entry& entry : fs::directory_iterator(kModels)) {
        if (!isModel(entry.path())) continue;
        SCOPED_TRACE(entry.path().string());
        const std::shared_ptr<const Model> model = loadModel(entry.path());
        EXPECT_FALSE(model->mesh.triangles.empty());
        loaded.insert(entry.path().filename().string());
    }
    EXPECT_EQ(loaded,
              (std::set<std::string>{"cube.obj", "sphere.glb", "sphere.gltf", "sphere.obj", "torus.obj"}));
}

// OBJ numbers are written to read back exactly; tinyobjloader's parser is up to an ulp off correct rounding.
TEST(ModelsFolder, SphereObjIsTheLevel3SphereWithExactNormals) {
    const std::shared_ptr<const Model> obj = loadModel(kModels / "sphere.obj");
    const SphereMesh sphere = buildSphere(3, VertexNormals::Exact);
    EXPECT_FALSE(obj->normalsMade);
    EXPECT_EQ(obj->mesh.positions.size(), sphere.positions.size());
    expectSameMesh(obj->mesh, sphere, 1e-15);
}

// glTF stores floats: the OBJ's doubles rounded to float, 2^-24 relative on a unit sphere.
TEST(ModelsFolder, SphereGltfAndGlbGiveTheObjsMesh) {
    const std::shared_ptr<const Model> obj = loadModel(kModels / "sphere.obj");
    const std::shared_ptr<const Model> gltf = loadModel(kModels / "sphere.gltf");
    const std::shared_ptr<const Model> glb = loadModel(kModels / "sphere.glb");
    expectSameMesh(obj->mesh, gltf->mesh, 1e-7);
    expectSameMesh(gltf->mesh, glb->mesh, 0);
    ASSERT_TRUE(gltf->material && glb->material);
    EXPECT_EQ(gltf->material->diffuse, glm::dvec3(0.2, 0.4, 0.8));
    EXPECT_EQ(glb->material->diffuse, glm::dvec3(0.2, 0.4, 0.8));
}

TEST(ModelsFolder, CubeIsClosedWithItsMtlMaterial) {
    const std::shared_ptr<const Model> cube = loadModel(kModels / "cube.obj");
    const TriangleMesh& mesh = cube->mesh;
    EXPECT_EQ(mesh.triangles.size(), 12u);
    // Closed and consistently wound: every directed edge (by position) once, and its reverse once.
    std::map<std::pair<std::array<double, 3>, std::array<double, 3>>, int> edges;
    const auto key = [&](unsigned v) {
        return std::array<double, 3>{mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z};
    };
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++edges[{key(t[k]), key(t[(k + 1) % 3])}];
    for (const auto& [edge, count] : edges) {
        EXPECT_EQ(count, 1);
        EXPECT_EQ(edges.count({edge.second, edge.first}), 1u);
    }
    // Outward: each face normal points away from the centre, as the file's normal does.
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::dvec3 centroid =
            (mesh.positions[mesh.triangles[t].x] + mesh.positions[mesh.triangles[t].y] +
             mesh.positions[mesh.triangles[t].z]) /
            3.0;
        EXPECT_GT(glm::dot(mesh.faceNormals[t], centroid), 0) << t;
        EXPECT_EQ(mesh.vertexNormals[mesh.triangles[t].x], mesh.faceNormals[t]) << t;
    }
    ASSERT_TRUE(cube->material);
    EXPECT_EQ(cube->material->ambient, glm::dvec3(0.1, 0.02, 0.02));
    EXPECT_EQ(cube->material->diffuse, glm::dvec3(0.8, 0.1, 0.1));
    EXPECT_EQ(cube->material->specular, glm::dvec3(0.5, 0.5, 0.5));
    EXPECT_EQ(cube->material->shininess, 64);
}

TEST(ModelsFolder, TorusNormalsAreMade) {
    const std::shared_ptr<const Model> torus = loadModel(kModels / "torus.obj");
    EXPECT_TRUE(torus->normalsMade);
    EXPECT_EQ(torus->mesh.triangles.size(), 1024u);
    // Outward: away from the tube's centre circle (radius 0.75 in the xz plane).
    for (std::size_t v = 0; v < torus->mesh.positions.size(); ++v) {
        const glm::dvec3 p = torus->mesh.positions[v];
        const glm::dvec3 ring = 0.75 * glm::normalize(glm::dvec3(p.x, 0, p.z));
        EXPECT_GT(glm::dot(torus->mesh.vertexNormals[v], glm::normalize(p - ring)), 0.99) << v;
    }
}

// Runs scripts/make_models.py into a fresh folder; every file there and in models/ (but the README) is
// the same, byte for byte.
TEST(ModelsFolder, MakeModelsWritesTheFolder) {
    char pattern[] = "/tmp/shadelab-models-XXXXXX";
    ASSERT_NE(mkdtemp(pattern), nullptr);
    const fs::path made = pattern;
    const std::string command =
        "python3 '" + (kRoot / "scripts" / "make_models.py").string() + "' '" + made.string() + "'";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command;
    std::set<std::string> madeNames, folderNames;
    for (const fs::directory_entry& entry : fs::directory_iterator(made))
        madeNames.insert(entry.path().filename().string());
    for (const fs::directory_entry& entry : fs::directory_iterator(kModels))
        if (entry.path().filename() != "README.md") folderNames.insert(entry.path().filename().string());
    EXPECT_EQ(madeNames, folderNames) << "models/ is stale: run scripts/make_models.py";
    for (const std::string& name : madeNames)
        EXPECT_TRUE(readBytes(made / name) == readBytes(kModels / name))
            << "models/" << name << " differs from what scripts/make_models.py writes: run it";
    fs::remove_all(made);
}

} // namespace
} // namespace shadelab
