// EGL with no display and no window system: first an EGL device (EGL_EXT_platform_device: a GPU on a
// headless server, or Mesa's software device), then Mesa's surfaceless platform. Plain
// eglGetDisplay(EGL_DEFAULT_DISPLAY) fails without an X display, so the platform is asked for explicitly.
// The context is desktop OpenGL 3.3 core or OpenGL ES 3.0 (DESIGN §7).
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include "shadelab/context/context.h"
#include "shadelab/errors.h"
#include "shadelab/gl/loader.h"
#include "shadelab/io/text.h"

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

EGLenum eglApi(Api api) {
    return api == Api::Gles ? EGL_OPENGL_ES_API : EGL_OPENGL_API;
}

// What one attempt to open a display and make a context on it gives: the objects, or why not.
struct Attempt {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    std::string failure;
};

// eglChooseConfig defaults EGL_SURFACE_TYPE to EGL_WINDOW_BIT, which a display with no window system never
// has; shadelab draws into its own framebuffer objects, so any surface type will do.
Attempt createContext(EGLDisplay display, Api api) {
    Attempt a;
    a.display = display;
    auto failed = [&](const std::string& step) {
        a.failure = step + " failed (" + eglErrorName(eglGetError()) + ")";
        return a;
    };
    if (display == EGL_NO_DISPLAY) return failed("eglGetPlatformDisplayEXT");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) return failed("eglInitialize");
    const bool gles = api == Api::Gles;
    if (!eglBindAPI(eglApi(api)))
        return failed(gles ? "eglBindAPI(EGL_OPENGL_ES_API)" : "eglBindAPI(EGL_OPENGL_API)");
    const EGLint renderable = gles ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT;
    EGLConfig config = nullptr;
    EGLint configs = 0;
    for (EGLint surfaceType : {EGLint(EGL_PBUFFER_BIT), EGLint(0)}) {
        const EGLint configAttributes[] = {EGL_SURFACE_TYPE, surfaceType, EGL_RENDERABLE_TYPE, renderable,
                                           EGL_NONE};
        if (eglChooseConfig(display, configAttributes, &config, 1, &configs) && configs > 0) break;
    }
    if (configs < 1)
        return failed(gles ? "eglChooseConfig (an OpenGL ES 3 config)"
                           : "eglChooseConfig (an OpenGL config)");
    const EGLint glAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                   3,
                                   EGL_CONTEXT_MINOR_VERSION,
                                   3,
                                   EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                   EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                   EGL_NONE};
    const EGLint glesAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    a.context = eglCreateContext(display, config, EGL_NO_CONTEXT, gles ? glesAttributes : glAttributes);
    if (a.context == EGL_NO_CONTEXT)
        return failed(gles ? "eglCreateContext (OpenGL ES 3.0)" : "eglCreateContext (OpenGL 3.3 core)");
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, a.context)) {
        failed("eglMakeCurrent (surfaceless)");
        eglDestroyContext(display, a.context);
        a.context = EGL_NO_CONTEXT;
    }
    return a;
}

struct Devices {
    bool supported = false; // EGL_EXT_platform_device and a way to enumerate
    std::vector<EGLDeviceEXT> list;
};

Devices queryDevices() {
    Devices d;
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(client, "EGL_EXT_platform_device")) return d;
    auto query = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    EGLint count = 0;
    if (!query || !query(0, nullptr, &count) || count <= 0) {
        d.supported = query != nullptr;
        return d;
    }
    d.supported = true;
    d.list.resize(std::size_t(count));
    if (!query(count, d.list.data(), &count)) count = 0;
    d.list.resize(std::size_t(count));
    return d;
}

// "software (EGL_MESA_device_software)", "/dev/dri/renderD128", or what the device says of itself.
std::string deviceKind(EGLDeviceEXT device) {
    auto queryString =
        reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
    if (!queryString) return "device";
    const char* extensions = queryString(device, EGL_EXTENSIONS);
    if (hasExtension(extensions, "EGL_MESA_device_software")) return "software rasterizer";
    if (hasExtension(extensions, "EGL_EXT_device_drm_render_node"))
        if (const char* node = queryString(device, EGL_DRM_RENDER_NODE_FILE_EXT)) return printable(node);
    if (hasExtension(extensions, "EGL_EXT_device_drm"))
        if (const char* file = queryString(device, EGL_DRM_DEVICE_FILE_EXT)) return printable(file);
    return "device";
}

// "EGL device 1 (/dev/dri/renderD128)": how messages and --verbose name a device.
std::string deviceName(std::size_t index, EGLDeviceEXT device) {
    return "EGL device " + std::to_string(index) + " (" + deviceKind(device) + ")";
}

PFNEGLGETPLATFORMDISPLAYEXTPROC platformDisplayFunction() {
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) fail("eglGetProcAddress(eglGetPlatformDisplayEXT)");
    return getPlatformDisplay;
}

Attempt onDevice(EGLDeviceEXT device, Api api) {
    return createContext(platformDisplayFunction()(EGL_PLATFORM_DEVICE_EXT, device, nullptr), api);
}

class EglContext final : public HeadlessContext {
public:
    EglContext(Api api, std::optional<int> device) : api_(api) {
        const Attempt made = open(device);
        display_ = made.display;
        context_ = made.context;
        try {
            makeCurrent();
        } catch (...) {
            release(); // the destructor does not run for a throwing constructor
            throw;
        }
    }

    // No surface: we draw into our own framebuffer objects only. The bound API decides which context
    // eglMakeCurrent replaces, so it is bound first (a process may hold a GL and a GLES context).
    void makeCurrent() override {
        eglBindAPI(eglApi(api_));
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) fail("eglMakeCurrent");
        gl::loadGl(eglGetProcAddress, "egl", api_);
    }

    ~EglContext() override { release(); }

    Backend backend() const override { return Backend::Egl; }
    Api api() const override { return api_; }
    std::string origin() const override { return origin_; }

private:
    // The requested device, or each device in turn and then the surfaceless platform.
    Attempt open(std::optional<int> device) {
        const Devices devices = queryDevices();
        if (device) {
            if (!devices.supported)
                throw RuntimeError("egl: --egl-device " + std::to_string(*device) +
                                   ": this EGL library lacks EGL_EXT_platform_device; leave --egl-device out "
                                   "to use the surfaceless platform");
            if (*device < 0 || std::size_t(*device) >= devices.list.size())
                throw InputError(
                    "--egl-device " + std::to_string(*device) + ": this machine has " +
                    std::to_string(devices.list.size()) + " EGL device(s)" +
                    (devices.list.empty() ? "" : " (0.." + std::to_string(devices.list.size() - 1) + ")") +
                    "; see --egl-device list");
            const EGLDeviceEXT chosen = devices.list[std::size_t(*device)];
            Attempt a = onDevice(chosen, api_);
            origin_ = deviceName(std::size_t(*device), chosen);
            if (a.context == EGL_NO_CONTEXT)
                throw RuntimeError("egl: " + origin_ + ": " + a.failure + ". " + environmentHint());
            return a;
        }
        std::string deviceFailures; // said only if the surfaceless platform fails too
        for (std::size_t i = 0; i < devices.list.size(); ++i) {
            const std::string name = deviceName(i, devices.list[i]);
            Attempt a = onDevice(devices.list[i], api_);
            if (a.context != EGL_NO_CONTEXT) {
                origin_ = name;
                return a;
            }
            deviceFailures += name + ": " + a.failure + "; ";
        }
        const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        if (!hasExtension(client, "EGL_MESA_platform_surfaceless"))
            throw RuntimeError("egl: no EGL device gives a context and the EGL library lacks "
                               "EGL_MESA_platform_surfaceless (Mesa's headless platform); install Mesa's EGL "
                               "(libegl-mesa0) or use --backend osmesa");
        Attempt a = createContext(
            platformDisplayFunction()(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), api_);
        if (a.context == EGL_NO_CONTEXT)
            throw RuntimeError("egl: " + deviceFailures + "surfaceless platform: " + a.failure + ". " +
                               environmentHint());
        origin_ = "EGL surfaceless platform";
        return a;
    }

    void release() {
        eglBindAPI(eglApi(api_));
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        // No eglTerminate: the display is one per process and is reused by the next context; Mesa's EGL
        // teardown leaks and crashes in some versions, and process exit releases it anyway.
    }

    Api api_;
    std::string origin_;
    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

} // namespace

std::unique_ptr<HeadlessContext> makeEglContext(Api api, std::optional<int> device) {
    return std::make_unique<EglContext>(api, device);
}

std::vector<std::string> describeEglDevices(Api api) {
    const Devices devices = queryDevices();
    if (!devices.supported) return {"(this EGL library lacks EGL_EXT_platform_device: no devices to list)"};
    std::vector<std::string> lines;
    for (std::size_t i = 0; i < devices.list.size(); ++i) {
        std::string line = std::to_string(i) + ": " + deviceKind(devices.list[i]) + ": ";
        try {
            const EglContext context(api, int(i));
            line += gl::rendererString();
        } catch (const std::exception& e) {
            line += std::string("no ") + std::string(displayName(api)) + " context: " + e.what();
        }
        lines.push_back(line);
    }
    if (lines.empty()) lines.push_back("(no EGL devices)");
    return lines;
}

} // namespace shadelab
