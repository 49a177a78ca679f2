#include "shadelab/gl/loader.h"

#include <glad/gl.h>

#include "shadelab/errors.h"
#include "shadelab/gl/handles.h"

namespace shadelab::gl {

void loadGl(ProcAddressFn getProcAddress, const char* backend) {
    // Entry points from one getProcAddress serve every context of that kind; reload only on a change.
    static ProcAddressFn loadedFrom = nullptr;
    if (getProcAddress == loadedFrom) return;
    loadedFrom = nullptr;
    const int version = gladLoadGL(getProcAddress);
    if (version == 0)
        throw RuntimeError(std::string(backend) + ": loading OpenGL entry points failed (glad)");
    const int major = GLAD_VERSION_MAJOR(version), minor = GLAD_VERSION_MINOR(version);
    if (major < 3 || (major == 3 && minor < 3))
        throw RuntimeError(std::string(backend) + ": the context offers OpenGL " + std::to_string(major) +
                           "." + std::to_string(minor) + "; shadelab needs 3.3 core");
    loadedFrom = getProcAddress;
}

std::string rendererString() {
    auto text = [](GLenum name) {
        const auto* s = reinterpret_cast<const char*>(glGetString(name));
        return std::string(s ? s : "?");
    };
    return text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
}

void checkGlError(const char* stage) {
    const GLenum error = glGetError();
    if (error == GL_NO_ERROR) return;
    while (glGetError() != GL_NO_ERROR) {
    }
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", error);
    const char* name = error == GL_OUT_OF_MEMORY       ? " (GL_OUT_OF_MEMORY: the driver could not allocate "
                                                         "the buffers; free memory, raise the limit (ulimit "
                                                         "-v), or use a smaller --size or --subdivisions)"
                       : error == GL_INVALID_ENUM      ? " (GL_INVALID_ENUM)"
                       : error == GL_INVALID_VALUE     ? " (GL_INVALID_VALUE)"
                       : error == GL_INVALID_OPERATION ? " (GL_INVALID_OPERATION)"
                       : error == GL_INVALID_FRAMEBUFFER_OPERATION ? " (GL_INVALID_FRAMEBUFFER_OPERATION)"
                                                                   : "";
    throw RuntimeError(std::string("GL error ") + code + " in " + stage + name);
}

void finish() {
    glFinish();
}

bool enableDebugOutput(std::function<void(const std::string&)>* sink) {
    if (!GLAD_GL_KHR_debug && !GLAD_GL_VERSION_4_3) return false;
    GLint flags = 0;
    glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
    if (!(flags & GL_CONTEXT_FLAG_DEBUG_BIT)) return false;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS); // messages arrive inside the offending call
    glDebugMessageCallback(
        [](GLenum, GLenum, GLuint, GLenum, GLsizei length, const GLchar* message, const void* user) {
            (*static_cast<std::function<void(const std::string&)>*>(const_cast<void*>(user)))(
                std::string(message, std::size_t(length)));
        },
        sink);
    return true;
}

void deleteBuffer(Id id) {
    glDeleteBuffers(1, &id);
}
void deleteVertexArray(Id id) {
    glDeleteVertexArrays(1, &id);
}
void deleteShader(Id id) {
    glDeleteShader(id);
}
void deleteProgram(Id id) {
    glDeleteProgram(id);
}
void deleteFramebuffer(Id id) {
    glDeleteFramebuffers(1, &id);
}
void deleteRenderbuffer(Id id) {
    glDeleteRenderbuffers(1, &id);
}

} // namespace shadelab::gl
