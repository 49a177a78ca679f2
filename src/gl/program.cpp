#include "shadelab/gl/program.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include <glad/gl.h>

#include "gl/shader_sources.h"
#include "shadelab/errors.h"
#include "shadelab/gl/loader.h"

namespace shadelab::gl {
namespace {

// Source-string numbers in #line directives, so a driver message "1(23)" means lighting.glsl line 23.
constexpr const char* kLightingFile = "lighting.glsl";
constexpr int kLightingSourceNumber = 1;
constexpr int kStageSourceNumber = 2;

std::string_view shaderText(const char* name) {
    const auto text = embeddedShader(name);
    if (!text) throw RuntimeError(std::string("shader ") + name + " is not embedded in the binary");
    return *text;
}

std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
              : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    isProgram ? glGetProgramInfoLog(object, length, nullptr, log.data())
              : glGetShaderInfoLog(object, length, nullptr, log.data());
    log.resize(std::char_traits<char>::length(log.c_str()));
    return log;
}

// Compiles `source`; `where` names it in messages.
Shader compileSource(GLenum stage, const std::string& source, const std::string& where) {
    Shader shader(stage);
    const char* text = source.c_str();
    glShaderSource(shader.get(), 1, &text, nullptr);
    glCompileShader(shader.get());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    const std::string log = infoLog(shader.get(), false);
    if (!ok) throw RuntimeError("compiling " + where + " failed:\n" + log);
    if (!log.empty()) std::fprintf(stderr, "shadelab: compile log of %s:\n%s\n", where.c_str(), log.c_str());
    return shader;
}

Shader compileStage(GLenum stage, const char* file, const ProgramVariant& variant) {
    const char* stageDefine = stage == GL_VERTEX_SHADER     ? "#define VERTEX_STAGE\n"
                              : stage == GL_FRAGMENT_SHADER ? "#define FRAGMENT_STAGE\n"
                                                            : "#define GEOMETRY_STAGE\n";
    const std::string source = glslHeader() + variant.defines() + stageDefine + "#line 1 " +
                               std::to_string(kLightingSourceNumber) + "\n" +
                               std::string(shaderText(kLightingFile)) + "#line 1 " +
                               std::to_string(kStageSourceNumber) + "\n" + std::string(shaderText(file));
    return compileSource(stage, source,
                         std::string(file) + " (variant " + variant.name() + "; source 1 = " + kLightingFile +
                             ", source 2 = " + file + ")");
}

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

void linkOrThrow(const Program& program, const std::string& name) {
    glLinkProgram(program.get());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (!ok) throw RuntimeError("linking program " + name + " failed:\n" + infoLog(program.get(), true));
}

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

glm::vec3 ambientProduct(const std::vector<Light>& lights, const Material& material) {
    glm::dvec3 sum(0); // k_a·ΣI_a = Σk_a·I_a
    for (const Light& light : lights) sum += capColor(light.ambient);
    return glm::vec3(capColor(material.ambient) * capColor(sum));
}

float shininessValue(const Material& material) {
    return finiteFloat(std::max(material.shininess, 1.0));
}

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
                        v.ndcView, v.values);
    };
    return key(*this) < key(other);
}

std::string ProgramVariant::name() const {
    std::string text = std::string(toString(shading)) + (flatGeometryShader ? "(gs)" : "") +
                       (exactToon ? "(toon)" : "") + (ndcView ? "(ndc)" : "") + "/" +
                       std::string(toString(lighting));
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
    std::string text = "#define MAX_LIGHTS " + std::to_string(kMaxLights) + "\n";
    char highlight[32];
    std::snprintf(highlight, sizeof highlight, "%.9g", kToonHighlight); // shadelab never sets a locale: "."
    text += std::string("#define TOON_HIGHLIGHT ") + highlight + "\n";
    static constexpr const char* kShadingDefines[] = {"SHADING_FLAT", "SHADING_GOURAUD", "SHADING_PHONG",
                                                      "SHADING_TOON", "SHADING_EXACT"};
    static_assert(std::size(kShadingDefines) == kAllShadingModes.size());
    text += std::string("#define ") + kShadingDefines[int(shading)] + "\n";
    if (exactToon) text += "#define SHADING_TOON\n";
    if (lighting == LightingModel::BlinnPhong) text += "#define LIGHTING_BLINN_PHONG\n";
    if (flatGeometryShader) text += "#define FLAT_GEOMETRY_SHADER\n";
    if (ndcView) text += "#define NDC_VIEW\n";
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

Program buildProgram(const ProgramVariant& variant) {
    if (variant.flatGeometryShader && !capabilities().geometryShaders)
        throw RuntimeError("flat shading through a geometry shader (program " + variant.name() +
                           ") needs desktop OpenGL: " + std::string(displayName(capabilities().api)) +
                           " has no geometry stage; use the default flat layout");
    const bool exact = variant.shading == ShadingMode::Exact;
    const Shader vertex =
        compileStage(GL_VERTEX_SHADER, exact ? "exact.vert.glsl" : "surface.vert.glsl", variant);
    const Shader fragment =
        compileStage(GL_FRAGMENT_SHADER, exact ? "exact.frag.glsl" : "surface.frag.glsl", variant);
    Shader geometry{NoCreate};
    Program program;
    glAttachShader(program.get(), vertex.get());
    glAttachShader(program.get(), fragment.get());
    if (variant.flatGeometryShader) {
        geometry = compileStage(GL_GEOMETRY_SHADER, "surface.geom.glsl", variant);
        glAttachShader(program.get(), geometry.get());
    }
    linkOrThrow(program, variant.name());
    glDetachShader(program.get(), vertex.get());
    glDetachShader(program.get(), fragment.get());
    if (geometry) glDetachShader(program.get(), geometry.get());
    return program;
}

SurfaceProgram::SurfaceProgram(Program linked, const ProgramVariant& variant) : program(std::move(linked)) {
    const GLuint id = program.get();
    auto find = [id](const std::string& name) { return glGetUniformLocation(id, name.c_str()); };
    // Every variant uses its transform into clip space: a mesh's uClipFromObject, exact shading's uNdcRect.
    const bool exact = variant.shading == ShadingMode::Exact;
    const char* required = exact ? "uNdcRect" : "uClipFromObject";
    if (find(required) < 0)
        throw RuntimeError("program " + variant.name() + " has no uniform " + required +
                           ": the shaders and src/gl/program.cpp disagree on its name");
    at.clipFromObject = find("uClipFromObject");
    at.cameraClipFromObject = find("uCameraClipFromObject");
    at.ndcRect = find("uNdcRect");
    at.viewport = find("uViewport");
    at.nearRect = find("uNearRect");
    at.nearFar = find("uNearFar");
    at.objectFromView = find("uObjectFromView");
    at.centerView = find("uCenterView");
    at.clipFromView = find("uClipFromView");
    at.depthZeroToOne = find("uDepthZeroToOne");
    at.alpha = find("uAlpha");
    at.viewFromObject = find("uViewFromObject");
    at.normalViewFromObject = find("uNormalViewFromObject");
    at.handedness = find("uHandedness");
    at.shininess = find("uShininess");
    at.orthographic = find("uOrthographic");
    at.toonBands = find("uToonBands");
    at.toonBandWidth = find("uToonBandWidth");
    at.lightCount = find("uLightCount");
    at.ambientProduct = find("uAmbientProduct");
    auto lightsOf = [&](const std::string& array, int count, bool uber) {
        std::vector<LightLocations> out(std::size_t(std::max(count, 0)));
        for (int i = 0; i < count; ++i) {
            const std::string prefix = array + "[" + std::to_string(i) + "].";
            LightLocations& l = out[std::size_t(i)];
            if (uber) {
                l.type = find(prefix + "type");
                l.ambientProduct = find(prefix + "ambientProduct");
            }
            l.diffuseProduct = find(prefix + "diffuseProduct");
            l.specularProduct = find(prefix + "specularProduct");
            l.positionView = find(prefix + "positionView");
            l.directionView = find(prefix + "directionView");
            l.cosCutoff = find(prefix + "cosCutoff");
            l.exponent = find(prefix + "exponent");
            l.attenuation = find(prefix + "attenuation");
        }
        return out;
    };
    if (!variant.specialized) {
        at.lights[0] = lightsOf("uLights", kMaxLights, true);
    } else {
        at.lights[1] = lightsOf("uDirectionalLights", variant.directional, false);
        at.lights[2] = lightsOf("uPointLights", variant.point, false);
        at.lights[3] = lightsOf("uSpotLights", variant.spot, false);
    }
}

Program buildProgramFromBodies(const std::string& name, std::string_view vertexBody,
                               std::string_view fragmentBody) {
    auto stage = [&](GLenum kind, std::string_view body, const char* which) {
        return compileSource(kind, glslHeader() + std::string("#line 1 1\n") + std::string(body),
                             "the " + std::string(which) + " stage of program " + name + " (source 1)");
    };
    const Shader vertex = stage(GL_VERTEX_SHADER, vertexBody, "vertex");
    const Shader fragment = stage(GL_FRAGMENT_SHADER, fragmentBody, "fragment");
    Program program;
    glAttachShader(program.get(), vertex.get());
    glAttachShader(program.get(), fragment.get());
    linkOrThrow(program, name);
    glDetachShader(program.get(), vertex.get());
    glDetachShader(program.get(), fragment.get());
    return program;
}

Program buildLineProgram() {
    return buildProgramFromBodies("lines", shaderText("lines.vert.glsl"), shaderText("lines.frag.glsl"));
}

} // namespace shadelab::gl
