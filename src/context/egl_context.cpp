// EGL on Mesa's surfaceless platform: a GL context with no display and no window system. Plain
// eglGetDisplay(EGL_DEFAULT_DISPLAY) fails without an X display, so the platform is asked for explicitly.
#include <cstdlib>
#include <cstring>
#include <string>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "shadelab/context.h"
#include "shadelab/errors.h"
#include "shadelab/gl/loader.h"
#include "shadelab/text.h"

namespace shadelab {
namespace {

const char* eglErrorName(EGLint error) {
    switch (error) {
    case EGL_SUCCESS:
        return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
        return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
        return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
        return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
        return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
        return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
        return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
        return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
        return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
        return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
        return "EGL_BAD_SURFACE";
    default:
        return "unknown EGL error";
    }
}

// Environment variables that steer Mesa or glvnd: when one is set, it is the likelier cause of a failure
// than a broken install, so the message names it.
std::string environmentHint() {
    static constexpr const char* kVariables[] = {"GALLIUM_DRIVER",
                                                 "MESA_GL_VERSION_OVERRIDE",
                                                 "MESA_GLSL_VERSION_OVERRIDE",
                                                 "MESA_LOADER_DRIVER_OVERRIDE",
                                                 "LIBGL_ALWAYS_SOFTWARE",
                                                 "EGL_PLATFORM",
                                                 "__EGL_VENDOR_LIBRARY_FILENAMES",
                                                 "__EGL_VENDOR_LIBRARY_DIRS",
                                                 "LIBGL_DRIVERS_PATH"};
    std::string set;
    for (const char* name : kVariables)
        if (const char* value = std::getenv(name); value && *value)
            set += (set.empty() ? "" : ", ") + std::string(name) + "=" + printable(value);
    std::string install = "Is Mesa's EGL installed (libegl1, libgl1-mesa-dri)?";
    if (set.empty()) return install;
    return "The environment sets " + set +
           ", which Mesa reads: unset it (or give a value this Mesa supports) and try again. Otherwise: " +
           install;
}

[[noreturn]] void fail(const std::string& step) {
    throw RuntimeError("egl: " + step + " failed (" + eglErrorName(eglGetError()) + "). " +
                       environmentHint());
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const std::size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + n, name))
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

class EglContext final : public HeadlessContext {
public:
    EglContext() {
        const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
            throw RuntimeError("egl: the EGL library lacks EGL_MESA_platform_surfaceless (Mesa's headless "
                               "platform); install Mesa's EGL (libegl-mesa0) or use --backend osmesa");
        auto getPlatformDisplay =
            reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!getPlatformDisplay) fail("eglGetProcAddress(eglGetPlatformDisplayEXT)");
        display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display_ == EGL_NO_DISPLAY) fail("eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)");
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display_, &major, &minor)) fail("eglInitialize");
        if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API)");

        // eglChooseConfig defaults EGL_SURFACE_TYPE to EGL_WINDOW_BIT, which a surfaceless display never has.
        const EGLint configAttributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                           EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint configs = 0;
        if (!eglChooseConfig(display_, configAttributes, &config, 1, &configs) || configs < 1)
            fail("eglChooseConfig (an OpenGL-renderable config)");
        const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                            3,
                                            EGL_CONTEXT_MINOR_VERSION,
                                            3,
                                            EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                            EGL_NONE};
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, contextAttributes);
        if (context_ == EGL_NO_CONTEXT) fail("eglCreateContext (OpenGL 3.3 core)");
        try {
            makeCurrent();
        } catch (...) {
            release(); // the destructor does not run for a throwing constructor
            throw;
        }
    }

    // Surfaceless: we draw into our own framebuffer object only.
    void makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) fail("eglMakeCurrent");
        gl::loadGl(eglGetProcAddress, "egl");
    }

    ~EglContext() override { release(); }

private:
    void release() {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        // No eglTerminate: the display is one per process and is reused by the next context; Mesa's EGL
        // teardown leaks and crashes in some versions, and process exit releases it anyway.
    }

public:
    Backend backend() const override { return Backend::Egl; }

private:
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

} // namespace

std::unique_ptr<HeadlessContext> makeEglContext() {
    return std::make_unique<EglContext>();
}

} // namespace shadelab
