#include "shadelab/gl/render_target.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

#include <glad/gl.h>

#include "shadelab/errors.h"
#include "shadelab/gl/loader.h"

namespace shadelab::gl {
namespace {

void checkSize(int width, int height) {
    GLint maxRenderbuffer = 0;
    GLint maxViewport[2] = {0, 0};
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
    const int limit = std::min({maxRenderbuffer, maxViewport[0], maxViewport[1]});
    if (width < 1 || height < 1 || width > limit || height > limit)
        throw InputError("image size " + std::to_string(width) + "x" + std::to_string(height) +
                         ": this GL context renders at most " + std::to_string(limit) + "x" +
                         std::to_string(limit) + "; choose a smaller --size");
}

// GL rows run bottom to top; images run top to bottom. This is the one place rows are flipped.
template <typename T> void flipRows(std::vector<T>& pixels, int width, int height) {
    const std::size_t row = std::size_t(width) * 4;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(pixels.begin() + std::ptrdiff_t(y * row),
                         pixels.begin() + std::ptrdiff_t((y + 1) * row),
                         pixels.begin() + std::ptrdiff_t((height - 1 - y) * row));
}

const char* framebufferStatusName(GLenum status) {
    switch (status) {
    case GL_FRAMEBUFFER_UNDEFINED:
        return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
        return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
        return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_UNSUPPORTED:
        return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
        return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    default:
        return "an unknown framebuffer status";
    }
}

} // namespace

DepthFormat depthFormatFor(DepthMode mode) {
    return mode == DepthMode::Standard ? DepthFormat::Depth24 : DepthFormat::Depth32F;
}

RenderTarget::RenderTarget(int width, int height, ColorFormat format, DepthFormat depth) {
    fit(width, height, format, depth);
}

void RenderTarget::fit(int width, int height, ColorFormat format, DepthFormat depth) {
    if (fbo_ && width == width_ && height == height_ && format == format_ && depth == depthFormat_) return;
    *this = RenderTarget(); // the old attachments' memory first: a large window may not hold both
    checkSize(width, height);
    if (format == ColorFormat::Rgba32F && !capabilities().floatColorTargets)
        throw RuntimeError("a float (RGBA32F) render target needs EXT_color_buffer_float, which this " +
                           std::string(displayName(capabilities().api)) + " context lacks");
    Framebuffer fbo;
    Texture color;
    Renderbuffer depthBuffer{NoCreate};
    glBindTexture(GL_TEXTURE_2D, color.get());
    if (format == ColorFormat::Rgba8)
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    else
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST); // sampled texel for texel
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color.get(), 0);
    if (depth != DepthFormat::None) {
        depthBuffer = Renderbuffer();
        glBindRenderbuffer(GL_RENDERBUFFER, depthBuffer.get());
        glRenderbufferStorage(GL_RENDERBUFFER,
                              depth == DepthFormat::Depth24 ? GL_DEPTH_COMPONENT24 : GL_DEPTH_COMPONENT32F,
                              width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depthBuffer.get());
    }
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        GLint maxRenderbuffer = 0;
        GLint maxViewport[2] = {0, 0};
        glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
        glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
        const double bytesPerPixel =
            (format == ColorFormat::Rgba8 ? 4 : 16) + (depth == DepthFormat::None ? 0 : 4);
        const double megabytes = double(width) * height * bytesPerPixel / 1048576.0;
        char needed[64];
        std::snprintf(needed, sizeof needed, "%.0f MiB", megabytes);
        throw RuntimeError(
            "offscreen framebuffer " + std::to_string(width) + "x" + std::to_string(height) + " (" +
            (format == ColorFormat::Rgba8 ? "RGBA8" : "RGBA32F") +
            (depth == DepthFormat::None ? "" : " + depth") + ", about " + needed +
            ") is incomplete: " + framebufferStatusName(status) +
            "; this context allows renderbuffers up to " + std::to_string(maxRenderbuffer) +
            " and viewports up to " + std::to_string(maxViewport[0]) + "x" + std::to_string(maxViewport[1]) +
            " (an attachment that could not be allocated, e.g. under a memory limit, also shows as "
            "incomplete): try a smaller --size");
    }
    checkGlError("creating the offscreen framebuffer");
    width_ = width;
    height_ = height;
    format_ = format;
    depthFormat_ = depth;
    fbo_ = std::move(fbo);
    color_ = std::move(color);
    depth_ = std::move(depthBuffer);
}

void bindDefaultFramebuffer() {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void clearWindow(int width, int height, glm::vec3 color) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glClearColor(color.x, color.y, color.z, 1.0f);
    clearDepth(0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void RenderTarget::blitToWindow(int x, int y) const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width_, height_, x, y, x + width_, y + height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    checkGlError("copying the picture into the window");
}

void RenderTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
}

// Reads the colour attachment into `image` (rows top first) as GL `type` components.
template <typename Pixels> Pixels RenderTarget::read(unsigned type, const char* stage) const {
    Pixels image(width_, height_);
    bind();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGBA, type, image.rgba.data());
    checkGlError(stage);
    flipRows(image.rgba, width_, height_);
    return image;
}

Image RenderTarget::readRgba8() const {
    return read<Image>(GL_UNSIGNED_BYTE, "reading back the image");
}

ImageF RenderTarget::readFloat() const {
    return read<ImageF>(GL_FLOAT, "reading back the float image");
}

std::vector<float> RenderTarget::readFloatRow(int y) const {
    std::vector<float> row(std::size_t(width_) * 4);
    bind();
    glReadPixels(0, y, width_, 1, GL_RGBA, GL_FLOAT, row.data());
    return row;
}

} // namespace shadelab::gl
