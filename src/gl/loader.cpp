#include "shadelab/gl/loader.h"

#include <glad/gl.h>

#include "shadelab/errors.h"
#include "shadelab/gl/handles.h"

namespace shadelab::gl {
namespace {

Capabilities loadedCapabilities;

// glad's flags for one API are left as they were by a load of the other (the merged loader shares them),
// so they are read here, right after the load, and only those of the API just loaded.
Capabilities capabilitiesOfLoaded(Api api) {
    Capabilities c;
    c.api = api;
    if (api == Api::Gl) {
        c.clipControl = GLAD_GL_VERSION_4_5;
        c.debugOutput = GLAD_GL_KHR_debug || GLAD_GL_VERSION_4_3;
        return c;
    }
    // An extension counts only with its entry point: a browser may list EXT_clip_control that the
    // Emscripten runtime cannot hand out (emscripten 3.1.6 resolves no glClipControlEXT).
    c.clipControl = GLAD_GL_EXT_clip_control && glClipControlEXT != nullptr;
    c.floatColorTargets = GLAD_GL_EXT_color_buffer_float;
    c.geometryShaders = false;
    c.sampleCounts = false;
    c.debugOutput = GLAD_GL_KHR_debug && glDebugMessageCallbackKHR != nullptr;
    return c;
}

} // namespace

void loadGl(ProcAddressFn getProcAddress, const char* backend, Api api) {
    // Entry points from one getProcAddress serve every context of that kind and API; reload on a change.
    static ProcAddressFn loadedFrom = nullptr;
    static Api loadedApi = Api::Gl;
    if (getProcAddress == loadedFrom && api == loadedApi) return;
    loadedFrom = nullptr;
    const int version = api == Api::Gl ? gladLoadGL(getProcAddress) : gladLoadGLES2(getProcAddress);
    if (version == 0)
        throw RuntimeError(std::string(backend) + ": loading " + std::string(displayName(api)) +
                           " entry points failed (glad)");
    const int major = GLAD_VERSION_MAJOR(version), minor = GLAD_VERSION_MINOR(version);
    const int neededMajor = 3, neededMinor = api == Api::Gl ? 3 : 0;
    if (major < neededMajor || (major == neededMajor && minor < neededMinor))
        throw RuntimeError(std::string(backend) + ": the context offers " +
                           (api == Api::Gl ? "OpenGL " : "OpenGL ES ") + std::to_string(major) + "." +
                           std::to_string(minor) + "; shadelab needs " + std::string(displayName(api)));
    loadedCapabilities = capabilitiesOfLoaded(api);
    loadedFrom = getProcAddress;
    loadedApi = api;
}

const Capabilities& capabilities() {
    return loadedCapabilities;
}

const char* glslHeader() {
    // highp everywhere: the lighting is checked against a double-precision reference, and mediump (as
    // little as 10 bits of mantissa) would show as banding in the specular highlight.
    return loadedCapabilities.api == Api::Gl
               ? "#version 330 core\n"
               : "#version 300 es\nprecision highp float;\nprecision highp int;\n";
}

void setClipDepthZeroToOne(bool zeroToOne, std::string_view depthMode) {
    const Capabilities& c = loadedCapabilities;
    if (!c.clipControl) {
        if (zeroToOne)
            throw RuntimeError("depth " + std::string(depthMode) +
                               ": needs glClipControl (OpenGL 4.5) or GL_EXT_clip_control (OpenGL ES), "
                               "which this " +
                               std::string(displayName(c.api)) + " context lacks; use depth standard");
        return; // the default range is the standard one
    }
    const GLenum depth = zeroToOne ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE;
    if (c.api == Api::Gl)
        glClipControl(GL_LOWER_LEFT, depth);
    else
        glClipControlEXT(GL_LOWER_LEFT_EXT, depth);
}

void clearDepth(float depth) {
    if (loadedCapabilities.api == Api::Gl)
        glClearDepth(depth);
    else
        glClearDepthf(depth);
}

std::string rendererString() {
    auto text = [](GLenum name) {
        const auto* s = reinterpret_cast<const char*>(glGetString(name));
        return std::string(s ? s : "?");
    };
    const std::string version = text(GL_VERSION); // an ES context says "OpenGL ES 3.2 Mesa …" itself
    return text(GL_RENDERER) + (version.starts_with("OpenGL ES") ? ", " : ", OpenGL ") + version;
}

void checkGlError(const char* stage) {
    const GLenum error = glGetError();
    if (error == GL_NO_ERROR) return;
    discardErrors();
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

void discardErrors() {
    while (glGetError() != GL_NO_ERROR) {
    }
}

void finish() {
    glFinish();
}

bool enableDebugOutput(std::function<void(const std::string&)>* sink) {
    const Capabilities& c = loadedCapabilities;
    if (!c.debugOutput) return false;
    const GLDEBUGPROC callback = [](GLenum, GLenum, GLuint, GLenum, GLsizei length, const GLchar* message,
                                    const void* user) {
        (*static_cast<std::function<void(const std::string&)>*>(const_cast<void*>(user)))(
            std::string(message, std::size_t(length)));
    };
    if (c.api == Api::Gles) { // KHR_debug on ES: the entry points carry the KHR suffix
        glEnable(GL_DEBUG_OUTPUT_KHR);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR);
        glDebugMessageCallbackKHR(callback, sink);
        return true;
    }
    GLint flags = 0;
    glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
    if (!(flags & GL_CONTEXT_FLAG_DEBUG_BIT)) return false;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS); // messages arrive inside the offending call
    glDebugMessageCallback(callback, sink);
    return true;
}

} // namespace shadelab::gl
