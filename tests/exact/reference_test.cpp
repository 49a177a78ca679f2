// The analytic reference against hand-computed values: the lighting at known pixels, coverage against
// πR², the perspective silhouette against the tangent cone, visibility, clipping, mirroring, robustness,
// and the interior mask used to score the image tests.
#include <cmath>
#include <numbers>
#include <set>

#include <gtest/gtest.h>

#include "shadelab/errors.h"
#include "shadelab/exact/reference.h"
#include "shadelab/image/image.h"

namespace shadelab {
namespace {

// Material and light numbers chosen so that no channel of k_a·I_a + k_d·I_d + k_s·I_s exceeds 1.
const glm::dvec3 kA{0.1, 0.2, 0.05}, kD{0.4, 0.3, 0.2}, kS{0.3, 0.2, 0.1};
const glm::dvec3 iA{0.5, 0.5, 0.5}, iD{0.8, 0.9, 1.0}, iS{0.6, 0.6, 0.6};
constexpr double kShininess = 4;

Material material() {
    Material m;
    m.ambient = kA, m.diffuse = kD, m.specular = kS, m.shininess = kShininess;
    return m;
}

Light directionalAlongMinusZ() {
    Light light;
    light.type = LightType::Directional;
    light.direction = {0, 0, -1};
    light.ambient = iA, light.diffuse = iD, light.specular = iS;
    return light;
}

SceneObject sphere(glm::dvec3 center, double radius, glm::dvec3 scale = {1, 1, 1}) {
    SceneObject object;
    object.center = center, object.radius = radius, object.scale = scale, object.material = material();
    return object;
}

// Camera on +z looking at the origin, orthographic box [−half, half]², one unit sphere at the origin lit by
// a directional light travelling along −z, Phong lighting and shading.
Scene orthographicScene(int size, double half) {
    Scene scene;
    scene.width = scene.height = size;
    scene.background = {0.25, 0.5, 0.75};
    scene.eye = {0, 0, 4}, scene.target = {0, 0, 0}, scene.up = {0, 1, 0};
    scene.projection.type = ProjectionType::Orthographic;
    scene.projection.left = scene.projection.bottom = -half;
    scene.projection.right = scene.projection.top = half;
    scene.projection.near = 1, scene.projection.far = 10;
    scene.shading = ShadingMode::Phong;
    scene.lighting = LightingModel::Phong;
    scene.objects = {sphere({0, 0, 0}, 1)};
    scene.lights = {directionalAlongMinusZ()};
    return scene;
}

Scene perspectiveScene(int size, double fovyDeg) {
    Scene scene = orthographicScene(size, 1);
    scene.projection.type = ProjectionType::Perspective;
    scene.projection.fovyDeg = fovyDeg;
    scene.projection.near = 0.5, scene.projection.far = 20;
    return scene;
}

// DESIGN §6 pixel centres, j = 0 the top row, in an orthographic box [−half, half]².
double viewX(int i, int size, double half) {
    return -half + 2 * half * (i + 0.5) / size;
}
double viewY(int j, int size, double half) {
    return half - 2 * half * (j + 0.5) / size;
}

// By hand: a sphere seen orthographically along −z, lit along −z (l = v = +z), Phong lighting. At the
// point over (x, y), n = ((x−cx)/r, (y−cy)/r, n_z), so l·n = n_z and v·r = −1 + 2·n_z².
glm::dvec3 expectedPhong(double x, double y, double cx, double cy, double r, bool toon = false) {
    const double nx = (x - cx) / r, ny = (y - cy) / r;
    const double nz = std::sqrt(1 - nx * nx - ny * ny);
    double diffuse = nz, spec = std::pow(std::max(2 * nz * nz - 1, 0.0), kShininess);
    if (toon) {
        diffuse = std::ceil(diffuse * kToonBands) / kToonBands;
        spec = spec > kToonHighlight ? 1 : 0;
    }
    return kA * iA + kD * iD * diffuse + kS * iS * spec;
}

void expectPixel(const ReferenceImage& image, int i, int j, const glm::dvec3& color, double alpha,
                 double tolerance = 1e-6) {
    const float* p = image.color.pixel(i, j);
    EXPECT_NEAR(p[0], color.x, tolerance) << "pixel " << i << "," << j;
    EXPECT_NEAR(p[1], color.y, tolerance) << "pixel " << i << "," << j;
    EXPECT_NEAR(p[2], color.z, tolerance) << "pixel " << i << "," << j;
    EXPECT_EQ(p[3], alpha) << "pixel " << i << "," << j;
}

int idAt(const ReferenceImage& image, int i, int j) {
    return image.objectId[std::size_t(j) * std::size_t(image.color.width) + std::size_t(i)];
}

long covered(const ReferenceImage& image) {
    long count = 0;
    for (int id : image.objectId) count += id >= 0;
    return count;
}

TEST(Reference, ImageHasTheSceneSizeAndIdsForEveryPixel) {
    Scene scene = orthographicScene(48, 1.3);
    scene.width = 64;
    const ReferenceImage image = renderReference(scene);
    EXPECT_EQ(image.color.width, 64);
    EXPECT_EQ(image.color.height, 48);
    EXPECT_EQ(image.color.rgba.size(), std::size_t(64 * 48 * 4));
    EXPECT_EQ(image.objectId.size(), std::size_t(64 * 48));
}

TEST(Reference, CentrePixelIsAmbientPlusDiffusePlusSpecular) {
    // 65 px over [−1.3, 1.3]: pixel 32's centre is exactly view (0, 0), where n = v = l = +z.
    const ReferenceImage image = renderReference(orthographicScene(65, 1.3));
    expectPixel(image, 32, 32, kA * iA + kD * iD + kS * iS, 1);
    EXPECT_EQ(idAt(image, 32, 32), 0);
}

TEST(Reference, OffCentrePixelMatchesHandComputedPhong) {
    const ReferenceImage image = renderReference(orthographicScene(65, 1.3));
    // Pixel (40, 20) is view (0.32, 0.48): n = (0.32, 0.48, √0.6672). Row 20 is above the centre.
    EXPECT_NEAR(viewX(40, 65, 1.3), 0.32, 1e-12);
    EXPECT_NEAR(viewY(20, 65, 1.3), 0.48, 1e-12);
    expectPixel(image, 40, 20, expectedPhong(0.32, 0.48, 0, 0, 1), 1);
    for (int i : {5, 20, 33, 50, 60})
        for (int j : {7, 31, 45, 58}) {
            const double x = viewX(i, 65, 1.3), y = viewY(j, 65, 1.3);
            if (x * x + y * y < 0.98) expectPixel(image, i, j, expectedPhong(x, y, 0, 0, 1), 1);
        }
}

TEST(Reference, ToonReferenceQuantizesDiffuseAndHighlight) {
    Scene scene = orthographicScene(65, 1.3);
    scene.shading = ShadingMode::Toon;
    const ReferenceImage image = renderReference(scene);
    expectPixel(image, 32, 32, expectedPhong(0, 0, 0, 0, 1, true), 1);
    expectPixel(image, 40, 20, expectedPhong(0.32, 0.48, 0, 0, 1, true), 1);
}

TEST(Reference, BackgroundHasTheSceneColourAndAlphaZero) {
    const ReferenceImage image = renderReference(orthographicScene(65, 1.3));
    for (auto [i, j] : {std::pair{0, 0}, {64, 0}, {0, 64}, {64, 64}}) {
        expectPixel(image, i, j, {0.25, 0.5, 0.75}, 0);
        EXPECT_EQ(idAt(image, i, j), -1);
    }
}

TEST(Reference, RowsAreStoredTopFirst) {
    Scene scene = orthographicScene(64, 2);
    scene.objects = {sphere({1, 1, 0}, 0.5)}; // upper right in view
    const ReferenceImage image = renderReference(scene);
    EXPECT_EQ(idAt(image, 48, 16), 0);  // view (1.03, 1.03)
    EXPECT_EQ(idAt(image, 16, 48), -1); // lower left
    EXPECT_EQ(idAt(image, 16, 16), -1); // upper left
    EXPECT_EQ(idAt(image, 48, 48), -1); // lower right
}

// A lattice of pixel centres inside a disc differs from its area by O(R^(2/3)) (the Gauss circle
// problem); for R = 20..40 px that is a few pixels. R/2 allows it, yet a radius off by 0.1 px changes the
// count by 2πR·0.1 > R/2.
TEST(Reference, SphereCoversPiRSquaredPixels) {
    const double r = 40; // 128 px over [−1.6, 1.6]: 40 px per unit
    const ReferenceImage image = renderReference(orthographicScene(128, 1.6));
    EXPECT_NEAR(double(covered(image)), std::numbers::pi * r * r, r / 2);
}

TEST(Reference, EllipsoidCoversTwoPiRSquaredPixels) {
    const double r = 20; // 128 px over [−3.2, 3.2]: 20 px per unit
    Scene scene = orthographicScene(128, 3.2);
    scene.objects = {sphere({0, 0, 0}, 1, {2, 1, 1})};
    const ReferenceImage image = renderReference(scene);
    EXPECT_NEAR(double(covered(image)), 2 * std::numbers::pi * r * r, r / 2);
    EXPECT_EQ(idAt(image, 64 + 35, 64), 0);  // 1.75 units right: inside the 2-unit semi-axis
    EXPECT_EQ(idAt(image, 64, 64 + 23), -1); // 1.15 units down: outside the 1-unit semi-axis

    // By hand: the surface x²/4 + y² + z² = 1 has the normal ∝ (x/4, y, z) (the gradient), not (x, y, z).
    const int i = 64 + 25, j = 64 - 10; // view (1.275, 0.525)
    const double x = viewX(i, 128, 3.2), y = viewY(j, 128, 3.2), z = std::sqrt(1 - x * x / 4 - y * y);
    const double nz = z / glm::length(glm::dvec3(x / 4, y, z));
    const glm::dvec3 expected = kA * iA + kD * iD * nz + kS * iS * std::pow(2 * nz * nz - 1, kShininess);
    expectPixel(image, i, j, expected, 1);
}

TEST(Reference, PerspectiveSilhouetteMatchesTheTangentCone) {
    // Unit sphere 4 units from the eye: the tangent cone has sin α = 1/4. On the image plane its radius is
    // tan α / tan(fovy/2) half-heights: 0.709395 · 64.5 = 45.76 px for 129 px and fovy 40°.
    const int size = 129;
    const double tanAlpha = 0.25 / std::sqrt(1 - 0.25 * 0.25);
    const double rPx = tanAlpha / std::tan(20 * std::numbers::pi / 180) * size / 2.0;
    ASSERT_NEAR(rPx, 45.756, 1e-3);
    const ReferenceImage image = renderReference(perspectiveScene(size, 40));

    // The middle row and column pass through the centre: pixel k (from the middle) is covered iff |k| < R.
    int rowCount = 0, columnCount = 0;
    for (int k = 0; k < size; ++k) {
        rowCount += idAt(image, k, size / 2) == 0;
        columnCount += idAt(image, size / 2, k) == 0;
    }
    EXPECT_EQ(rowCount, 2 * int(rPx) + 1);
    EXPECT_EQ(columnCount, 2 * int(rPx) + 1);
    EXPECT_NEAR(double(covered(image)), std::numbers::pi * rPx * rPx, rPx / 2); // see the coverage tests
}

TEST(Reference, PerspectivePixelMatchesHandComputedHeadlight) {
    // A point light at the eye: l = v = the direction back along the ray (local viewer). For a ray at angle
    // θ off the axis towards a unit sphere 4 units away, the law of sines gives the angle γ between the
    // ray and the normal: sin γ = 4·sin θ, so l·n = cos γ, and for Phong v·r = 2(l·n)² − 1.
    Scene scene = perspectiveScene(65, 40);
    Light headlight;
    headlight.position = scene.eye, headlight.ambient = iA, headlight.diffuse = iD, headlight.specular = iS;
    scene.lights = {headlight};
    const ReferenceImage image = renderReference(scene);
    const double near = 0.5, top = near * std::tan(20 * std::numbers::pi / 180);
    for (auto [i, j] : {std::pair{32, 32}, {40, 20}, {12, 30}, {44, 40}}) {
        const double x = -top + 2 * top * (i + 0.5) / 65, y = top - 2 * top * (j + 0.5) / 65;
        const double sinTheta = std::hypot(x, y) / std::sqrt(x * x + y * y + near * near);
        ASSERT_LT(4 * sinTheta, 0.99) << "pixel " << i << "," << j << " must be well inside the silhouette";
        const double lDotN = std::sqrt(1 - 16 * sinTheta * sinTheta);
        const glm::dvec3 expected =
            kA * iA + kD * iD * lDotN + kS * iS * std::pow(std::max(2 * lDotN * lDotN - 1, 0.0), kShininess);
        expectPixel(image, i, j, expected, 1);
    }
}

TEST(Reference, NearerSphereWinsWhereSpheresOverlap) {
    const SceneObject far = sphere({-0.3, 0, 0}, 0.6), near = sphere({0.3, 0, 1}, 0.6);
    for (bool nearFirst : {false, true}) {
        Scene scene = orthographicScene(64, 1);
        scene.objects = nearFirst ? std::vector{near, far} : std::vector{far, near};
        const int nearId = nearFirst ? 0 : 1, farId = 1 - nearId;
        const ReferenceImage image = renderReference(scene);
        // Orthographic along −z: each sphere covers the disc of its radius around its (x, y).
        int overlap = 0;
        for (int j = 0; j < 64; ++j)
            for (int i = 0; i < 64; ++i) {
                const double x = viewX(i, 64, 1), y = viewY(j, 64, 1);
                const bool inFar = std::hypot(x + 0.3, y) < 0.6, inNear = std::hypot(x - 0.3, y) < 0.6;
                const int expected = inNear ? nearId : inFar ? farId : -1;
                overlap += inNear && inFar;
                EXPECT_EQ(idAt(image, i, j), expected)
                    << "pixel " << i << "," << j << " near first " << nearFirst;
            }
        EXPECT_GT(overlap, 200);
    }
}

TEST(Reference, ObjectsOutsideNearAndFarAreNotDrawn) {
    Scene scene = orthographicScene(64, 2);     // eye at z = 4, near 1, far 10
    scene.objects = {sphere({-1, 0, 3.5}, 0.3), // view z in [−0.8, −0.2]: before the near plane
                     sphere({1, 0, -7}, 0.3),   // view z in [−11.3, −10.7]: beyond the far plane
                     sphere({0, 1, 0}, 0.3)};   // inside
    const ReferenceImage image = renderReference(scene);
    const std::set<int> ids(image.objectId.begin(), image.objectId.end());
    EXPECT_EQ(ids, (std::set<int>{-1, 2}));
}

TEST(Reference, NearPlaneCutsASphereOpenAndItsFarSideShows) {
    // View z of the centre −1.2, radius 0.5: the near plane z = −1 cuts it in a circle of radius 0.458.
    // Inside that circle the ray's first in-volume hit is the far side, whose outward normal −z faces
    // away from the light: only ambient.
    Scene scene = orthographicScene(65, 1.3);
    scene.objects = {sphere({0, 0, 2.8}, 0.5)};
    const ReferenceImage image = renderReference(scene);
    expectPixel(image, 32, 32, kA * iA, 1);
    // Pixel 32+11 is 0.44 from the centre, still inside the cut; +12 (0.48) sees the front side.
    expectPixel(image, 32 + 11, 32, kA * iA, 1);
    expectPixel(image, 32 + 12, 32, expectedPhong(0.48, 0, 0, 0, 0.5), 1);
}

TEST(Reference, MirroredScaleRendersTheSamePicture) {
    for (glm::dvec3 scale : {glm::dvec3{1, 1, 1}, glm::dvec3{2, 1, 0.5}}) {
        Scene scene = perspectiveScene(64, 40);
        Light point;
        point.position = {2, 1.5, 3}, point.ambient = iA, point.diffuse = iD, point.specular = iS;
        scene.lights = {point};
        scene.objects = {sphere({0.2, -0.1, 0}, 0.8, scale)};
        const ReferenceImage plain = renderReference(scene);
        scene.objects[0].scale.x = -scale.x;
        const ReferenceImage mirrored = renderReference(scene);
        EXPECT_EQ(plain.objectId, mirrored.objectId);
        ASSERT_EQ(plain.color.rgba.size(), mirrored.color.rgba.size());
        for (std::size_t k = 0; k < plain.color.rgba.size(); ++k)
            ASSERT_NEAR(plain.color.rgba[k], mirrored.color.rgba[k], 1e-6) << "value " << k;
        EXPECT_GT(covered(plain), 500);
    }
}

TEST(Reference, ExtremeLightingStaysFiniteAndInRange) {
    // A point light inside the sphere (l = −v exactly at the centre pixel), a directional light from
    // behind (l = −v under orthographic projection), a spot at the eye, I = 1000, shininess 1.
    Light inside;
    inside.position = {0, 0, 0}, inside.ambient = inside.diffuse = inside.specular = glm::dvec3(1000);
    Light behind = directionalAlongMinusZ();
    behind.direction = {0, 0, 1}, behind.diffuse = behind.specular = glm::dvec3(1000);
    Light spot;
    spot.type = LightType::Spot, spot.position = {0, 0, 4}, spot.direction = {0, 0, -1};
    spot.cutoffDeg = 10, spot.exponent = 3, spot.attenuation = {0, 0, 1};
    spot.diffuse = spot.specular = glm::dvec3(1000);
    for (bool orthographic : {true, false})
        for (ShadingMode shading : kShadingModes)
            for (LightingModel lighting : kLightingModels) {
                Scene scene = orthographic ? orthographicScene(33, 1.3) : perspectiveScene(33, 40);
                scene.shading = shading, scene.lighting = lighting;
                scene.objects[0].material.shininess = 1;
                scene.lights = {inside, behind, spot};
                const ReferenceImage image = renderReference(scene);
                const ValueScan scan = scanValues(image.color);
                EXPECT_EQ(scan.nonFinite, 0u) << toString(shading) << " " << toString(lighting);
                EXPECT_EQ(scan.outOfRange, 0u) << toString(shading) << " " << toString(lighting);
                EXPECT_GT(covered(image), 0);
            }
}

TEST(Reference, TinySphereIsExact) {
    // Radius 1e-12 seen from 4 units: in object space the eye is 4e12 radii away, where the textbook
    // discriminant b² − c cancels to noise, o + t·d misses the surface by ~1e-4 radii, and the cofactor
    // normal matrix (~1e-24) would be "zero" to safeNormalize.
    Scene scene = orthographicScene(65, 1.3e-12);
    scene.objects = {sphere({0, 0, 0}, 1e-12)};
    const ReferenceImage image = renderReference(scene);
    EXPECT_NEAR(double(covered(image)), std::numbers::pi * 25 * 25, 25 / 2.0); // 25 px per 1e-12
    expectPixel(image, 32, 32, expectedPhong(0, 0, 0, 0, 1), 1);
    expectPixel(image, 40, 20, expectedPhong(0.32e-12, 0.48e-12, 0, 0, 1e-12), 1);
}

TEST(Reference, HugeSphereIsExact) {
    // Radius 1e6 whose front pole sits at the origin: the whole view is its cap, nearly facing the eye.
    Scene scene = orthographicScene(65, 1.3);
    scene.objects = {sphere({0.2, 0, -1e6}, 1e6)};
    const ReferenceImage image = renderReference(scene);
    EXPECT_EQ(covered(image), 65 * 65);
    for (auto [i, j] : {std::pair{0, 0}, {32, 32}, {40, 20}, {64, 64}})
        expectPixel(image, i, j, expectedPhong(viewX(i, 65, 1.3), viewY(j, 65, 1.3), 0.2, 0, 1e6), 1);
}

TEST(Reference, IsDeterministic) {
    const Scene scene = perspectiveScene(64, 40);
    const ReferenceImage a = renderReference(scene), b = renderReference(scene);
    EXPECT_EQ(a.color.rgba, b.color.rgba);
    EXPECT_EQ(a.objectId, b.objectId);
}

TEST(Reference, RejectsAnInvalidScene) {
    Scene scene = orthographicScene(16, 1);
    scene.objects[0].radius = 0;
    EXPECT_THROW(renderReference(scene), InputError);
    scene = orthographicScene(16, 1);
    scene.up = {0, 0, 1}; // parallel to the view direction
    EXPECT_THROW(renderReference(scene), InputError);
}

// ---- interiorMask ----

// The definition, O(w·h·r²): every pixel within Chebyshev distance r exists and has the centre's id >= 0.
std::vector<bool> bruteForceInterior(const std::vector<int>& ids, int w, int h, int r) {
    std::vector<bool> out(ids.size(), false);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int id = ids[std::size_t(y * w + x)];
            bool interior = id >= 0;
            for (int dy = -r; dy <= r && interior; ++dy)
                for (int dx = -r; dx <= r && interior; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    interior = nx >= 0 && nx < w && ny >= 0 && ny < h && ids[std::size_t(ny * w + nx)] == id;
                }
            out[std::size_t(y * w + x)] = interior;
        }
    return out;
}

// ids from a predicate on (x, y).
template <typename F> std::vector<int> makeIds(int w, int h, F idOf) {
    std::vector<int> ids(std::size_t(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) ids[std::size_t(y * w + x)] = idOf(x, y);
    return ids;
}

TEST(InteriorMask, SquareErodesByTheRadius) {
    // A 10×10 block of id 0 at [5, 15)² in a 20×20 background: radius 2 leaves [7, 13)².
    const auto ids =
        makeIds(20, 20, [](int x, int y) { return x >= 5 && x < 15 && y >= 5 && y < 15 ? 0 : -1; });
    const std::vector<bool> mask = interiorMask(ids, 20, 20, 2);
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x)
            EXPECT_EQ(mask[std::size_t(y * 20 + x)], x >= 7 && x < 13 && y >= 7 && y < 13) << x << "," << y;
}

TEST(InteriorMask, DiscErodesByTheRadius) {
    // A disc of diameter 10 centred in a 20×20 image: a pixel is interior iff its whole 5×5 neighbourhood
    // lies in the disc, i.e. its four farthest corners' pixels do.
    auto inDisc = [](int x, int y) { return std::hypot(x + 0.5 - 10, y + 0.5 - 10) < 5; };
    const auto ids = makeIds(20, 20, [&](int x, int y) { return inDisc(x, y) ? 0 : -1; });
    const std::vector<bool> mask = interiorMask(ids, 20, 20, 2);
    int count = 0;
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x) {
            const bool expected =
                inDisc(x - 2, y - 2) && inDisc(x + 2, y - 2) && inDisc(x - 2, y + 2) && inDisc(x + 2, y + 2);
            EXPECT_EQ(mask[std::size_t(y * 20 + x)], expected) << x << "," << y;
            count += expected;
        }
    EXPECT_GT(count, 0);
}

TEST(InteriorMask, BorderPixelsAreNeverInterior) {
    // Outside the image counts as another id: a full image of id 0 loses a border of `radius` pixels.
    const std::vector<int> ids(20 * 20, 0);
    const std::vector<bool> mask = interiorMask(ids, 20, 20, 2);
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x)
            EXPECT_EQ(mask[std::size_t(y * 20 + x)], x >= 2 && x < 18 && y >= 2 && y < 18) << x << "," << y;
}

TEST(InteriorMask, AdjacentIdsErodeAtTheirSharedBoundary) {
    const auto ids = makeIds(20, 20, [](int x, int) { return x < 10 ? 0 : 1; });
    const std::vector<bool> mask = interiorMask(ids, 20, 20, 2);
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x) {
            const bool expected = y >= 2 && y < 18 && ((x >= 2 && x < 8) || (x >= 12 && x < 18));
            EXPECT_EQ(mask[std::size_t(y * 20 + x)], expected) << x << "," << y;
        }
}

TEST(InteriorMask, RadiusZeroKeepsEveryObjectPixel) {
    const auto ids = makeIds(7, 5, [](int x, int y) { return (x + y) % 3 - 1; });
    const std::vector<bool> mask = interiorMask(ids, 7, 5, 0);
    for (std::size_t k = 0; k < ids.size(); ++k) EXPECT_EQ(mask[k], ids[k] >= 0);
}

TEST(InteriorMask, MatchesTheDefinitionOnPatchworks) {
    // Overlapping rectangles and discs of several ids, non-square, radii 0..4.
    const int w = 37, h = 23;
    const auto ids = makeIds(w, h, [](int x, int y) {
        if (std::hypot(x - 25.0, y - 11.0) < 8) return 3;
        if (x >= 4 && x < 20 && y >= 3 && y < 19) return (x < 12 && y < 10) ? 1 : 2;
        return (x * 7 + y * 13) % 11 == 0 ? 4 : -1;
    });
    for (int r = 0; r <= 4; ++r) EXPECT_EQ(interiorMask(ids, w, h, r), bruteForceInterior(ids, w, h, r)) << r;
}

TEST(InteriorMask, OfAReferenceIsTheSilhouetteEroded) {
    const ReferenceImage image = renderReference(orthographicScene(64, 1.6));
    const std::vector<bool> mask = interiorMask(image.objectId, 64, 64);
    EXPECT_EQ(mask, bruteForceInterior(image.objectId, 64, 64, 2));
}

TEST(InteriorMask, RejectsBadArguments) {
    EXPECT_THROW(interiorMask(std::vector<int>(10, 0), 4, 3), InputError);
    EXPECT_THROW(interiorMask(std::vector<int>(12, 0), 4, 3, -1), InputError);
}

} // namespace
} // namespace shadelab
