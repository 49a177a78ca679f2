#include "shadelab/gl/program_variant.h"

#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>
#include <tuple>

#include "shadelab/errors.h"
#include "shadelab/io/text.h"

namespace shadelab::gl {
namespace {

// A GLSL float literal that reads back as `value` exactly: nine significant digits round-trip any float,
// and a literal needs a point or an exponent (ES 3.00 converts no int to float). GLSL has no literal for
// Inf or NaN; the values are finite by construction (lightValues), so one here is a bug.
std::string glslFloat(float value) {
    if (!std::isfinite(value))
        throw RuntimeError("internal error: a non-finite value was to be compiled into a shader");
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(value)); // shadelab never sets a locale: "."
    std::string literal = text;
    if (literal.find_first_of(".e") == std::string::npos) literal += ".0";
    return literal;
}

std::string glslVec3(const glm::vec3& v) {
    return "vec3(" + glslFloat(v.x) + ", " + glslFloat(v.y) + ", " + glslFloat(v.z) + ")";
}

} // namespace

ProgramVariant ProgramVariant::uber(ShadingMode shading, LightingModel lighting) {
    ProgramVariant v;
    v.shading = shading;
    v.lighting = lighting;
    return v;
}

ProgramVariant ProgramVariant::forScene(const Scene& scene, bool specialize) {
    ProgramVariant v = uber(scene.shading, scene.lighting);
    if (!specialize) return v;
    v.specialized = true;
    v.ambient = v.attenuation = false;
    bool lightSpecular = false, objectSpecular = false;
    for (const Light& light : scene.lights) {
        v.directional += light.type == LightType::Directional;
        v.point += light.type == LightType::Point;
        v.spot += light.type == LightType::Spot;
        v.ambient |= light.ambient != glm::dvec3(0);
        const bool positional = light.type == LightType::Point || light.type == LightType::Spot;
        v.attenuation |= positional && light.attenuation != glm::dvec3(1, 0, 0);
        lightSpecular |= light.type != LightType::Ambient && light.specular != glm::dvec3(0);
    }
    for (const SceneObject& object : scene.objects)
        objectSpecular |= object.material.specular != glm::dvec3(0);
    v.specular = lightSpecular && objectSpecular;
    v.viewerAtInfinity = scene.projection.type == ProjectionType::Orthographic;
    return v;
}

ProgramVariant ProgramVariant::withValues(const Scene& scene, const Material& material) const {
    ProgramVariant v = *this;
    if (!specialized) return v;
    std::string& text = v.values;
    text = "#define VALUES_COMPILED_IN\n";
    const float shininess = shininessValue(material);
    text += "#define SHININESS " + glslFloat(shininess) + "\n";
    if (shininess <= 2047 && shininess == std::floor(shininess)) // the bits lighting.glsl's loop reads
        text += "#define SHININESS_INTEGER " + std::to_string(int(shininess)) + "\n";
    if (ambient) text += "#define AMBIENT_PRODUCT " + glslVec3(ambientProduct(scene.lights, material)) + "\n";
    if (shading == ShadingMode::Toon || exactToon) {
        text += "#define TOON_BANDS " + glslFloat(float(scene.toonBands)) + "\n";
        text += "#define TOON_BAND_WIDTH " + glslFloat(float(1.0 / scene.toonBands)) + "\n";
    }
    // One LightValues(...) list per light type, in scene order within a type: the order of the uniform
    // arrays the light geometry goes to (renderer.cpp forEachLightSlot), indexed as its LIGHT_* codes.
    static_assert(int(LightType::Directional) == 1 && int(LightType::Point) == 2 &&
                  int(LightType::Spot) == 3);
    std::string lists[4];
    for (const Light& light : scene.lights) {
        if (light.type == LightType::Ambient) continue;
        const LightValues l = lightValues(light, material);
        std::string& list = lists[int(light.type)];
        list += std::string(list.empty() ? "" : ", ") + "LightValues(" + glslVec3(l.diffuseProduct) + ", " +
                glslVec3(l.specularProduct) + ", " + glslVec3(l.attenuation) + ", " + glslFloat(l.cosCutoff) +
                ", " + glslFloat(l.exponent) + ")";
    }
    static constexpr const char* kListNames[] = {"", "DIRECTIONAL_VALUES", "POINT_VALUES", "SPOT_VALUES"};
    for (int type = 1; type < 4; ++type)
        if (!lists[type].empty())
            text += std::string("#define ") + kListNames[type] + " LightValues[](" + lists[type] + ")\n";
    return v;
}

bool ProgramVariant::operator<(const ProgramVariant& other) const {
    // Every field, in declaration order: one left out would let the cache hand a variant another's program.
    auto key = [](const ProgramVariant& v) {
        return std::tie(v.shading, v.lighting, v.specialized, v.flatGeometryShader, v.directional, v.point,
                        v.spot, v.ambient, v.attenuation, v.specular, v.viewerAtInfinity, v.exactToon,
                        v.ndcView, v.twoSided, v.exactPatches, v.objectIdAlpha, v.values);
    };
    return key(*this) < key(other);
}

std::string ProgramVariant::name() const {
    std::string text = std::string(toString(shading)) + (flatGeometryShader ? "(gs)" : "") +
                       (exactToon ? "(toon)" : "") + (ndcView ? "(ndc)" : "") +
                       (twoSided ? "(two-sided)" : "") + (exactPatches ? "(patches)" : "") +
                       (objectIdAlpha ? "(ids)" : "") + "/" + std::string(toString(lighting));
    if (!specialized) return text;
    text += "+d" + std::to_string(directional) + "p" + std::to_string(point) + "s" + std::to_string(spot);
    if (!ambient) text += "-ambient";
    if (!attenuation) text += "-attenuation";
    if (!specular) text += "-specular";
    if (viewerAtInfinity) text += "+ortho";
    if (!values.empty()) text += "+values";
    return text;
}

std::string ProgramVariant::defines() const {
    // What src/shading/lighting.cpp owns and shaders/lighting.glsl reads: the limits, DESIGN §3's guards, and
    // the LightType codes of the uber program's uLights[i].type.
    std::string text = "#define MAX_LIGHTS " + std::to_string(kMaxLights) + "\n";
    text += "#define TOON_HIGHLIGHT " + glslFloat(float(kToonHighlight)) + "\n";
    text += "#define TINY_COMPONENT " + glslFloat(float(kTinyComponent)) + "\n";
    text += "#define MIN_ATTENUATION_DENOMINATOR " + glslFloat(float(kMinAttenuationDenominator)) + "\n";
    text += "#define MIN_LENGTH_SQUARED " + glslFloat(float(kMinLengthSquared)) + "\n";
    for (const LightType type : kLightTypes)
        text += "#define LIGHT_" + upperAscii(toString(type)) + " " + std::to_string(int(type)) + "\n";
    static constexpr const char* kShadingDefines[] = {"SHADING_FLAT", "SHADING_GOURAUD", "SHADING_PHONG",
                                                      "SHADING_TOON", "SHADING_EXACT"};
    static_assert(std::size(kShadingDefines) == kAllShadingModes.size());
    text += std::string("#define ") + kShadingDefines[int(shading)] + "\n";
    if (exactToon) text += "#define SHADING_TOON\n";
    if (lighting == LightingModel::BlinnPhong) text += "#define LIGHTING_BLINN_PHONG\n";
    if (flatGeometryShader) text += "#define FLAT_GEOMETRY_SHADER\n";
    if (ndcView) text += "#define NDC_VIEW\n";
    if (twoSided) text += "#define TWO_SIDED\n";
    if (exactPatches) text += "#define EXACT_PATCHES\n";
    if (objectIdAlpha) text += "#define OBJECT_ID_ALPHA\n";
    if (!specialized) return text;
    text += "#define SPECIALIZED\n";
    text += "#define NUM_DIRECTIONAL " + std::to_string(directional) + "\n";
    text += "#define NUM_POINT " + std::to_string(point) + "\n";
    text += "#define NUM_SPOT " + std::to_string(spot) + "\n";
    text += "#define HAS_AMBIENT " + std::to_string(int(ambient)) + "\n";
    text += "#define HAS_ATTENUATION " + std::to_string(int(attenuation)) + "\n";
    text += "#define HAS_SPECULAR " + std::to_string(int(specular)) + "\n";
    text += "#define NEEDS_NORMAL " + std::to_string(int(directional + point + spot > 0)) + "\n";
    if (viewerAtInfinity) text += "#define VIEWER_AT_INFINITY\n";
    return text + values;
}

} // namespace shadelab::gl
