// Headless rendering: a context, the shared renderer and an offscreen target, returning pixels.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "shadelab/context/context.h"
#include "shadelab/image/image.h"
#include "shadelab/scene/scene.h"

namespace shadelab {
namespace gl {
class Renderer;
struct ViewFigures;
enum class Specialization;
} // namespace gl

class HeadlessRenderer {
public:
    explicit HeadlessRenderer(const ContextRequest& request);
    explicit HeadlessRenderer(Backend backend)
        : HeadlessRenderer(ContextRequest{backend, Api::Gl, std::nullopt}) {}
    ~HeadlessRenderer();
    HeadlessRenderer(const HeadlessRenderer&) = delete;
    HeadlessRenderer& operator=(const HeadlessRenderer&) = delete;

    Image render(const Scene& scene); // scene.width × scene.height, rows top first
    // The scene, then `over` drawing on it through the same renderer and target (slides' lesson band).
    Image render(const Scene& scene, const std::function<void(gl::Renderer&)>& over);
    ImageF renderFloat(const Scene& scene); // through an RGBA32F target: NaN and Inf stay visible
    Backend backend() const { return context_->backend(); }
    Api api() const { return context_->api(); }
    // "EGL device 0 (software rasterizer)", "EGL surfaceless platform", "OSMesa".
    std::string origin() const { return context_->origin(); }
    // How far programs are specialized (default: to each object's values); see gl/program.h.
    void setSpecialization(gl::Specialization specialization);
    // Flat shading through shared vertices and a geometry shader (see gl/renderer.h).
    void setFlatGeometryShader(bool enabled);
    int programsBuilt() const;
    // What the last render's view measured (gl/view_figures.h): the error view's figures, the profile's rows.
    const gl::ViewFigures& viewFigures() const;
    const std::string& rendererString() const { return rendererString_; }

private:
    std::unique_ptr<HeadlessContext> context_;
    std::unique_ptr<gl::Renderer> renderer_;
    std::string rendererString_;
};

} // namespace shadelab
