// An offscreen framebuffer the program owns: a colour texture (RGBA8, or RGBA32F so that a NaN cannot hide
// behind the 8-bit conversion and the teaching views can sample unrounded colours) and, unless
// DepthFormat::None, a depth renderbuffer; no MSAA. Reading back flips the rows to top-first here and
// nowhere else.
#pragma once

#include <vector>

#include "shadelab/gl/handles.h"
#include "shadelab/image/image.h"
#include "shadelab/scene/scene.h"

namespace shadelab::gl {

enum class ColorFormat { Rgba8, Rgba32F };
// Depth24 for the standard depth mode; Depth32F for reversed-Z, where float depth's precision near 0
// meets the far plane (DESIGN §2); None for a pass that tests no depth (the error view's reduction).
enum class DepthFormat { None, Depth24, Depth32F };

class RenderTarget {
public:
    // Holds nothing until fit().
    RenderTarget() = default;
    // Throws InputError if the size exceeds what the context allows, RuntimeError if the context lacks
    // float colour targets or the framebuffer is incomplete.
    RenderTarget(int width, int height, ColorFormat format = ColorFormat::Rgba8,
                 DepthFormat depth = DepthFormat::Depth24);
    // Allocates anew when the size or a format differs from what it holds (a window's or a view's target
    // follows the viewport), the old attachments freed first; throws as the constructor does, and then
    // holds nothing.
    void fit(int width, int height, ColorFormat format, DepthFormat depth);
    void bind() const;
    Image readRgba8() const;
    ImageF readFloat() const;
    std::vector<float> readFloatRow(int y) const; // row y (from the bottom) as RGBA floats
    // Copies the colour attachment, pixel for pixel, into the window's framebuffer with its lower-left
    // corner at (x, y) (GL's convention, rows up); leaves the window's framebuffer bound.
    void blitToWindow(int x, int y) const;
    const Texture& color() const { return color_; } // to sample
    int width() const { return width_; }
    int height() const { return height_; }

private:
    template <typename Pixels> Pixels read(unsigned type, const char* stage) const;

    int width_ = 0, height_ = 0;
    ColorFormat format_ = ColorFormat::Rgba8;
    DepthFormat depthFormat_ = DepthFormat::None;
    Framebuffer fbo_{NoCreate};
    Texture color_{NoCreate};
    Renderbuffer depth_{NoCreate};
};

// The depth attachment a scene's depth mode asks for.
DepthFormat depthFormatFor(DepthMode mode);

// Binds the window's own framebuffer again after drawing offscreen.
void bindDefaultFramebuffer();
// Binds the window's framebuffer and clears all of its width × height to `color` (and depth to 0).
void clearWindow(int width, int height, glm::vec3 color);

} // namespace shadelab::gl
