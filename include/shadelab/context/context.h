// Headless GL contexts: EGL (primary: a device, e.g. a GPU on a server with no display or Mesa's software
// device, else Mesa's surfaceless platform) and OSMesa (second, optional at configure time, desktop OpenGL
// only). Window and headless differ only in the context and the render target.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shadelab/gl/api.h"

namespace shadelab {

enum class Backend { Egl, Osmesa };
inline constexpr std::array kBackends = {Backend::Egl, Backend::Osmesa}; // --backend's (vocabulary.h)
std::string_view toString(Backend backend);                              // "egl" | "osmesa"
std::optional<Backend> parseBackend(std::string_view text);

// What to make: the backend, the API and, for EGL, the device (EGL_EXT_platform_device).
struct ContextRequest {
    Backend backend = Backend::Egl;
    Api api = Api::Gl;
    // EGL only: the index into --egl-device list; none: the first device that gives a context, then the
    // surfaceless platform.
    std::optional<int> eglDevice;
};

// A current OpenGL 3.3+ core or OpenGL ES 3.0+ context with the loader fed by the backend's
// getProcAddress. Destroying it releases the context.
class HeadlessContext {
public:
    virtual ~HeadlessContext() = default;
    virtual Backend backend() const = 0;
    virtual Api api() const { return Api::Gl; }
    // Where the context comes from, e.g. "EGL device 0 (software)" or "EGL surfaceless platform".
    virtual std::string origin() const = 0;
    // Makes this context current on the calling thread and the loader's entry points its own (two
    // contexts may live in one process: EGL and OSMesa resolve entry points differently).
    virtual void makeCurrent() = 0;
};

// Each throws RuntimeError naming the step that failed (with the EGL error, or the OSMesa call); an
// --egl-device index this machine does not have is an InputError.
std::unique_ptr<HeadlessContext> makeEglContext(Api api = Api::Gl, std::optional<int> device = std::nullopt);
std::unique_ptr<HeadlessContext> makeOsmesaContext();
// InputError for a request no backend can meet: OpenGL ES or an EGL device asked of OSMesa.
void checkContextRequest(const ContextRequest& request);
// Throws RuntimeError for a backend not compiled in, naming the ones that are, and InputError as
// checkContextRequest.
std::unique_ptr<HeadlessContext> makeHeadlessContext(const ContextRequest& request);

// One line per EGL device (EGL_EXT_device_enumeration): its index, what it is (DRM device file or
// software), and the renderer a context of `api` on it reports, or why none could be made.
std::vector<std::string> describeEglDevices(Api api);

} // namespace shadelab
