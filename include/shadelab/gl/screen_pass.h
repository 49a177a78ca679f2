// What the teaching views (src/gl/views.h) draw with besides the scene draw and their render targets:
// full-screen (or any rectangle) fragment passes, and CPU-made images (labels, plots, the demo's bands)
// drawn into the picture. Each owns its GL objects (gl/handles.h).
#pragma once

#include <vector>

#include "shadelab/gl/handles.h"
#include "shadelab/gl/render_target.h"
#include "shadelab/image/image.h"
#include "shadelab/last_key.h"

namespace shadelab::gl {

// A fragment shader (shaders/<fragment>, no defines) over a rectangle from shaders/quad.vert.glsl. A pass
// finds its uniforms' locations once, when it is built (location), and gives each sampler its texture unit
// then (setSampler): a frame looks nothing up by name.
struct ScreenPass {
    explicit ScreenPass(const char* fragment);
    int location(const char* name) const;
    void setSampler(const char* name, int unit) const; // leaves the current program as it was
    // The rectangle [x0, x1] × [y0, y1] of the current viewport, in pixels from its lower left; needs a
    // vertex array bound (none of its attributes are read).
    void draw(double x0, double y0, double x1, double y1, int viewportWidth, int viewportHeight) const;

    Program program;
    int ndcRect = -1;
};

void bindTexture(int unit, const Texture& texture);

// An image made on the CPU from a few values (a label's words and figures, a lesson step's band), kept as
// a texture. update() makes it, and uploads it, only when those values (its key) differ from the last
// ones: a frame that shows the same values builds no text and uploads nothing.
class Sprite {
public:
    int width() const { return width_; }
    int height() const { return height_; }
    const Texture& texture() const { return texture_; }
    // Uploads `image` (rows from the top) as the sprite's texture.
    void set(const Image& image);

private:
    Texture texture_{NoCreate}; // made at the first set(): a sprite can be declared before a context exists
    int width_ = 0, height_ = 0;
};

template <class Key> class KeyedSprite : public Sprite {
public:
    // `make()` (returning an Image) is called only when `key` differs from the last update's. When it (or
    // the upload) throws, the next update tries again.
    template <class Make> const KeyedSprite& update(const Key& key, Make&& make) {
        if (last_.changed(key)) {
            try {
                set(make());
            } catch (...) {
                last_.forget();
                throw;
            }
        }
        return *this;
    }

private:
    LastKey<Key> last_;
};

// Draws RGBA8 images made on the CPU into the picture, blended by their alpha (the picture's own alpha,
// its coverage, is kept).
class ImagePass {
public:
    ImagePass();
    // The sprite with its top left corner at (left, top) of the viewport (x, 0, width, height), rows from
    // the top.
    void draw(const Sprite& sprite, int left, int top, int viewportX, int viewportWidth,
              int viewportHeight) const;
    const VertexArray& emptyVertexArray() const { return empty_; }

private:
    struct SpritePass : ScreenPass {
        SpritePass() : ScreenPass("sprite.frag.glsl") { setSampler("uImage", 0); }
        int origin = location("uOrigin");
    };
    SpritePass sprite_;
    VertexArray empty_;
};

} // namespace shadelab::gl
