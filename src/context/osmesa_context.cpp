// OSMesa: Mesa's off-screen software context, the second headless backend. GL/osmesa.h pulls in GL/gl.h,
// which cannot share a translation unit with glad's gl.h, hence this file of its own.
#include <cstdlib>
#include <cstring>
#include <string>

#include <GL/osmesa.h>

#include "shadelab/context/context.h"
#include "shadelab/errors.h"
#include "shadelab/gl/loader.h"

namespace shadelab {
namespace {

class OsmesaContext final : public HeadlessContext {
public:
    OsmesaContext() {
        // Mesa 22.3's OSMesa crashes inside OSMesaCreateContextAttribs for any gallium driver it lacks
        // (measured: zink, swr, d3d12, virpipe, a typo); say so instead.
        if (const char* driver = std::getenv("GALLIUM_DRIVER");
            driver && *driver && std::strcmp(driver, "llvmpipe") != 0 && std::strcmp(driver, "softpipe") != 0)
            throw RuntimeError(
                std::string("osmesa: GALLIUM_DRIVER=") + driver +
                " is not a driver OSMesa has (llvmpipe, softpipe); unset it or use --backend egl");
        // No depth bits: shadelab draws into its own framebuffer object with its own depth buffer.
        const int attributes[] = {OSMESA_FORMAT,
                                  OSMESA_RGBA,
                                  OSMESA_DEPTH_BITS,
                                  0,
                                  OSMESA_PROFILE,
                                  OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION,
                                  3,
                                  OSMESA_CONTEXT_MINOR_VERSION,
                                  3,
                                  0};
        context_ = OSMesaCreateContextAttribs(attributes, nullptr);
        if (!context_) throw RuntimeError("osmesa: OSMesaCreateContextAttribs (OpenGL 3.3 core) failed");
        try {
            makeCurrent();
        } catch (...) {
            OSMesaDestroyContext(context_); // the destructor does not run for a throwing constructor
            throw;
        }
    }

    // OSMesa needs a colour buffer to make a context current; 1×1 is enough since nothing draws to it.
    void makeCurrent() override {
        if (!OSMesaMakeCurrent(context_, buffer_, GL_UNSIGNED_BYTE, 1, 1))
            throw RuntimeError("osmesa: OSMesaMakeCurrent failed");
        gl::loadGl(OSMesaGetProcAddress, "osmesa");
    }

    ~OsmesaContext() override { OSMesaDestroyContext(context_); }

    Backend backend() const override { return Backend::Osmesa; }
    std::string origin() const override { return "OSMesa"; }

private:
    OSMesaContext context_ = nullptr;
    unsigned char buffer_[4] = {};
};

} // namespace

std::unique_ptr<HeadlessContext> makeOsmesaContext() {
    return std::make_unique<OsmesaContext>();
}

} // namespace shadelab
