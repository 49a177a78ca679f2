// Headless GL contexts: EGL on Mesa's surfaceless platform (primary) and OSMesa (second, optional at
// configure time). Window and headless differ only in the context and the render target.
#pragma once

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace shadelab {

enum class Backend { Egl, Osmesa };
std::string_view toString(Backend backend); // "egl" | "osmesa"
std::optional<Backend> parseBackend(std::string_view text);
// Backends compiled into this binary, primary first.
std::vector<Backend> availableBackends();

// A current GL 3.3+ core context with the loader fed by the backend's getProcAddress. Destroying it
// releases the context.
class HeadlessContext {
public:
    virtual ~HeadlessContext() = default;
    virtual Backend backend() const = 0;
    // Makes this context current on the calling thread and the loader's entry points its own (two
    // contexts may live in one process: EGL and OSMesa resolve entry points differently).
    virtual void makeCurrent() = 0;
};

// Each throws RuntimeError naming the step that failed (with the EGL error, or the OSMesa call).
std::unique_ptr<HeadlessContext> makeEglContext();
std::unique_ptr<HeadlessContext> makeOsmesaContext();
// Throws RuntimeError for a backend not compiled in, naming the ones that are.
std::unique_ptr<HeadlessContext> makeHeadlessContext(Backend backend);

} // namespace shadelab
