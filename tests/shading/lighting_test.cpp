// The lighting equations of DESIGN §3 against values worked by hand, plus their guards and the enum
// spellings.
#include "shadelab/shading/lighting.h"
#include "shadelab/vocabulary.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace shadelab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string str(const glm::dvec3& v) {
    std::ostringstream out;
    out.precision(17);
    out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return out.str();
}

#define EXPECT_VEC_NEAR(actual, expected, tolerance)                                                         \
    EXPECT_LE(glm::length((actual) - (expected)), tolerance)                                                 \
        << "actual " << str(actual) << "\nexpected " << str(expected)

bool finite(const glm::dvec3& c) {
    return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z);
}

// ---- the worked example ----
// Surface point P = (1, 2, 3), normal n = +z, viewer straight above: v = +z.
// Point light at P + (0, 3, 4): t = 5, l = (0, 0.6, 0.8), l·n = 0.8.
// Phong:  r = −l + 2(l·n)n = (0, −0.6, 0.8),  v·r = 0.8,  α = 2 → spec = 0.64.
// Blinn:  v + l = (0, 0.6, 1.8), |v + l| = √3.6,  n·h = 1.8/√3.6,  β = 2 → spec = 3.24/3.6 = 0.9.
const glm::dvec3 kPoint{1, 2, 3};
const SurfacePoint kSurface{kPoint, {0, 0, 1}, {0, 0, 1}};

Material exampleMaterial(double shininess = 2) {
    Material m;
    m.ambient = {0.1, 0.2, 0.3};
    m.diffuse = {0.5, 0.25, 0.125};
    m.specular = {0.25, 0.5, 1};
    m.shininess = shininess;
    return m;
}

Light pointLight() {
    Light light;
    light.type = LightType::Point;
    light.position = kPoint + glm::dvec3(0, 3, 4);
    light.ambient = {0.2, 0.2, 0.2};
    light.diffuse = {1, 1, 1};
    light.specular = {1, 1, 1};
    light.attenuation = {1, 0, 0};
    return light;
}

const glm::dvec3 kAmbientPart{0.1 * 0.2, 0.2 * 0.2, 0.3 * 0.2};    // k_a·I_a = (0.02, 0.04, 0.06)
const glm::dvec3 kDiffusePart{0.5 * 0.8, 0.25 * 0.8, 0.125 * 0.8}; // k_d·I_d·(l·n) = (0.4, 0.2, 0.1)

glm::dvec3 shadeOne(const Light& light, const Material& material, LightingModel model, bool toon = false,
                    const SurfacePoint& point = kSurface) {
    const std::vector<Light> lights = {light};
    return shade(point, material, lights, ShadeOptions{model, toon});
}

TEST(Shade, PointLightPhongByHand) {
    // (0.02 + 0.4 + 0.25·0.64, 0.04 + 0.2 + 0.5·0.64, 0.06 + 0.1 + 1·0.64)
    EXPECT_VEC_NEAR(shadeOne(pointLight(), exampleMaterial(), LightingModel::Phong),
                    glm::dvec3(0.58, 0.56, 0.80), 1e-14);
}

TEST(Shade, PointLightBlinnPhongByHand) {
    // (0.02 + 0.4 + 0.25·0.9, 0.04 + 0.2 + 0.5·0.9, 0.06 + 0.1 + 1·0.9)
    EXPECT_VEC_NEAR(shadeOne(pointLight(), exampleMaterial(), LightingModel::BlinnPhong),
                    glm::dvec3(0.645, 0.69, 1.06), 1e-14);
}

TEST(Shade, ShininessIsTheExponentOfTheActiveModel) {
    for (double exponent : {1.0, 3.0, 32.0}) {
        SCOPED_TRACE(exponent);
        const glm::dvec3 ks = exampleMaterial().specular;
        EXPECT_VEC_NEAR(shadeOne(pointLight(), exampleMaterial(exponent), LightingModel::Phong),
                        kAmbientPart + kDiffusePart + ks * std::pow(0.8, exponent), 1e-14);
        EXPECT_VEC_NEAR(shadeOne(pointLight(), exampleMaterial(exponent), LightingModel::BlinnPhong),
                        kAmbientPart + kDiffusePart + ks * std::pow(1.8 / std::sqrt(3.6), exponent), 1e-14);
    }
}

TEST(Shade, MirrorDirectionGivesTheFullHighlight) {
    // Viewer on the reflected ray: v = r = (0, −0.6, 0.8), so v·r = 1 and h = n: spec = 1 for any exponent.
    const SurfacePoint mirror{kPoint, {0, 0, 1}, {0, -0.6, 0.8}};
    for (LightingModel model : kLightingModels) {
        SCOPED_TRACE(std::string(toString(model)));
        EXPECT_VEC_NEAR(shadeOne(pointLight(), exampleMaterial(50), model, false, mirror),
                        kAmbientPart + kDiffusePart + exampleMaterial().specular, 1e-12);
    }
}

TEST(Shade, AmbientLightContributesOnlyAmbient) {
    Light ambient;
    ambient.type = LightType::Ambient;
    ambient.ambient = {0.5, 1, 2};
    ambient.diffuse = {1, 1, 1}; // ignored: an ambient light has only I_a
    ambient.specular = {1, 1, 1};
    ambient.position = kPoint + glm::dvec3(0, 0, 1);
    for (LightingModel model : kLightingModels)
        for (bool toon : {false, true})
            EXPECT_VEC_NEAR(shadeOne(ambient, exampleMaterial(), model, toon), glm::dvec3(0.05, 0.2, 0.6),
                            1e-15);
}

TEST(Shade, AttenuationAtAKnownDistance) {
    Light light = pointLight();
    light.attenuation = {0.5, 0.25, 0.125}; // at t = 5: 0.5 + 1.25 + 3.125 = 4.875
    const glm::dvec3 ks = exampleMaterial().specular;
    EXPECT_VEC_NEAR(shadeOne(light, exampleMaterial(), LightingModel::Phong),
                    kAmbientPart + (kDiffusePart + 0.64 * ks) / 4.875, 1e-14);
    EXPECT_VEC_NEAR(shadeOne(light, exampleMaterial(), LightingModel::BlinnPhong),
                    kAmbientPart + (kDiffusePart + 0.9 * ks) / 4.875, 1e-14);
}

// Ambient is neither attenuated nor spot-limited (the seed's formula).
TEST(Shade, AmbientTermOfALightIsNotAttenuated) {
    Material ambientOnly = exampleMaterial();
    ambientOnly.diffuse = ambientOnly.specular = glm::dvec3(0);
    Light light = pointLight();
    light.attenuation = {0, 0, 1}; // 1/25 at t = 5
    EXPECT_VEC_NEAR(shadeOne(light, ambientOnly, LightingModel::Phong), kAmbientPart, 1e-15);
    light.position = kPoint + glm::dvec3(0, 300, 400);
    EXPECT_VEC_NEAR(shadeOne(light, ambientOnly, LightingModel::Phong), kAmbientPart, 1e-15);
}

TEST(Shade, DirectionalLightIsNotAttenuated) {
    Light light = pointLight();
    light.type = LightType::Directional;
    light.direction = {0, -3, -4};       // travels towards −l; not unit length
    light.position = {1000, 1000, 1000}; // ignored
    light.attenuation = {0, 0, 7};       // ignored
    EXPECT_VEC_NEAR(shadeOne(light, exampleMaterial(), LightingModel::Phong), glm::dvec3(0.58, 0.56, 0.80),
                    1e-14);
}

// ---- spot lights ----
// The spot sits at the point light's place and points straight down, d = −z: −l·d = 0.8, 36.87° off axis.

Light spotLight(double cutoffDeg, double exponent) {
    Light light = pointLight();
    light.type = LightType::Spot;
    light.direction = {0, 0, -2}; // not unit length
    light.cutoffDeg = cutoffDeg;
    light.exponent = exponent;
    return light;
}

TEST(Shade, SpotInsideTheConeScalesByCosineToTheExponent) {
    const glm::dvec3 ks = exampleMaterial().specular;
    // 0.8³ = 0.512
    EXPECT_VEC_NEAR(shadeOne(spotLight(40, 3), exampleMaterial(), LightingModel::Phong),
                    kAmbientPart + 0.512 * (kDiffusePart + 0.64 * ks), 1e-14);
    // Attenuation and spot multiply.
    Light attenuated = spotLight(40, 3);
    attenuated.attenuation = {0.5, 0.25, 0.125};
    EXPECT_VEC_NEAR(shadeOne(attenuated, exampleMaterial(), LightingModel::BlinnPhong),
                    kAmbientPart + 0.512 / 4.875 * (kDiffusePart + 0.9 * ks), 1e-14);
}

TEST(Shade, SpotExponentZeroInsideTheConeIsOne) {
    EXPECT_VEC_NEAR(shadeOne(spotLight(40, 0), exampleMaterial(), LightingModel::Phong),
                    shadeOne(pointLight(), exampleMaterial(), LightingModel::Phong), 1e-15);
    EXPECT_VEC_NEAR(shadeOne(spotLight(90, 0), exampleMaterial(), LightingModel::Phong),
                    glm::dvec3(0.58, 0.56, 0.80), 1e-14);
}

TEST(Shade, OutsideTheConeOnlyAmbientRemains) {
    for (double exponent : {0.0, 3.0}) {
        for (LightingModel model : kLightingModels) {
            SCOPED_TRACE(std::string(toString(model)) + " exponent " + std::to_string(exponent));
            EXPECT_VEC_NEAR(shadeOne(spotLight(30, exponent), exampleMaterial(), model), kAmbientPart, 1e-15);
            EXPECT_VEC_NEAR(shadeOne(spotLight(0, exponent), exampleMaterial(), model), kAmbientPart, 1e-15);
        }
    }
    // A spot pointing away from the surface.
    Light away = spotLight(80, 1);
    away.direction = {0, 0, 1};
    EXPECT_VEC_NEAR(shadeOne(away, exampleMaterial(), LightingModel::Phong), kAmbientPart, 1e-15);
}

// ---- guards ----

TEST(Shade, LightBehindTheSurfaceGivesNoDiffuseAndNoSpecular) {
    Light below = pointLight();
    below.position = kPoint + glm::dvec3(0, 3, -4); // l·n = −0.8
    // Viewer placed where the mirror highlight would be if the light were not gated.
    const SurfacePoint point{kPoint, {0, 0, 1}, glm::normalize(glm::dvec3(0, -0.6, -0.8))};
    for (const SurfacePoint& p : {kSurface, point})
        for (LightingModel model : kLightingModels)
            for (bool toon : {false, true})
                EXPECT_VEC_NEAR(shadeOne(below, exampleMaterial(), model, toon, p), kAmbientPart, 1e-15)
                    << toString(model) << (toon ? " toon" : "");
    // Grazing light, l·n = 0: no highlight either.
    Light grazing = pointLight();
    grazing.position = kPoint + glm::dvec3(0, 5, 0);
    const SurfacePoint facing{kPoint, {0, 0, 1}, {0, -1, 0}};
    for (LightingModel model : kLightingModels)
        EXPECT_VEC_NEAR(shadeOne(grazing, exampleMaterial(), model, false, facing), kAmbientPart, 1e-15)
            << toString(model);
}

TEST(Shade, PhongHighlightVanishesWhenTheViewerIsPastTheReflection) {
    // v·r < 0: the viewer is on the light's side, low. Diffuse stays, specular is 0 (max(v·r, 0)).
    const SurfacePoint point{kPoint, {0, 0, 1}, glm::normalize(glm::dvec3(0, 1, 0.1))};
    // r = (0, −0.6, 0.8); v·r = (−0.6 + 0.08)/|(0, 1, 0.1)| < 0
    EXPECT_VEC_NEAR(shadeOne(pointLight(), exampleMaterial(), LightingModel::Phong, false, point),
                    kAmbientPart + kDiffusePart, 1e-14);
}

TEST(Shade, ViewerOppositeTheLightIsFinite) {
    // v = −l makes v + l zero: the half-vector must not be normalized from nothing.
    for (const glm::dvec3& normal :
         {glm::dvec3(0, 0, 1), glm::dvec3(0, 0.6, 0.8), glm::dvec3(0, -0.6, 0.8)}) {
        const SurfacePoint point{kPoint, normal, {0, -0.6, -0.8}};
        for (LightingModel model : kLightingModels) {
            for (bool toon : {false, true}) {
                const glm::dvec3 c = shadeOne(pointLight(), exampleMaterial(), model, toon, point);
                EXPECT_TRUE(finite(c)) << str(c);
                EXPECT_TRUE(glm::all(glm::greaterThanEqual(c, kAmbientPart - 1e-15))) << str(c);
            }
        }
    }
}

TEST(Shade, ExtremeShininessIsFinite) {
    const glm::dvec3 ks = exampleMaterial().specular;
    for (LightingModel model : kLightingModels) {
        SCOPED_TRACE(std::string(toString(model)));
        const glm::dvec3 soft = shadeOne(pointLight(), exampleMaterial(1), model);
        const glm::dvec3 sharp = shadeOne(pointLight(), exampleMaterial(1e4), model);
        EXPECT_TRUE(finite(soft)) << str(soft);
        EXPECT_TRUE(finite(sharp)) << str(sharp);
        // 0.8^1e4 and 0.95^1e4 underflow to (nearly) 0: only ambient and diffuse remain.
        EXPECT_VEC_NEAR(sharp, kAmbientPart + kDiffusePart, 1e-15);
        const double spec1 = model == LightingModel::Phong ? 0.8 : 1.8 / std::sqrt(3.6);
        EXPECT_VEC_NEAR(soft, kAmbientPart + kDiffusePart + spec1 * ks, 1e-14);
    }
    // At the mirror direction a huge exponent still gives exactly the full highlight.
    const SurfacePoint mirror{kPoint, {0, 0, 1}, {0, -0.6, 0.8}};
    const glm::dvec3 c = shadeOne(pointLight(), exampleMaterial(1e4), LightingModel::Phong, false, mirror);
    EXPECT_TRUE(finite(c));
    EXPECT_VEC_NEAR(c, kAmbientPart + kDiffusePart + ks, 1e-10);
}

// A light exactly at the shaded point: t = 0, l undefined. The result must stay finite for every valid
// attenuation (a, b, c >= 0 with a + b + c > 0), including the physical inverse-square law (0, 0, 1).
TEST(Shade, LightAtTheSurfacePointIsFinite) {
    for (const glm::dvec3& attenuation :
         {glm::dvec3(1, 0, 0), glm::dvec3(1, 1, 1), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)}) {
        for (LightType type : {LightType::Point, LightType::Spot}) {
            Light light = pointLight();
            light.type = type;
            light.position = kPoint;
            light.attenuation = attenuation;
            light.cutoffDeg = 45;
            Material material = exampleMaterial();
            material.diffuse.x = 0; // 0·∞ would be NaN
            for (LightingModel model : kLightingModels) {
                const glm::dvec3 c = shadeOne(light, material, model);
                EXPECT_TRUE(finite(c)) << str(c) << " for attenuation " << str(attenuation) << ", "
                                       << toString(type) << ", " << toString(model);
            }
        }
    }
}

TEST(Shade, LightsSumLinearly) {
    Light directional;
    directional.type = LightType::Directional;
    directional.direction = {1, -1, -2};
    directional.diffuse = {0.3, 0.6, 0.9};
    directional.specular = {0.5, 0.5, 0.5};
    Light ambient;
    ambient.type = LightType::Ambient;
    ambient.ambient = {0.1, 0.1, 0.3};
    Light attenuated = pointLight();
    attenuated.position = kPoint + glm::dvec3(-2, 1, 1);
    attenuated.attenuation = {1, 0.1, 0.01};
    const std::vector<Light> lights = {pointLight(), spotLight(40, 3), directional,
                                       ambient,      attenuated,       spotLight(20, 1)};
    const SurfacePoint point{kPoint, glm::normalize(glm::dvec3(0.1, -0.2, 1)),
                             glm::normalize(glm::dvec3(0.3, 0.1, 1))};
    for (LightingModel model : kLightingModels) {
        for (bool toon : {false, true}) {
            glm::dvec3 sum(0);
            for (const Light& light : lights) sum += shadeOne(light, exampleMaterial(8), model, toon, point);
            const glm::dvec3 all = shade(point, exampleMaterial(8), lights, ShadeOptions{model, toon});
            EXPECT_VEC_NEAR(all, sum, 1e-14) << toString(model) << (toon ? " toon" : "");
            EXPECT_GT(all.x, 0);
        }
    }
    EXPECT_EQ(shade(point, exampleMaterial(), std::span<const Light>{}, ShadeOptions{}), glm::dvec3(0));
}

// One term (ShadeOptions::term): shade() returns that sum of shadeTerms alone, and it equals the whole
// equation evaluated with the other terms' coefficients at 0 (onlyTerm, what the renderer draws): the two
// ways of drawing a term agree, for every light type, both lighting models, with and without toon.
TEST(Shade, OneTermIsThatSumAndTheWholeEquationWithTheOthersAtZero) {
    Light ambient;
    ambient.type = LightType::Ambient;
    ambient.ambient = {0.1, 0.1, 0.3};
    Light point = pointLight();
    point.ambient = {0.2, 0.1, 0.1};
    point.attenuation = {1, 0.1, 0.01};
    const std::vector<Light> lights = {point, spotLight(40, 3), ambient};
    const SurfacePoint p{kPoint, glm::normalize(glm::dvec3(0.1, -0.2, 1)),
                         glm::normalize(glm::dvec3(0.3, 0.1, 1))};
    for (LightingModel model : kLightingModels)
        for (bool toon : {false, true}) {
            const LightTerms terms = shadeTerms(p, exampleMaterial(8), lights, ShadeOptions{model, toon});
            EXPECT_GT(glm::length(terms.ambient), 0);
            EXPECT_GT(glm::length(terms.diffuse), 0);
            if (!toon) { // toon's highlight is thresholded: this point lies below it
                EXPECT_GT(glm::length(terms.specular), 0);
            }
            glm::dvec3 sum(0);
            for (LightingTerm term : kLightingTerms) {
                const ShadeOptions options{model, toon, kToonBands, term};
                const glm::dvec3 picked = shade(p, exampleMaterial(8), lights, options);
                const glm::dvec3 zeroed =
                    shade(p, onlyTerm(exampleMaterial(8), term), lights, ShadeOptions{model, toon});
                EXPECT_VEC_NEAR(picked, zeroed, 1e-15) << toString(term);
                EXPECT_VEC_NEAR(picked, terms.of(term), 0) << toString(term);
                if (term != LightingTerm::All) sum += picked;
            }
            EXPECT_VEC_NEAR(sum, terms.total(), 1e-15);
            EXPECT_VEC_NEAR(terms.of(LightingTerm::Diffuse), terms.diffuse, 0);
        }
    const Material m = onlyTerm(exampleMaterial(8), LightingTerm::Specular);
    EXPECT_EQ(m.ambient, glm::dvec3(0));
    EXPECT_EQ(m.diffuse, glm::dvec3(0));
    EXPECT_EQ(m.specular, exampleMaterial(8).specular);
    EXPECT_EQ(m.shininess, 8);
    EXPECT_EQ(onlyTerm(exampleMaterial(8), LightingTerm::All), exampleMaterial(8));
}

// ---- toon ----

// Directional light from angle θ off the normal in the y–z plane: l·n = cos θ.
Light directionalAt(double cosine) {
    Light light;
    light.type = LightType::Directional;
    light.direction = -glm::dvec3(0, std::sqrt(1 - cosine * cosine), cosine);
    light.ambient = {0.2, 0.2, 0.2};
    return light;
}

TEST(Shade, ToonQuantizesDiffuseIntoBands) {
    ASSERT_EQ(kToonBands, 4);
    Material diffuseOnly = exampleMaterial();
    diffuseOnly.specular = glm::dvec3(0);
    struct Case {
        double cosine, band; // band = ceil(cosine·4)/4
    };
    for (const Case c : {Case{0.95, 1.0}, Case{0.8, 1.0}, Case{0.6, 0.75}, Case{0.45, 0.5}, Case{0.3, 0.5},
                         Case{0.2, 0.25}, Case{0.01, 0.25}, Case{-0.5, 0.0}}) {
        SCOPED_TRACE("l·n = " + std::to_string(c.cosine));
        const glm::dvec3 toon = shadeOne(directionalAt(c.cosine), diffuseOnly, LightingModel::Phong, true);
        EXPECT_VEC_NEAR(toon, kAmbientPart + diffuseOnly.diffuse * c.band, 1e-14);
        const glm::dvec3 smooth = shadeOne(directionalAt(c.cosine), diffuseOnly, LightingModel::Phong, false);
        EXPECT_VEC_NEAR(smooth, kAmbientPart + diffuseOnly.diffuse * std::max(c.cosine, 0.0), 1e-14);
    }
}

TEST(Shade, ToonHighlightIsAThreshold) {
    ASSERT_EQ(kToonHighlight, 0.5);
    const glm::dvec3 ks = exampleMaterial().specular;
    const glm::dvec3 base = kAmbientPart + glm::dvec3(0.5, 0.25, 0.125); // l·n = 0.8 → band 1
    // Phong α = 2: 0.64 > 0.5 → full highlight; α = 4: 0.4096 < 0.5 → none.
    EXPECT_VEC_NEAR(shadeOne(pointLight(), exampleMaterial(2), LightingModel::Phong, true), base + ks, 1e-14);
    EXPECT_VEC_NEAR(shadeOne(pointLight(), exampleMaterial(4), LightingModel::Phong, true), base, 1e-14);
    // Blinn-Phong β = 2: 0.9 → full; β = 16: 0.9^8 = 0.430 → none.
    EXPECT_VEC_NEAR(shadeOne(pointLight(), exampleMaterial(2), LightingModel::BlinnPhong, true), base + ks,
                    1e-14);
    EXPECT_VEC_NEAR(shadeOne(pointLight(), exampleMaterial(16), LightingModel::BlinnPhong, true), base,
                    1e-14);
}

// ---- helpers ----

TEST(ClampColor, ClampsToUnitRangeAndMapsNaNToZero) {
    EXPECT_EQ(clampColor({-0.5, 0.25, 3}), glm::dvec3(0, 0.25, 1));
    EXPECT_EQ(clampColor({0, 1, 0.999}), glm::dvec3(0, 1, 0.999));
    EXPECT_EQ(clampColor({kNaN, -kNaN, 0.5}), glm::dvec3(0, 0, 0.5));
    EXPECT_EQ(clampColor({kInf, -kInf, -0.0}), glm::dvec3(1, 0, 0));
}

TEST(SafeNormalize, NormalizesOrdinaryVectors) {
    const glm::dvec3 fallback{0, 0, 1};
    EXPECT_VEC_NEAR(safeNormalize({3, 4, 0}, fallback), glm::dvec3(0.6, 0.8, 0), 1e-15);
    EXPECT_VEC_NEAR(safeNormalize({0, -3e-3, 4e-3}, fallback), glm::dvec3(0, -0.6, 0.8), 1e-15);
    EXPECT_VEC_NEAR(safeNormalize({-2e5, 0, 0}, fallback), glm::dvec3(-1, 0, 0), 1e-15);
}

// "fallback when |v| is too small to normalize": a huge but finite vector is not too small.
TEST(SafeNormalize, NormalizesHugeVectors) {
    const glm::dvec3 fallback{0, 0, 1};
    EXPECT_VEC_NEAR(safeNormalize({3e160, 4e160, 0}, fallback), glm::dvec3(0.6, 0.8, 0), 1e-15);
    EXPECT_VEC_NEAR(safeNormalize({0, -1e300, 0}, fallback), glm::dvec3(0, -1, 0), 1e-15);
}

TEST(SafeNormalize, FallsBackForZeroAndTinyVectors) {
    const glm::dvec3 fallback{0.6, 0, 0.8};
    const double denormal = std::numeric_limits<double>::denorm_min();
    for (const glm::dvec3& v : {glm::dvec3(0), glm::dvec3(-0.0, 0, -0.0), glm::dvec3(1e-200, 0, 0),
                                glm::dvec3(denormal, denormal, -denormal), glm::dvec3(0, 1e-30, 1e-30)}) {
        const glm::dvec3 n = safeNormalize(v, fallback);
        EXPECT_EQ(n, fallback) << "v " << str(v) << " gave " << str(n);
    }
}

// ---- enum spellings ----

// DESIGN §3's viewer: towards the eye under perspective, +z under orthographic projection, and — the one
// fallback rule C++ and GLSL share — the normal for a viewer exactly on the surface.
TEST(ToViewer, TowardsTheEyePlusZOrthographicAndTheNormalOnTheSurface) {
    const glm::dvec3 n = glm::normalize(glm::dvec3(1, 2, 2));
    const glm::dvec3 p(3, 0, -4);
    const glm::dvec3 v = toViewer(p, n, false);
    EXPECT_NEAR(v.x, -0.6, 1e-15);
    EXPECT_NEAR(v.z, 0.8, 1e-15);
    EXPECT_EQ(toViewer(p, n, true), glm::dvec3(0, 0, 1));
    EXPECT_EQ(toViewer(glm::dvec3(0), n, false), n);
    EXPECT_EQ(toViewer(glm::dvec3(kTinyComponent / 2, 0, 0), n, false), n) << "below the guard: the normal";
    EXPECT_EQ(toViewer(glm::dvec3(0), n, true), glm::dvec3(0, 0, 1));
}

TEST(EnumSpelling, EveryValueRoundTrips) {
    const std::vector<std::pair<ShadingMode, std::string_view>> shading = {{ShadingMode::Flat, "flat"},
                                                                           {ShadingMode::Gouraud, "gouraud"},
                                                                           {ShadingMode::Phong, "phong"},
                                                                           {ShadingMode::Toon, "toon"}};
    ASSERT_EQ(shading.size(), kShadingModes.size());
    for (const auto& [mode, spelling] : shading) {
        EXPECT_EQ(toString(mode), spelling);
        EXPECT_EQ(parseShadingMode(spelling), mode);
    }
    for (ShadingMode mode : kShadingModes) EXPECT_EQ(parseShadingMode(toString(mode)), mode);

    const std::vector<std::pair<LightingModel, std::string_view>> lighting = {
        {LightingModel::Phong, "phong"}, {LightingModel::BlinnPhong, "blinn-phong"}};
    ASSERT_EQ(lighting.size(), kLightingModels.size());
    for (const auto& [model, spelling] : lighting) {
        EXPECT_EQ(toString(model), spelling);
        EXPECT_EQ(parseLightingModel(spelling), model);
    }
    for (LightingModel model : kLightingModels) EXPECT_EQ(parseLightingModel(toString(model)), model);

    const std::vector<std::pair<LightType, std::string_view>> types = {
        {LightType::Ambient, "ambient"},
        {LightType::Directional, "directional"},
        {LightType::Point, "point"},
        {LightType::Spot, "spot"}};
    for (const auto& [type, spelling] : types) EXPECT_EQ(toString(type), spelling);
    EXPECT_EQ(joinNames(kLightingTerms), "all, ambient, diffuse, specular");
}

TEST(EnumSpelling, UnknownSpellingsAreRejected) {
    using namespace std::string_view_literals;
    for (std::string_view text : {""sv, "Flat"sv, "PHONG"sv, "smooth"sv, " phong"sv, "phong "sv,
                                  "gouraud\0"sv, "blinn-phong"sv, "flatt"sv})
        EXPECT_FALSE(parseShadingMode(text).has_value()) << "\"" << text << "\"";
    for (std::string_view text :
         {""sv, "Phong"sv, "blinn_phong"sv, "blinnphong"sv, "Blinn-Phong"sv, "blinn"sv, "toon"sv, "flat"sv})
        EXPECT_FALSE(parseLightingModel(text).has_value()) << "\"" << text << "\"";
}

// ---- transformLight ----

TEST(TransformLight, MovesPositionsWithTranslationAndDirectionsWithout) {
    // Rotate 90° about z, then translate by (1, 2, 3).
    const glm::dmat4 m = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3)),
                                     std::numbers::pi / 2, glm::dvec3(0, 0, 1));
    Light light = spotLight(25, 4);
    light.position = {1, 0, 0};
    light.direction = {2, 0, 0};
    light.attenuation = {0.5, 0.25, 0.125};
    const Light moved = transformLight(light, m);
    EXPECT_VEC_NEAR(moved.position, glm::dvec3(1, 3, 3), 1e-15);  // (0, 1, 0) + (1, 2, 3)
    EXPECT_VEC_NEAR(moved.direction, glm::dvec3(0, 1, 0), 1e-15); // rotated, not translated, made unit
    EXPECT_EQ(moved.type, light.type);
    EXPECT_EQ(moved.ambient, light.ambient);
    EXPECT_EQ(moved.diffuse, light.diffuse);
    EXPECT_EQ(moved.specular, light.specular);
    EXPECT_EQ(moved.cutoffDeg, light.cutoffDeg);
    EXPECT_EQ(moved.exponent, light.exponent);
    EXPECT_EQ(moved.attenuation, light.attenuation);

    // A pure translation leaves directions alone (made unit: [2, 0, 0] is [1, 0, 0]).
    const Light shifted = transformLight(light, glm::translate(glm::dmat4(1.0), glm::dvec3(-5, 6, 7)));
    EXPECT_EQ(shifted.direction, glm::dvec3(1, 0, 0));
    EXPECT_VEC_NEAR(shifted.position, glm::dvec3(-4, 6, 7), 1e-15);
}

// Shading is invariant under a rigid move of the whole scene (what bringing lights into view space relies
// on).
TEST(TransformLight, ShadingIsInvariantUnderARigidMove) {
    const glm::dmat4 m = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(-3, 0.5, 8)), 1.1,
                                     glm::normalize(glm::dvec3(1, -2, 0.5)));
    const glm::dmat3 r(m);
    const std::vector<Light> lights = {pointLight(), spotLight(40, 3), directionalAt(0.6)};
    std::vector<Light> moved;
    for (const Light& light : lights) moved.push_back(transformLight(light, m));
    const SurfacePoint point{kPoint, glm::normalize(glm::dvec3(0.1, -0.2, 1)),
                             glm::normalize(glm::dvec3(0.3, 0.1, 1))};
    const SurfacePoint movedPoint{glm::dvec3(m * glm::dvec4(point.position, 1)), r * point.normal,
                                  r * point.toViewer};
    for (LightingModel model : kLightingModels) {
        const glm::dvec3 before = shade(point, exampleMaterial(8), lights, ShadeOptions{model, false});
        const glm::dvec3 after = shade(movedPoint, exampleMaterial(8), moved, ShadeOptions{model, false});
        EXPECT_VEC_NEAR(after, before, 1e-12) << toString(model);
    }
}

// A direction is scale-free: [1e-30, 0, 0] used to light differently from [1, 0, 0] in the
// renderer, the reference and the unit direction, because 1e-30 fell under the "zero" threshold.
TEST(TransformLight, DirectionsOfAnyScaleLightAlike) {
    const glm::dmat4 view = glm::rotate(glm::dmat4(1.0), 0.3, glm::dvec3(0, 1, 0));
    Light unit = spotLight(25, 4);
    unit.direction = {1, -2, 0.5};
    const glm::dvec3 expected = transformLight(unit, view).direction;
    EXPECT_NEAR(glm::length(expected), 1.0, 1e-15);
    for (double scale : {1e-30, 1e-300, 1e30, 1e300}) {
        Light scaled = unit;
        scaled.direction = unit.direction * scale;
        EXPECT_VEC_NEAR(transformLight(scaled, view).direction, expected, 1e-15) << "scale " << scale;
    }
    EXPECT_VEC_NEAR(unitDirection(glm::dvec3(1e-320, 0, 0)), glm::dvec3(1, 0, 0), 0);
    EXPECT_VEC_NEAR(unitDirection(glm::dvec3(0, -1e308, 1e308)), glm::normalize(glm::dvec3(0, -1, 1)), 1e-15);
}

} // namespace
} // namespace shadelab
