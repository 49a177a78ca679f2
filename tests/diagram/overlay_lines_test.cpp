// The normals overlay's lines (shadelab/diagram/overlay.h) on the CPU: taken through the object's matrix M
// as the renderer draws them, each normal runs along the normal the shading uses, (M⁻¹)ᵀ·n or, wrong on
// purpose, M·n, computed here independently of the code under test (a diagonal M's inverse transpose is
// 1/s per axis).
#include <algorithm>
#include <cmath>
#include <cstddef>

#include <gtest/gtest.h>

#include "shadelab/diagram/overlay.h"

namespace shadelab {
namespace {

constexpr glm::dvec3 kScale{1.8, 0.45, 0.9}; // the lecture's ellipsoid, scenes/normal_matrix.json

// The vertex normals' lines: the last 2 × vertices entries (after the edges and the face normals).
struct Drawn {
    glm::dvec3 from, direction;
    double length;
};
Drawn vertexNormalLine(const std::vector<LineVertex>& lines, const SphereMesh& mesh, std::size_t v,
                       const glm::dmat3& m) {
    const std::size_t first = lines.size() - 2 * mesh.positions.size() + 2 * v;
    const glm::dvec3 a = m * glm::dvec3(lines[first].position), b = m * glm::dvec3(lines[first + 1].position);
    return {a, glm::normalize(b - a), glm::length(b - a)};
}

TEST(OverlayLines, NormalsRunAlongTheNormalMatrixOfTheRule) {
    const SphereMesh mesh = buildSphere(2, VertexNormals::Averaged);
    const glm::dmat3 m(glm::dvec3(kScale.x, 0, 0), glm::dvec3(0, kScale.y, 0), glm::dvec3(0, 0, kScale.z));
    const auto right = overlayLines(mesh, Overlay::Normals, m, NormalMatrixRule::InverseTranspose);
    const auto wrong = overlayLines(mesh, Overlay::Normals, m, NormalMatrixRule::Model);
    ASSERT_EQ(right.size(), wrong.size());
    const double meanScale = std::cbrt(kScale.x * kScale.y * kScale.z);
    std::size_t tilted = 0;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::dvec3 n = mesh.vertexNormals[v];
        const glm::dvec3 inverseTranspose = glm::normalize(n / kScale), model = glm::normalize(n * kScale);
        const Drawn r = vertexNormalLine(right, mesh, v, m), w = vertexNormalLine(wrong, mesh, v, m);
        EXPECT_NEAR(glm::length(r.direction - inverseTranspose), 0, 1e-5) << "vertex " << v;
        EXPECT_NEAR(glm::length(w.direction - model), 0, 1e-5) << "vertex " << v;
        // As long on every side: the level's length times the mean scale.
        EXPECT_NEAR(r.length, w.length, 1e-5);
        EXPECT_NEAR(r.length / meanScale, std::clamp(0.7 * 1.63 / 4, 0.05, 0.35), 1e-5);
        // From M·p (lifted): the surface point the shading lights.
        EXPECT_NEAR(glm::length(r.from - double(kOverlayLift) * (m * mesh.positions[v])), 0, 1e-5);
        tilted += glm::length(inverseTranspose - model) > 0.05;
    }
    EXPECT_GT(tilted, mesh.positions.size() / 2) << "the two rules differ on most of an uneven ellipsoid";
}

// Under a uniform scale both rules draw the same lines, and without M the normals are the mesh's own.
TEST(OverlayLines, UniformScaleAndIdentityKeepTheMeshsNormals) {
    const SphereMesh mesh = buildSphere(1, VertexNormals::Averaged);
    const auto plain = overlayLines(mesh, Overlay::Normals);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
        EXPECT_NEAR(
            glm::length(vertexNormalLine(plain, mesh, v, glm::dmat3(1)).direction - mesh.vertexNormals[v]), 0,
            1e-6);
    const glm::dmat3 uniform(2.0);
    const auto a = overlayLines(mesh, Overlay::Normals, uniform, NormalMatrixRule::InverseTranspose);
    const auto b = overlayLines(mesh, Overlay::Normals, uniform, NormalMatrixRule::Model);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        EXPECT_NEAR(glm::length(a[i].position - b[i].position), 0, 1e-6);
}

// Past level 3 the normals are thinned so that they read: level 3's vertices, and each level-3 face's centre
// descendant, whose centroid lies near its ancestor's (the middle child of the middle child ...).
TEST(OverlayLines, FineLevelsShowTheNormalsOfLevelThree) {
    const SphereMesh coarse = buildSphere(3, VertexNormals::Averaged);
    const std::size_t coarseEdges = 6 * 64, coarseNormals = coarse.triangles.size() + coarse.positions.size();
    EXPECT_EQ(overlayLines(coarse, Overlay::Normals).size(), 2 * (coarseEdges + coarseNormals));
    for (const int level : {4, 6}) {
        const SphereMesh mesh = buildSphere(level, VertexNormals::Averaged);
        const auto lines = overlayLines(mesh, Overlay::Normals);
        const std::size_t edges = 6 * (std::size_t(1) << (2 * level));
        ASSERT_EQ(lines.size(), 2 * (edges + coarseNormals)) << "level " << level;
        EXPECT_EQ(normalsShown(level).faceStride, std::size_t(1) << (2 * (level - 3)));
        // The vertex normals start at level 3's vertices, the face normals near level 3's centroids.
        for (std::size_t v = 0; v < coarse.positions.size(); ++v) {
            const glm::dvec3 from(lines[2 * (edges + coarse.triangles.size() + v)].position);
            EXPECT_NEAR(glm::length(from - double(kOverlayLift) * coarse.positions[v]), 0, 1e-6);
        }
        for (std::size_t f = 0; f < coarse.triangles.size(); ++f) {
            const glm::uvec3 t = coarse.triangles[f];
            const glm::dvec3 centroid =
                (coarse.positions[t.x] + coarse.positions[t.y] + coarse.positions[t.z]) / 3.0;
            const glm::dvec3 from(lines[2 * (edges + f)].position);
            EXPECT_LT(glm::length(glm::normalize(from) - glm::normalize(centroid)), 0.03) << "face " << f;
        }
    }
}

} // namespace
} // namespace shadelab
