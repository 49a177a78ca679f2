#include "shadelab/gl/program.h"

#include <cstdio>
#include <string>
#include <vector>

#include <glad/gl.h>

#include "gl/shader_sources.h"
#include "shadelab/errors.h"

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

std::string variantDefines(const ProgramVariant& variant) {
    std::string defines = "#define MAX_LIGHTS " + std::to_string(kMaxLights) + "\n";
    defines += "#define TOON_HIGHLIGHT " + std::to_string(kToonHighlight) + "\n";
    static constexpr const char* kShadingDefines[] = {"SHADING_FLAT", "SHADING_GOURAUD", "SHADING_PHONG",
                                                      "SHADING_TOON"};
    defines += std::string("#define ") + kShadingDefines[int(variant.shading)] + "\n";
    if (variant.lighting == LightingModel::BlinnPhong) defines += "#define LIGHTING_BLINN_PHONG\n";
    return defines;
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

Shader compileStage(GLenum stage, const char* file, const ProgramVariant& variant) {
    const std::string source = "#version 330 core\n" + variantDefines(variant) + "#line 1 " +
                               std::to_string(kLightingSourceNumber) + "\n" +
                               std::string(shaderText(kLightingFile)) + "#line 1 " +
                               std::to_string(kStageSourceNumber) + "\n" + std::string(shaderText(file));
    Shader shader(glCreateShader(stage));
    const char* text = source.c_str();
    glShaderSource(shader.get(), 1, &text, nullptr);
    glCompileShader(shader.get());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    const std::string log = infoLog(shader.get(), false);
    const std::string where = std::string(file) + " (variant " + variant.name() + "; source 1 = " +
                              kLightingFile + ", source 2 = " + file + ")";
    if (!ok) throw RuntimeError("compiling " + where + " failed:\n" + log);
    if (!log.empty()) std::fprintf(stderr, "shadelab: compile log of %s:\n%s\n", where.c_str(), log.c_str());
    return shader;
}

} // namespace

std::string ProgramVariant::name() const {
    return std::string(toString(shading)) + "/" + std::string(toString(lighting));
}

Program buildProgram(const ProgramVariant& variant) {
    const Shader vertex = compileStage(GL_VERTEX_SHADER, "surface.vert.glsl", variant);
    const Shader fragment = compileStage(GL_FRAGMENT_SHADER, "surface.frag.glsl", variant);
    Program program(glCreateProgram());
    glAttachShader(program.get(), vertex.get());
    glAttachShader(program.get(), fragment.get());
    glLinkProgram(program.get());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (!ok) throw RuntimeError("linking program " + variant.name() + " failed:\n" + infoLog(program.get(), true));
    glDetachShader(program.get(), vertex.get());
    glDetachShader(program.get(), fragment.get());
    return program;
}

} // namespace shadelab::gl
