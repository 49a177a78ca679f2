#include "shadelab/shading/lighting.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "shadelab/vocabulary.h"

namespace shadelab {

glm::dvec3 toViewer(const glm::dvec3& positionView, const glm::dvec3& normalView, bool orthographic) {
    return orthographic ? glm::dvec3(0, 0, 1) : safeNormalize(-positionView, normalView);
}

std::pair<glm::dvec3, double> toLight(const Light& light, const SurfacePoint& point) {
    if (light.type == LightType::Directional) return {-safeNormalize(light.direction, point.normal), 0.0};
    const glm::dvec3 d = light.position - point.position;
    // A light exactly on the surface lights it head-on rather than from an undefined direction.
    return {safeNormalize(d, point.normal), glm::length(d)};
}

double attenuation(const Light& light, double t) {
    if (light.type == LightType::Directional) return 1;
    const glm::dvec3& k = light.attenuation;
    // a, b, c >= 0 with a positive sum is validated, but a = 0 with the light on the surface (t = 0) would
    // still divide by zero: the floor keeps the result finite (the colour is clamped anyway).
    return 1 / std::max(k.x + k.y * t + k.z * t * t, kMinAttenuationDenominator);
}

double spotFactor(const Light& light, const glm::dvec3& l) {
    if (light.type != LightType::Spot) return 1;
    const glm::dvec3 d = safeNormalize(light.direction, -l);
    const double cosAngle = glm::dot(-l, d);
    if (cosAngle < std::cos(light.cutoffDeg * std::numbers::pi / 180)) return 0;
    // Exponent 0 gives 1 even at cos = 0 (a 90° cone's rim), where GLSL's pow(0, 0) is undefined.
    return light.exponent > 0 ? std::pow(std::max(cosAngle, 0.0), light.exponent) : 1.0;
}

glm::dvec3 specularVector(const SurfacePoint& p, const glm::dvec3& l, LightingModel model) {
    if (model == LightingModel::Phong) return -l + 2 * glm::dot(l, p.normal) * p.normal;
    return safeNormalize(p.toViewer + l, p.normal);
}

double specular(const SurfacePoint& p, const glm::dvec3& l, double shininess, LightingModel model) {
    const double exponent = std::max(shininess, 1.0); // pow(0, 0) is undefined in GLSL
    const glm::dvec3 rh = specularVector(p, l, model);
    const double cosine = model == LightingModel::Phong ? glm::dot(p.toViewer, rh) : glm::dot(p.normal, rh);
    return std::pow(std::max(cosine, 0.0), exponent);
}

std::string_view toString(ShadingMode mode) {
    switch (mode) {
    case ShadingMode::Flat:
        return "flat";
    case ShadingMode::Gouraud:
        return "gouraud";
    case ShadingMode::Phong:
        return "phong";
    case ShadingMode::Toon:
        return "toon";
    case ShadingMode::Exact:
        return "exact";
    }
    return "?";
}

std::string_view toString(LightingModel model) {
    return model == LightingModel::Phong ? "phong" : "blinn-phong";
}

std::string_view toString(LightType type) {
    switch (type) {
    case LightType::Ambient:
        return "ambient";
    case LightType::Directional:
        return "directional";
    case LightType::Point:
        return "point";
    case LightType::Spot:
        return "spot";
    }
    return "?";
}

std::optional<ShadingMode> parseShadingMode(std::string_view text) {
    return parseName(text, kAllShadingModes);
}
std::optional<LightingModel> parseLightingModel(std::string_view text) {
    return parseName(text, kLightingModels);
}

std::string_view toString(LightingTerm term) {
    switch (term) {
    case LightingTerm::All:
        return "all";
    case LightingTerm::Ambient:
        return "ambient";
    case LightingTerm::Diffuse:
        return "diffuse";
    case LightingTerm::Specular:
        return "specular";
    }
    return "unknown";
}

Material onlyTerm(const Material& material, LightingTerm term) {
    const glm::dvec3 none(0.0);
    Material out = material;
    if (term != LightingTerm::All && term != LightingTerm::Ambient) out.ambient = none;
    if (term != LightingTerm::All && term != LightingTerm::Diffuse) out.diffuse = none;
    if (term != LightingTerm::All && term != LightingTerm::Specular) out.specular = none;
    return out;
}

glm::dvec3 LightTerms::of(LightingTerm term) const {
    switch (term) {
    case LightingTerm::Ambient:
        return ambient;
    case LightingTerm::Diffuse:
        return diffuse;
    case LightingTerm::Specular:
        return specular;
    case LightingTerm::All:
        break;
    }
    return total();
}

Light transformLight(const Light& light, const glm::dmat4& m) {
    Light out = light;
    out.position = glm::dvec3(m * glm::dvec4(light.position, 1.0));
    // A direction is scale-free: made unit in double first, so [1e-30, 0, 0] lights exactly as [1, 0, 0]
    // in the renderer (float uniforms) and in the reference alike.
    out.direction = unitDirection(glm::dmat3(m) * unitDirection(light.direction));
    return out;
}

glm::dvec3 unitDirection(const glm::dvec3& v) {
    const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (!(largest > 0) || !std::isfinite(largest)) return v; // validation refuses zero and non-finite
    const glm::dvec3 scaled = v / largest;                   // exact for any finite scale, subnormals too
    return scaled / glm::length(scaled);
}

glm::dvec3 safeNormalize(const glm::dvec3& v, const glm::dvec3& fallback) {
    // Scaling by the largest component first keeps |v|² from overflowing for huge vectors.
    const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (!(largest > kTinyComponent) || !std::isfinite(largest)) return fallback;
    const glm::dvec3 scaled = v / largest;
    return scaled / glm::length(scaled);
}

glm::dvec3 capColor(const glm::dvec3& color) {
    return glm::min(color, glm::dvec3(kMaxColorComponent));
}

LightTerms shadeTerms(const SurfacePoint& p, const Material& uncapped, std::span<const Light> lights,
                      ShadeOptions options) {
    const Material material{capColor(uncapped.ambient), capColor(uncapped.diffuse),
                            capColor(uncapped.specular), uncapped.shininess};
    LightTerms terms;
    for (const Light& uncappedLight : lights) {
        Light light = uncappedLight;
        light.ambient = capColor(light.ambient);
        light.diffuse = capColor(light.diffuse);
        light.specular = capColor(light.specular);
        terms.ambient += material.ambient * light.ambient; // neither attenuated nor spot-limited
        if (light.type == LightType::Ambient) continue;

        const auto [l, t] = toLight(light, p);
        const double factor = attenuation(light, t) * spotFactor(light, l);
        const double lDotN = glm::dot(l, p.normal);
        double diffuse = std::max(lDotN, 0.0);
        double spec = lDotN > 0 ? specular(p, l, material.shininess, options.model) : 0.0;
        if (options.toon) {
            diffuse = std::ceil(diffuse * options.toonBands) / options.toonBands;
            spec = spec > kToonHighlight ? 1.0 : 0.0;
        }
        terms.diffuse += factor * material.diffuse * light.diffuse * diffuse;
        terms.specular += factor * material.specular * light.specular * spec;
    }
    return terms;
}

glm::dvec3 shade(const SurfacePoint& p, const Material& material, std::span<const Light> lights,
                 ShadeOptions options) {
    return shadeTerms(p, material, lights, options).of(options.term);
}

namespace {

// A non-negative double as the nearest float, or the largest float where it is beyond float's range.
float finiteFloat(double value) {
    return float(std::min(value, double(std::numeric_limits<float>::max())));
}

} // namespace

LightValues lightValues(const Light& light, const Material& material) {
    LightValues v;
    v.ambientProduct = glm::vec3(capColor(material.ambient) * capColor(light.ambient));
    v.diffuseProduct = glm::vec3(capColor(material.diffuse) * capColor(light.diffuse));
    v.specularProduct = glm::vec3(capColor(material.specular) * capColor(light.specular));
    v.attenuation = {finiteFloat(light.attenuation.x), finiteFloat(light.attenuation.y),
                     finiteFloat(light.attenuation.z)};
    v.cosCutoff = float(std::cos(light.cutoffDeg * std::numbers::pi / 180));
    v.exponent = finiteFloat(light.exponent);
    return v;
}

glm::vec3 ambientProduct(std::span<const Light> lights, const Material& material) {
    glm::dvec3 sum(0); // k_a·ΣI_a = Σk_a·I_a
    for (const Light& light : lights) sum += capColor(light.ambient);
    return glm::vec3(capColor(material.ambient) * capColor(sum));
}

float shininessValue(const Material& material) {
    return finiteFloat(std::max(material.shininess, 1.0));
}

glm::dvec3 clampColor(const glm::dvec3& c) {
    auto clamp01 = [](double x) { return x > 0 ? std::min(x, 1.0) : 0.0; }; // NaN → 0
    return {clamp01(c.x), clamp01(c.y), clamp01(c.z)};
}

} // namespace shadelab
