// An offscreen framebuffer the program owns: a colour renderbuffer (RGBA8, or RGBA32F so that a NaN
// cannot hide behind the 8-bit conversion) and a depth renderbuffer, no MSAA. Reading back flips the rows
// to top-first here and nowhere else.
#pragma once

#include "shadelab/gl/handles.h"
#include "shadelab/image.h"
#include "shadelab/scene.h"

namespace shadelab::gl {

enum class ColorFormat { Rgba8, Rgba32F };
// Depth24 for the standard depth mode; Depth32F for reversed-Z, where float depth's precision near 0
// meets the far plane (DESIGN §2).
enum class DepthFormat { Depth24, Depth32F };

class RenderTarget {
public:
    // Throws InputError if the size exceeds what the context allows, RuntimeError if incomplete.
    RenderTarget(int width, int height, ColorFormat format = ColorFormat::Rgba8,
                 DepthFormat depth = DepthFormat::Depth24);
    void bind() const;
    Image readRgba8() const;
    // Copies the colour attachment, pixel for pixel, into the window's framebuffer with its lower-left
    // corner at (x, y) (GL's convention, rows up); leaves the window's framebuffer bound.
    void blitToWindow(int x, int y) const;
    ImageF readFloat() const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    template <typename Pixels> Pixels read(unsigned type, const char* stage) const;

    int width_, height_;
    Framebuffer fbo_;
    Renderbuffer color_, depth_;
};

// The depth attachment a scene's depth mode asks for.
DepthFormat depthFormatFor(DepthMode mode);

// Binds the window's own framebuffer again after drawing offscreen.
void bindDefaultFramebuffer();
// Binds the window's framebuffer and clears all of its width × height to `color` (and depth to 0).
void clearWindow(int width, int height, glm::vec3 color);

} // namespace shadelab::gl
