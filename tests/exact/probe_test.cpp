// The demo's probe (shadelab/exact/probe.h) and the overlay's lines (shadelab/diagram/overlay.h) on the
// CPU, against DESIGN §1 and §3 and the analytic reference: the exact sample is the reference's pixel, flat
// shading is the centroid's lighting, Gouraud the interpolation of the vertices', Phong converges to the
// exact value, and the vectors are the equation's l, n, v, r and h.
#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "shadelab/diagram/overlay.h"
#include "shadelab/errors.h"
#include "shadelab/exact/probe.h"
#include "shadelab/exact/reference.h"
#include "shadelab/scene/auto_level.h"

namespace shadelab {
namespace {

Scene probeScene(ShadingMode shading, LightingModel lighting, int level) {
    Scene scene;
    scene.width = scene.height = 96;
    scene.shading = shading;
    scene.lighting = lighting;
    scene.objects[0].subdivisions = level;
    scene.objects[0].scale = {1, 0.8, 1.1}; // an ellipsoid: the normal matrix matters
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {2, 1, 4};
    spot.direction = {-2, -1, -4};
    spot.cutoffDeg = 30;
    spot.exponent = 2;
    spot.attenuation = {1, 0.05, 0.01};
    spot.ambient = {0.05, 0.05, 0.05};
    scene.lights.push_back(spot);
    return scene;
}

ProbeReport probeAtPixel(const Scene& scene, int i, int j) {
    const auto point = pickSurfacePoint(scene, i + 0.5, j + 0.5);
    EXPECT_TRUE(point.has_value()) << "pixel " << i << "," << j;
    return probeSurface(scene, point.value_or(ProbePoint{}),
                        buildSphere(subdivisionLevel(scene, scene.objects[0]), scene.vertexNormals));
}

double largestDifference(const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 d = glm::abs(a - b);
    return std::max({d.x, d.y, d.z});
}

// The exact sample at a pixel's surface point is what the analytic reference shows at that pixel.
// Under every term (the demo's K): the pixel row is what is drawn, one term alone where one is shown.
TEST(Probe, ExactSampleIsTheReferencePixel) {
    for (const bool orthographic : {false, true})
        for (const LightingTerm term : kLightingTerms) {
            Scene scene = probeScene(ShadingMode::Phong, LightingModel::Phong, 3);
            scene.term = term;
            if (orthographic)
                scene.projection = {ProjectionType::Orthographic, 40, -1.5, 1.5, -1.5, 1.5, 0.5, 20};
            const ReferenceImage reference = renderReference(scene);
            int probed = 0;
            for (int j = 8; j < 96; j += 11)
                for (int i = 8; i < 96; i += 11) {
                    if (reference.objectId[std::size_t(j) * 96 + std::size_t(i)] < 0) continue;
                    const ProbeReport probe = probeAtPixel(scene, i, j);
                    const float* pixel = reference.color.pixel(i, j);
                    EXPECT_LT(largestDifference(probe.exact.color, glm::dvec3(pixel[0], pixel[1], pixel[2])),
                              1e-6)
                        << "pixel " << i << "," << j << (orthographic ? " orthographic" : " perspective")
                        << ", " << toString(term);
                    ++probed;
                }
            EXPECT_GE(probed, 15);
        }
}

// The mode's pixel follows the term too, for every mode: the term's own value, clamped, and the difference
// row (mode against exact) is between the two drawn values.
TEST(Probe, PixelAndDifferenceFollowTheTermShown) {
    for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong})
        for (const LightingTerm term :
             {LightingTerm::Ambient, LightingTerm::Diffuse, LightingTerm::Specular}) {
            Scene scene = probeScene(mode, LightingModel::BlinnPhong, 2);
            scene.term = term;
            const ProbeReport probe = probeAtPixel(scene, 40, 44);
            scene.term = LightingTerm::All;
            const ProbeReport all = probeAtPixel(scene, 40, 44);
            EXPECT_NE(probe.mode.color, all.mode.color) << toString(mode) << ", " << toString(term);
            if (mode != ShadingMode::Gouraud) { // Gouraud interpolates the vertices' clamped colours
                EXPECT_EQ(probe.mode.color, clampColor(probe.mode.terms.of(term))) << toString(mode);
            }
            EXPECT_EQ(probe.exact.color, clampColor(probe.exact.terms.of(term))) << toString(mode);
        }
}

TEST(Probe, BackgroundPicksNothing) {
    const Scene scene = probeScene(ShadingMode::Phong, LightingModel::Phong, 3);
    EXPECT_FALSE(pickSurfacePoint(scene, 0.5, 0.5).has_value());
    EXPECT_TRUE(pickSurfacePoint(scene, 48, 48).has_value());
}

// The terms add up to DESIGN §3's I, and the pixel is their clamped sum (flat, Phong) at the mode's point.
TEST(Probe, TermsSumToTheShadedColour) {
    for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Phong, ShadingMode::Toon}) {
        const Scene scene = probeScene(mode, LightingModel::BlinnPhong, 2);
        const ProbeReport probe = probeAtPixel(scene, 40, 44);
        std::vector<Light> lightsView;
        const SceneView view = sceneView(scene);
        for (const Light& l : scene.lights) lightsView.push_back(transformLight(l, view.viewFromWorld));
        const glm::dvec3 shaded = shade(probe.mode.pointView, scene.objects[0].material, lightsView,
                                        {scene.lighting, mode == ShadingMode::Toon, scene.toonBands});
        EXPECT_LT(largestDifference(probe.mode.terms.total(), shaded), 1e-12) << toString(mode);
        EXPECT_EQ(probe.mode.color, clampColor(shaded)) << toString(mode);
    }
}

// Flat shading: the lighting of the triangle's centroid with its face normal, the same for every point
// of the triangle.
TEST(Probe, FlatIsTheCentroidsLightingOverTheWholeTriangle) {
    const Scene scene = probeScene(ShadingMode::Flat, LightingModel::Phong, 2);
    const SphereMesh mesh = buildSphere(2);
    const ProbeReport probe = probeAtPixel(scene, 48, 40);
    const glm::uvec3 t = mesh.triangles[probe.triangle];
    const glm::dvec3 centroid = (mesh.positions[t.x] + mesh.positions[t.y] + mesh.positions[t.z]) / 3.0;
    const glm::dmat4 viewFromObject = sceneView(scene).viewFromWorld * worldFromObject(scene.objects[0]);
    const glm::dvec3 centroidView(viewFromObject * glm::dvec4(centroid, 1));
    EXPECT_LT(glm::length(probe.mode.pointView.position - centroidView), 1e-12);
    // Another direction inside the same triangle (towards a corner) gives the same sample.
    const glm::dvec3 inside =
        glm::normalize(0.6 * mesh.positions[t.x] + 0.2 * mesh.positions[t.y] + 0.2 * mesh.positions[t.z]);
    const ProbeReport other = probeSurface(scene, ProbePoint{0, inside}, mesh);
    EXPECT_EQ(other.triangle, probe.triangle);
    EXPECT_EQ(other.mode.color, probe.mode.color);
    EXPECT_NE(other.exact.color, probe.exact.color) << "while the exact value varies";
}

// Gouraud shading at a vertex is that vertex's lighting; between vertices, the clamped vertex colours
// interpolated with the point's barycentric weights.
TEST(Probe, GouraudIsTheVerticesLightingInterpolated) {
    const Scene scene = probeScene(ShadingMode::Gouraud, LightingModel::Phong, 2);
    const SphereMesh mesh = buildSphere(2);
    const ProbeReport centre = probeAtPixel(scene, 48, 48);
    const glm::uvec3 t = mesh.triangles[centre.triangle];
    const ProbeReport atVertex = probeSurface(scene, ProbePoint{0, mesh.positions[t.y]}, mesh);
    EXPECT_NEAR(std::max({atVertex.barycentric.x, atVertex.barycentric.y, atVertex.barycentric.z}), 1, 1e-9);
    // At a vertex the Gouraud terms are the Phong terms there (same point, same vertex normal).
    Scene phong = scene;
    phong.shading = ShadingMode::Phong;
    const ProbeReport phongAtVertex = probeSurface(phong, ProbePoint{0, mesh.positions[t.y]}, mesh);
    EXPECT_LT(largestDifference(atVertex.mode.terms.total(), phongAtVertex.mode.terms.total()), 1e-9);
    // The weights sum to one and the colour lies within the vertices' colours.
    EXPECT_NEAR(centre.barycentric.x + centre.barycentric.y + centre.barycentric.z, 1, 1e-12);
    EXPECT_GT(std::min({centre.barycentric.x, centre.barycentric.y, centre.barycentric.z}), -1e-12);
}

// Phong shading converges to the exact value as the level rises (DESIGN §6).
TEST(Probe, PhongConvergesToTheExactValue) {
    double previous = 1;
    for (int level : {2, 5, 8}) {
        const Scene scene = probeScene(ShadingMode::Phong, LightingModel::BlinnPhong, level);
        const ProbeReport probe = probeAtPixel(scene, 44, 40);
        const double error = largestDifference(probe.mode.color, probe.exact.color);
        EXPECT_LE(error, previous) << "level " << level;
        previous = error;
    }
    EXPECT_LT(previous, 0.5 / 255) << "level 8";
}

// The drawn vectors are the equation's: unit l, n, v; r = −l + 2(l·n)n; h = normalize(v + l).
TEST(Probe, VectorsAreTheEquationsLNVRH) {
    for (LightingModel model : {LightingModel::Phong, LightingModel::BlinnPhong}) {
        const Scene scene = probeScene(ShadingMode::Phong, model, 4);
        const ProbeReport probe = probeAtPixel(scene, 52, 40);
        ASSERT_EQ(probe.light, 0) << "the point light comes first";
        const SurfacePoint& p = probe.mode.pointView;
        const glm::dvec3 l = probe.mode.toLight;
        EXPECT_NEAR(glm::length(l), 1, 1e-12);
        EXPECT_NEAR(glm::length(p.normal), 1, 1e-12);
        EXPECT_NEAR(glm::length(p.toViewer), 1, 1e-12);
        const glm::dvec3 lightView(sceneView(scene).viewFromWorld * glm::dvec4(scene.lights[0].position, 1));
        EXPECT_LT(glm::length(l - glm::normalize(lightView - p.position)), 1e-12);
        const glm::dvec3 expected = model == LightingModel::Phong ? -l + 2 * glm::dot(l, p.normal) * p.normal
                                                                  : glm::normalize(p.toViewer + l);
        EXPECT_LT(glm::length(probe.mode.specularVector - expected), 1e-12) << toString(model);
    }
}

// The lecture's argument for (M⁻¹)ᵀ at the probed point of an uneven ellipsoid: t is tangent (n·t = 0), M·t
// stays tangent to the drawn surface, (M⁻¹)ᵀ·n is perpendicular to it and M·n is not; each vector against
// its own computation here (a diagonal M's inverse transpose is 1/s per axis).
TEST(Probe, NormalMatrixArgumentAtThePoint) {
    Scene scene = probeScene(ShadingMode::Phong, LightingModel::BlinnPhong, 3);
    scene.objects[0].scale = {1.8, 0.45, 0.9};
    const glm::dvec3 s = scene.objects[0].radius * scene.objects[0].scale;
    const glm::dmat3 viewFromWorld(sceneView(scene).viewFromWorld);
    int probed = 0;
    double largestLean = 0;
    for (const auto& [i, j] : {std::pair{30, 40}, std::pair{60, 35}, std::pair{48, 60}, std::pair{25, 50}}) {
        const auto point = pickSurfacePoint(scene, i + 0.5, j + 0.5);
        ASSERT_TRUE(point) << i << "," << j;
        const ProbeReport probe = probeSurface(scene, *point, buildSphere(3));
        const NormalMatrixArgument& a = probe.normalMatrix;
        ASSERT_TRUE(a.unevenScale);
        const glm::dvec3 n = glm::normalize(point->directionObject);
        EXPECT_NEAR(glm::dot(n, a.tangentObject), 0, 1e-12);
        EXPECT_NEAR(glm::length(a.tangentObject), 1, 1e-12);
        EXPECT_LT(glm::length(a.tangentByM - glm::normalize(viewFromWorld * (s * a.tangentObject))), 1e-9);
        EXPECT_LT(glm::length(a.normalByM - glm::normalize(viewFromWorld * (s * n))), 1e-9);
        EXPECT_LT(glm::length(a.normalByInverseTranspose - glm::normalize(viewFromWorld * (n / s))), 1e-9);
        EXPECT_NEAR(glm::dot(a.tangentByM, a.normalByInverseTranspose), 0, 1e-9);
        largestLean = std::max(largestLean, std::abs(glm::dot(a.tangentByM, a.normalByM)));
        ++probed;
    }
    EXPECT_EQ(probed, 4);
    EXPECT_GT(largestLean, 0.2) << "M·n leans off the surface's normal on an uneven ellipsoid";
    // Under a uniform scale the two normals agree, and nothing extra is drawn.
    scene.objects[0].scale = {2, 2, 2};
    const ProbeReport uniform = probeAtPixel(scene, 48, 48);
    EXPECT_FALSE(uniform.normalMatrix.unevenScale);
    EXPECT_LT(glm::length(uniform.normalMatrix.normalByM - uniform.normalMatrix.normalByInverseTranspose),
              1e-12);
}

TEST(Probe, ObjectOutsideTheSceneIsAnInputError) {
    const Scene scene = probeScene(ShadingMode::Phong, LightingModel::Phong, 1);
    EXPECT_THROW(probeSurface(scene, ProbePoint{3, {0, 0, 1}}, buildSphere(1)), InputError);
}

// The overlay's lines: every edge of the mesh once (6·4ⁿ), lifted just outside the sphere; with normals,
// one segment per face and one per vertex.
TEST(OverlayLines, EveryEdgeOnceAndOneNormalPerFaceAndVertex) {
    for (int level : {0, 1, 3}) {
        const SphereMesh mesh = buildSphere(level);
        EXPECT_TRUE(overlayLines(mesh, Overlay::None).empty());
        const auto edges = overlayLines(mesh, Overlay::Wireframe);
        const std::size_t edgeCount = 6 * std::size_t(std::pow(4, level));
        ASSERT_EQ(edges.size(), 2 * edgeCount) << "level " << level;
        std::set<std::pair<std::tuple<float, float, float>, std::tuple<float, float, float>>> unique;
        for (std::size_t k = 0; k < edges.size(); k += 2) {
            auto key = [](const glm::vec3& v) { return std::tuple{v.x, v.y, v.z}; };
            unique.insert(std::minmax(key(edges[k].position), key(edges[k + 1].position)));
            EXPECT_NEAR(glm::length(edges[k].position), kOverlayLift, 1e-6);
            EXPECT_EQ(edges[k].color, kEdgeColor);
        }
        EXPECT_EQ(unique.size(), edgeCount) << "no edge twice";
        const auto normals = overlayLines(mesh, Overlay::Normals);
        EXPECT_EQ(normals.size(), edges.size() + 2 * (mesh.triangles.size() + mesh.positions.size()));
    }
}

// The probe's lines start at the point the mode lights and point along n, v, l and r/h.
TEST(OverlayLines, ProbeLinesFollowTheVectors) {
    const Scene scene = probeScene(ShadingMode::Flat, LightingModel::Phong, 3);
    const ProbeReport probe = probeAtPixel(scene, 48, 48);
    const auto lines = probeLines(probe, 0.5);
    // Four vectors, the normal matrix's three on this ellipsoid (M·t, M·n, (M⁻¹)ᵀ·n), the cross's two arms.
    ASSERT_EQ(lines.size(), 18u);
    const NormalMatrixArgument& a = probe.normalMatrix;
    const glm::dvec3 vectors[] = {probe.mode.pointView.normal,
                                  probe.mode.pointView.toViewer,
                                  probe.mode.toLight,
                                  probe.mode.specularVector,
                                  a.tangentByM,
                                  a.normalByM,
                                  a.normalByInverseTranspose};
    for (std::size_t k = 0; k < 7; ++k) {
        EXPECT_LT(glm::length(glm::dvec3(lines[2 * k].position) - probe.mode.pointView.position), 1e-6);
        EXPECT_LT(
            glm::length(glm::dvec3(lines[2 * k + 1].position - lines[2 * k].position) - 0.5 * vectors[k]),
            1e-6);
    }
}

} // namespace
} // namespace shadelab
