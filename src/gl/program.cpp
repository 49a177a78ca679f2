#include "shadelab/gl/program.h"

#include <algorithm>
#include <cstdio>
#include <string>
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

void linkOrThrow(const Program& program, const std::string& name) {
    glLinkProgram(program.get());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (!ok) throw RuntimeError("linking program " + name + " failed:\n" + infoLog(program.get(), true));
}

} // namespace

Program buildProgram(const ProgramVariant& variant) {
    if (variant.flatGeometryShader && !capabilities().geometryShaders)
        throw RuntimeError("flat shading through a geometry shader (program " + variant.name() +
                           ") needs desktop OpenGL: " + std::string(displayName(capabilities().api)) +
                           " has no geometry stage; use the default flat layout");
    const bool exact = variant.shading == ShadingMode::Exact;
    const char* vertexFile = variant.exactPatches ? "exact_patch.vert.glsl"
                             : exact              ? "exact.vert.glsl"
                                                  : "surface.vert.glsl";
    const char* fragmentFile = variant.exactPatches ? "exact_patch.frag.glsl"
                               : exact              ? "exact.frag.glsl"
                                                    : "surface.frag.glsl";
    const Shader vertex = compileStage(GL_VERTEX_SHADER, vertexFile, variant);
    const Shader fragment = compileStage(GL_FRAGMENT_SHADER, fragmentFile, variant);
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
    if (variant.exactPatches) {
        // GLSL 3.30 and ES 3.00 have no layout(binding): the block's binding point is set here.
        const GLuint block = glGetUniformBlockIndex(program.get(), "TeapotPatches");
        if (block == GL_INVALID_INDEX)
            throw RuntimeError("program " + variant.name() + " has no uniform block TeapotPatches");
        glUniformBlockBinding(program.get(), block, kTeapotPatchesBinding);
    }
    return program;
}

SurfaceProgram::SurfaceProgram(Program linked, const ProgramVariant& variant) : program(std::move(linked)) {
    const GLuint id = program.get();
    auto find = [id](const std::string& name) { return glGetUniformLocation(id, name.c_str()); };
    // Every variant uses its transform into clip space: a mesh's uClipFromObject, exact shading's uNdcRect.
    const bool exact = variant.shading == ShadingMode::Exact && !variant.exactPatches;
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
