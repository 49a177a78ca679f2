#include "shadelab/context/headless.h"

#include "shadelab/errors.h"
#include "shadelab/gl/loader.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/gl/renderer.h"

namespace shadelab {

#if !SHADELAB_HAVE_OSMESA
std::unique_ptr<HeadlessContext> makeOsmesaContext() {
    throw RuntimeError("osmesa: this shadelab was built without OSMesa (libosmesa6-dev was not found at "
                       "configure time); use --backend egl");
}
#endif

void checkContextRequest(const ContextRequest& request) {
    if (request.backend != Backend::Osmesa) return;
    if (request.api == Api::Gles)
        throw InputError("--api gles: OSMesa offers desktop OpenGL only; use --backend egl for OpenGL ES");
    if (request.eglDevice)
        throw InputError("--egl-device: a choice of the EGL backend; leave it out with --backend osmesa");
}

std::unique_ptr<HeadlessContext> makeHeadlessContext(const ContextRequest& request) {
    checkContextRequest(request);
    if (request.backend == Backend::Egl) return makeEglContext(request.api, request.eglDevice);
    return makeOsmesaContext();
}

HeadlessRenderer::HeadlessRenderer(const ContextRequest& request)
    : context_(makeHeadlessContext(request)), renderer_(std::make_unique<gl::Renderer>()),
      rendererString_(gl::rendererString()) {}

// The renderer's GL objects must go while its context is current.
HeadlessRenderer::~HeadlessRenderer() {
    try {
        context_->makeCurrent();
        renderer_.reset();
    } catch (...) {
        (void)renderer_.release(); // the context is unusable: deleting its objects elsewhere would be worse
    }
}

void HeadlessRenderer::setSpecialization(gl::Specialization specialization) {
    renderer_->setSpecialization(specialization);
}
void HeadlessRenderer::setFlatGeometryShader(bool enabled) {
    renderer_->setFlatGeometryShader(enabled);
}
const gl::ViewFigures& HeadlessRenderer::viewFigures() const {
    return renderer_->viewFigures();
}
int HeadlessRenderer::programsBuilt() const {
    return renderer_->programsBuilt();
}

// Validated first, so a bad value is reported with its JSON path (objects[1].subdivisions, image.width)
// rather than by whichever GL step would trip over it.
Image HeadlessRenderer::render(const Scene& scene) {
    return render(scene, {});
}

Image HeadlessRenderer::render(const Scene& scene, const std::function<void(gl::Renderer&)>& over) {
    validateScene(scene);
    context_->makeCurrent();
    const gl::RenderTarget target(scene.width, scene.height, gl::ColorFormat::Rgba8,
                                  gl::depthFormatFor(scene.depth));
    target.bind();
    renderer_->render(scene, scene.width, scene.height);
    if (over) over(*renderer_);
    return target.readRgba8();
}

ImageF HeadlessRenderer::renderFloat(const Scene& scene) {
    validateScene(scene);
    context_->makeCurrent();
    const gl::RenderTarget target(scene.width, scene.height, gl::ColorFormat::Rgba32F,
                                  gl::depthFormatFor(scene.depth));
    target.bind();
    renderer_->render(scene, scene.width, scene.height);
    return target.readFloat();
}

} // namespace shadelab
