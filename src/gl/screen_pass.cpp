#include "shadelab/gl/screen_pass.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include <glad/gl.h>

#include "gl/shader_sources.h"
#include "shadelab/errors.h"
#include "shadelab/gl/program.h"

namespace shadelab::gl {
namespace {

std::string_view shaderSource(const char* name) {
    const auto text = embeddedShader(name);
    if (!text) throw RuntimeError(std::string("shader ") + name + " is not embedded in the binary");
    return *text;
}

} // namespace

ScreenPass::ScreenPass(const char* fragment)
    : program(buildProgramFromBodies(fragment, shaderSource("quad.vert.glsl"), shaderSource(fragment))),
      ndcRect(location("uNdcRect")) {
    if (ndcRect < 0) throw RuntimeError(std::string("program ") + fragment + " has no uniform uNdcRect");
}

int ScreenPass::location(const char* name) const {
    return glGetUniformLocation(program.get(), name);
}

void ScreenPass::setSampler(const char* name, int unit) const {
    GLint current = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    glUseProgram(program.get());
    glUniform1i(location(name), unit);
    glUseProgram(GLuint(current));
}

void ScreenPass::draw(double x0, double y0, double x1, double y1, int viewportWidth,
                      int viewportHeight) const {
    glUniform4f(ndcRect, float(2 * x0 / viewportWidth - 1), float(2 * y0 / viewportHeight - 1),
                float(2 * x1 / viewportWidth - 1), float(2 * y1 / viewportHeight - 1));
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

void bindTexture(int unit, const Texture& texture) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, texture.get());
}

void Sprite::set(const Image& image) {
    width_ = std::max(image.width, 0);
    height_ = std::max(image.height, 0);
    if (width_ == 0 || height_ == 0) return;
    if (!texture_) texture_ = Texture();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_.get());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 image.rgba.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

ImagePass::ImagePass() = default;

void ImagePass::draw(const Sprite& sprite, int left, int top, int viewportX, int viewportWidth,
                     int viewportHeight) const {
    if (sprite.width() <= 0 || sprite.height() <= 0) return;
    bindTexture(0, sprite.texture());
    glUseProgram(sprite_.program.get());
    glBindVertexArray(empty_.get());
    const int bottom = viewportHeight - top - sprite.height();
    glUniform2f(sprite_.origin, float(viewportX + left), float(bottom));
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    sprite_.draw(left, bottom, left + sprite.width(), bottom + sprite.height(), viewportWidth,
                 viewportHeight);
    glDisable(GL_BLEND);
}

} // namespace shadelab::gl
