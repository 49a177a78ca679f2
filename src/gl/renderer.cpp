// The front (gl/renderer.h): the scene draw for a plain scene, the views for the rest, each given the
// front's settings as the draw's options; and the images drawn over a picture.
#include "shadelab/gl/renderer.h"

#include <glad/gl.h>

#include "shadelab/gl/loader.h"

#include "gl/scene_draw.h"
#include "gl/views.h"

namespace shadelab::gl {

Renderer::Renderer() : sceneDraw_(std::make_unique<SceneDraw>()) {}

Renderer::~Renderer() = default;

void Renderer::render(const Scene& scene, int width, int height, int x) {
    DrawOptions options;
    options.specialization = specialization_;
    options.flatGeometryShader = flatGeometryShader_;
    const Viewport viewport{x, width, height};
    if (scene.view.kind == ViewKind::Scene) {
        sceneDraw_->draw(scene, viewport, options);
        return;
    }
    if (!views_) views_ = std::make_unique<Views>(*sceneDraw_);
    views_->draw(scene, viewport, options);
}

const ViewFigures& Renderer::viewFigures() const {
    static const ViewFigures kNone;
    return views_ ? views_->figures() : kNone;
}

int Renderer::programsBuilt() const {
    return sceneDraw_->programsBuilt();
}

void Renderer::drawLinesOver(const Scene& scene, std::span<const LineVertex> linesView, int width, int height,
                             int x) {
    sceneDraw_->drawLinesOver(scene, linesView, {x, width, height});
}

void Renderer::drawWorld(const Scene& scene, std::span<const LineVertex> linesWorld,
                         std::span<const LineVertex> trianglesWorld, float faceAlpha, int width, int height,
                         int x) {
    sceneDraw_->drawWorld(scene, linesWorld, trianglesWorld, faceAlpha, {x, width, height});
}

void Renderer::drawImageOver(const Image& image, int left, int top, int width, int height, int x) {
    imageOver_.set(image);
    drawSpriteOver(imageOver_, left, top, width, height, x);
}

void Renderer::drawSpriteOver(const Sprite& sprite, int left, int top, int width, int height, int x) {
    if (width <= 0 || height <= 0 || sprite.width() <= 0 || sprite.height() <= 0) return;
    if (!imagePass_) imagePass_ = std::make_unique<ImagePass>();
    glViewport(x, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    imagePass_->draw(sprite, left, top, x, width, height);
    glBindVertexArray(0);
    glUseProgram(0);
    glEnable(GL_DEPTH_TEST);
    checkGlError("drawing an image over the scene");
}

} // namespace shadelab::gl
