// The exact teapot's reference (exact/patch_cast.h) and a mesh's (exact/mesh_cast.h), each against an
// independent path: the patches against a very fine mesh of them ray-cast as triangles, a sphere mesh with
// exact normals against the analytic sphere; and the stiff cases of DESIGN §1's teapot — its cusps, rays
// grazing its silhouettes, its inside seen two-sided, and extreme transforms.
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "shadelab/errors.h"
#include "shadelab/exact/mesh_cast.h"
#include "shadelab/exact/patch_cast.h"
#include "shadelab/exact/probe.h"
#include "shadelab/exact/reference.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/geometry/teapot.h"
#include "shadelab/scene/model.h"

namespace shadelab {
namespace {

Light directional(glm::dvec3 direction) {
    Light light;
    light.type = LightType::Directional;
    light.direction = direction;
    light.ambient = {0.1, 0.1, 0.1}, light.diffuse = {0.8, 0.7, 0.6}, light.specular = {0.5, 0.5, 0.5};
    return light;
}

// A teapot seen from the front and above, whole, lit by two directional lights; Phong shading.
Scene teapotScene(int size) {
    Scene scene;
    scene.width = scene.height = size;
    scene.eye = {0, 2.0, 5.0}, scene.target = {0, 0, 0};
    scene.projection.fovyDeg = 45;
    scene.objects[0].shape = Shape::Teapot;
    scene.objects[0].material.shininess = 30;
    scene.lights = {directional({-1, -1, -1}), directional({1, -0.3, -0.5})};
    return scene;
}

std::shared_ptr<const Model> modelOf(TriangleMesh mesh) {
    auto model = std::make_shared<Model>();
    model->path = "test mesh";
    model->mesh = std::move(mesh);
    return model;
}

SceneObject meshObject(const SceneObject& like, std::shared_ptr<const Model> model, bool closed) {
    SceneObject object = like;
    object.shape = Shape::Mesh, object.mesh = "test mesh", object.model = std::move(model);
    object.closed = closed;
    return object;
}

long coveredPixels(const ReferenceImage& image) {
    long count = 0;
    for (int id : image.objectId) count += id >= 0;
    return count;
}

bool allFinite(const ReferenceImage& image) {
    for (float v : image.color.rgba)
        if (!std::isfinite(v)) return false;
    return true;
}

// Pixels covered by one picture and not the other that are not on the first one's silhouette (within
// `radius` px of a pixel of another id): a missing or spurious hit away from an edge.
long coverageDifferencesOffTheEdge(const ReferenceImage& a, const ReferenceImage& b, int radius) {
    std::vector<int> covered(a.objectId.size());
    for (std::size_t i = 0; i < covered.size(); ++i) covered[i] = a.objectId[i] >= 0 ? 0 : 1;
    const int w = a.color.width, h = a.color.height;
    const std::vector<bool> inside = interiorMask(covered, w, h, radius);
    long count = 0;
    for (std::size_t i = 0; i < covered.size(); ++i)
        if (inside[i] && (a.objectId[i] >= 0) != (b.objectId[i] >= 0)) ++count;
    return count;
}

// Both independent: the patches by Newton's iteration, the level-7 mesh (1,047,552 triangles, its
// vertices on the surface with the analytic normals) by Möller–Trumbore. The mesh's surface lies within
// teapotMeshError(7) ≈ 1.6e-4 object units of the patches (≈ 0.02 px here), its interpolated normals
// within about the same angle: the interior agrees far inside 1/255 (measured: mean 0.003/255, max
// 0.39/255 at 256²), and neither misses a pixel the other covers away from the silhouette.
TEST(TeapotReference, AgreesWithAVeryFineMeshOfItsPatches) {
    const Scene exact = teapotScene(256);
    Scene meshed = exact;
    meshed.objects[0] = meshObject(exact.objects[0], modelOf(buildTeapot(7)), false);
    const ReferenceImage patches = renderReference(exact), triangles = renderReference(meshed);
    ASSERT_TRUE(allFinite(patches));
    EXPECT_GT(coveredPixels(patches), 256 * 256 / 5);
    const InteriorError error = interiorError(triangles.color, patches);
    EXPECT_GT(error.pixels, 10000u);
    EXPECT_LE(error.mean, 0.05) << "max " << error.max;
    EXPECT_LE(error.max, 1.0);
    EXPECT_EQ(coverageDifferencesOffTheEdge(patches, triangles, 1), 0);
    EXPECT_EQ(coverageDifferencesOffTheEdge(triangles, patches, 1), 0);
}

ObjectRay rayAlong(glm::dvec3 origin, glm::dvec3 direction) {
    return ObjectRay{origin, glm::normalize(direction), -1e9, 1e9};
}

// The lid's knob and the bottom collapse their u = 0 rows to one point on the axis (∂P/∂v = 0 there): a
// ray along the axis meets the surface exactly at the cusp, where the Jacobian is singular. It hits, at
// y = ±1, with patchNormal's cusp rule ±y; rays just beside the axis hit the same flat tops with normals
// ±y too.
TEST(TeapotReference, RaysThroughTheCuspsHitWithNormalAlongY) {
    for (const double offset : {0.0, 1e-300, 1e-15, 1e-9, 1e-6, 1e-3}) {
        ObjectRayHit down, up;
        ASSERT_TRUE(intersectTeapot(rayAlong({offset, 5, offset / 2}, {0, -1, 0}), down)) << offset;
        ASSERT_TRUE(intersectTeapot(rayAlong({offset, -5, -offset}, {0, 1, 0}), up)) << offset;
        // The tops are flat to second order: y drops by about offset² off the axis.
        EXPECT_NEAR(down.pointObject.y, 1.0, 1e-9 + offset * offset) << offset;
        EXPECT_NEAR(up.pointObject.y, -1.0, 1e-9 + offset * offset) << offset;
        EXPECT_NEAR(glm::normalize(down.normalObject).y, 1.0, 1e-6) << offset;
        EXPECT_NEAR(glm::normalize(up.normalObject).y, -1.0, 1e-6) << offset;
        EXPECT_FALSE(down.backFace);
        EXPECT_FALSE(up.backFace);
    }
}

struct Graze {
    const char* name;
    glm::dvec3 origin, direction; // the ray at offset 0
    glm::dvec3 sweep;             // the way out of the silhouette
};

// Sweeping a ray outwards from a hit in 1e-3-unit steps finds the outermost silhouette's last hit; then 2,000
// rays in that step, spaced 5e-7 (≈ 1/2000 of a pixel of a 500-pixel teapot): each hit has a finite unit
// normal and the coverage changes once, from hit to miss. A missed root shows as a miss among hits, a
// spurious one as a hit among misses.
TEST(TeapotReference, RaysGrazingTheSilhouettesStayFiniteAndCoverageChangesOnce) {
    const Graze cases[] = {
        {"body's side", {0.5, -0.3, 5}, {0, 0, -1}, {1, 0, 0}},
        {"handle's outer curve", {0, 0.2, 5}, {0, 0, -1}, {-1, 0, 0}},
        {"handle's top, seen from above", {-1.5, 5, 0}, {0, -1, 0}, {0, 0, 1}},
        {"spout's tip", {1.8, 0.55, 5}, {0, 0, -1}, {1, 0, 0}},
        {"knob's flat top, edge-on", {0, 0.8, 5}, {0, 0, -1}, {0, 1, 0}},
        {"bottom's flat disc, edge-on", {0, -0.8, 5}, {0, 0, -1}, {0, -1, 0}},
    };
    for (const Graze& c : cases) {
        auto hits = [&](double offset, ObjectRayHit& hit) {
            hit = ObjectRayHit{};
            return intersectTeapot(rayAlong(c.origin + offset * c.sweep, c.direction), hit);
        };
        ObjectRayHit hit;
        ASSERT_TRUE(hits(0, hit)) << c.name;
        double last = 0;
        for (double offset = 0; offset < 3; offset += 1e-3)
            if (hits(offset, hit)) last = offset;
        int changes = 0;
        bool previous = true;
        for (int k = 0; k <= 2000; ++k) {
            const bool now = hits(last + k * 5e-7, hit);
            if (now) {
                ASSERT_TRUE(std::isfinite(hit.t) && std::isfinite(glm::length(hit.normalObject))) << c.name;
                EXPECT_NEAR(glm::length(hit.normalObject), 1.0, 1e-9) << c.name;
            }
            changes += now != previous;
            previous = now;
        }
        EXPECT_EQ(changes, 1) << c.name << ": the silhouette near offset " << last;
    }
}

// The camera inside the teapot's body (the near plane cuts it open): every surface it sees is the inside,
// a back face. Lit by a light travelling along the view, the inside wall turned towards the viewer is lit
// (l·n > 0); with its outward normal it would get the ambient term alone. The same holds for the teapot
// read as an open mesh, and a mesh marked closed keeps its outward normal (DESIGN §3: closed meshes cull).
TEST(TeapotReference, TheInsideIsLitTwoSided) {
    Scene scene;
    scene.width = scene.height = 64;
    scene.eye = {0, -0.2, 0}, scene.target = {0, -0.2, -1};
    scene.projection.fovyDeg = 60, scene.projection.near = 0.01, scene.projection.far = 10;
    scene.objects[0].shape = Shape::Teapot;
    scene.lights = {directional({0, 0, -1})};
    const double ambientOnly = scene.lights[0].ambient.x * scene.objects[0].material.ambient.x;

    auto meanRed = [](const ReferenceImage& image) {
        double sum = 0;
        for (std::size_t i = 0; i < image.objectId.size(); ++i) sum += image.color.rgba[4 * i];
        return sum / double(image.objectId.size());
    };
    const ReferenceImage patches = renderReference(scene);
    EXPECT_EQ(coveredPixels(patches), 64 * 64);
    EXPECT_GT(meanRed(patches), ambientOnly + 0.2);

    const auto model = modelOf(buildTeapot(4));
    scene.objects[0] = meshObject(scene.objects[0], model, false);
    const ReferenceImage open = renderReference(scene);
    EXPECT_EQ(coveredPixels(open), 64 * 64);
    EXPECT_NEAR(meanRed(open), meanRed(patches), 0.01);
    scene.objects[0].closed = true;
    EXPECT_NEAR(meanRed(renderReference(scene)), ambientOnly, 1e-6);
}

// Mirroring x (scale −1, 1, 1) with the camera and the light on the z axis gives the picture mirrored left
// to right, normals included (the normal matrix keeps them outward, DESIGN §2).
TEST(TeapotReference, MirroredScaleGivesTheMirroredPicture) {
    Scene scene = teapotScene(96);
    scene.eye = {0, 0, 5};
    scene.lights = {directional({0, -0.5, -1})};
    const ReferenceImage plain = renderReference(scene);
    scene.objects[0].scale = {-1, 1, 1};
    const ReferenceImage mirrored = renderReference(scene);
    ASSERT_TRUE(allFinite(mirrored));
    long differentCoverage = 0;
    double largest = 0;
    for (int j = 0; j < 96; ++j)
        for (int i = 0; i < 96; ++i) {
            const float *a = plain.color.pixel(i, j), *b = mirrored.color.pixel(95 - i, j);
            if (a[3] != b[3]) {
                ++differentCoverage;
                continue;
            }
            for (int c = 0; c < 3; ++c) largest = std::max(largest, double(std::abs(a[c] - b[c])));
        }
    EXPECT_LE(differentCoverage, 2); // a pixel centre on the silhouette itself may round either way
    EXPECT_LT(largest, 1e-6);        // measured: identical
}

// A tiny teapot (radius 1e-9, the camera 5e-9 away) is the same picture as the unit one: the ray is moved
// into object units before anything is solved.
TEST(TeapotReference, TinyRadiusGivesTheSamePicture) {
    Scene unit = teapotScene(96);
    Scene tiny = unit;
    tiny.objects[0].radius = 1e-9;
    tiny.eye *= 1e-9;
    tiny.projection.near *= 1e-9, tiny.projection.far *= 1e-9;
    const ReferenceImage a = renderReference(unit), b = renderReference(tiny);
    ASSERT_TRUE(allFinite(b));
    EXPECT_NEAR(double(coveredPixels(b)), double(coveredPixels(a)), 2);
    const InteriorError error = interiorError(b.color, a);
    EXPECT_GT(error.pixels, 500u);
    EXPECT_LT(error.max, 1e-3); // measured: identical
}

// Seen edge-on (the eye level with the teapot, so the lid's and the bottom's flat discs are lines) from ten
// million units away through a 1.4e-5° field of view, the picture is the orthographic one: the rays are
// parallel to 1e-7, and their origins' rounding (1e7·2⁻⁵² ≈ 2e-9) stays far below a pixel (2e-2 units) —
// provided the cast solves near the teapot, not 1e7 units from it, where |F| could not fall below 1e-9.
TEST(TeapotReference, EdgeOnFromAfarIsTheOrthographicPicture) {
    Scene far = teapotScene(128);
    far.eye = {0, 0, 1e7};
    far.projection.fovyDeg = 2 * std::atan(1.25 / 1e7) * 180 / std::numbers::pi;
    far.projection.near = 1e7 - 10, far.projection.far = 1e7 + 10;
    Scene ortho = far;
    ortho.projection.type = ProjectionType::Orthographic;
    ortho.projection.left = ortho.projection.bottom = -1.25;
    ortho.projection.right = ortho.projection.top = 1.25;
    const ReferenceImage a = renderReference(ortho), b = renderReference(far);
    ASSERT_TRUE(allFinite(b));
    EXPECT_GT(coveredPixels(b), 128 * 128 / 5);
    EXPECT_EQ(coverageDifferencesOffTheEdge(a, b, 1), 0);
    const InteriorError error = interiorError(b.color, a);
    EXPECT_LT(error.max, 0.05); // v differs from +z by ≤ 1.3e-7 rad
}

// An OBJ-like sphere (level 6, exact normals, no analytic surface known to the cast) against the analytic
// sphere: the Phong picture of a level-6 mesh is within 1/255 of the exact one (DESIGN §6), and the mesh
// reference is that picture (measured: mean 0.016/255, max 0.25/255 at 200²).
TEST(MeshReference, SphereMeshWithExactNormalsAgreesWithTheAnalyticSphere) {
    Scene sphere;
    sphere.width = sphere.height = 200;
    sphere.lights = {directional({-1, -1, -1})};
    sphere.objects[0].material.shininess = 20;
    Scene meshed = sphere;
    meshed.objects[0] = meshObject(sphere.objects[0], modelOf(buildSphere(6, VertexNormals::Exact)), true);
    const ReferenceImage exact = renderReference(sphere), mesh = renderReference(meshed);
    const InteriorError error = interiorError(mesh.color, exact);
    EXPECT_GT(error.pixels, 10000u);
    EXPECT_LE(error.mean, 0.1) << "max " << error.max;
    EXPECT_LE(error.max, 1.0);
    EXPECT_EQ(coverageDifferencesOffTheEdge(exact, mesh, 1), 0);
}

// Rays through points of an edge two triangles share (a tilted quad, its diagonal at awkward coordinates)
// hit one of them: no pinhole where rounding puts the point a hair outside both.
TEST(MeshReference, RaysThroughASharedEdgeAlwaysHit) {
    TriangleMesh quad;
    quad.positions = {{-0.7, -0.31, 0.13}, {0.9, -0.57, -0.21}, {0.83, 0.77, 0.37}, {-0.61, 0.59, 0.11}};
    quad.triangles = {{0, 1, 2}, {0, 2, 3}};
    quad.vertexNormals.assign(4, glm::dvec3(0, 0, 1));
    const MeshBvh bvh(quad);
    int misses = 0;
    for (int k = 1; k < 10000; ++k) {
        const glm::dvec3 onEdge = glm::mix(quad.positions[0], quad.positions[2], k / 10000.0);
        const glm::dvec3 direction = glm::normalize(glm::dvec3(0.1 * std::sin(k), 0.2, -1));
        ObjectRayHit hit;
        misses += !bvh.intersect(ObjectRay{onEdge - 3.0 * direction, direction, 0, 10}, hit);
    }
    EXPECT_EQ(misses, 0);
}

// The probe pins points on spheres only: a teapot hides the sphere behind it and gives no probe point, and
// asking to probe it says so.
TEST(MeshReference, ProbeGivesNothingForATeapotAndRefusesToProbeIt) {
    Scene scene = teapotScene(64);
    SceneObject behind;
    behind.center = {0, 0, -3};
    scene.objects.push_back(behind);
    EXPECT_FALSE(pickSurfacePoint(scene, 32, 32).has_value());
    EXPECT_THROW(probeSurface(scene, ProbePoint{0, {0, 0, 1}}, buildSphere(2)), InputError);
}

} // namespace
} // namespace shadelab
