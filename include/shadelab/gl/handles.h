// Move-only RAII owners for GL objects, as Magnum's GL::Buffer: constructing one creates its GL object (a
// context must be current), `NoCreate` makes an empty owner to be given an object later, and wrap() adopts
// an id made elsewhere. Every GL object has exactly one owner, and no raw id outlives a function scope.
// The GL calls that create and delete each kind are in src/gl/handles.cpp; the deleter runs only while a
// context is current (handles are destroyed before it).
#pragma once

#include <utility>

namespace shadelab::gl {

using Id = unsigned int; // GLuint

// Makes an owner that holds no GL object yet.
inline constexpr struct NoCreateT { explicit NoCreateT() = default; } NoCreate{};

// Kind gives `static Id create()` (for a default-constructible kind) and `static void destroy(Id)`.
template <class Kind> class Handle {
public:
    Handle() : id_(Kind::create()) {}
    explicit Handle(NoCreateT) noexcept {}
    static Handle wrap(Id id) noexcept {
        Handle handle{NoCreate};
        handle.id_ = id;
        return handle;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    ~Handle() { reset(); }

    Id get() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_ != 0) Kind::destroy(std::exchange(id_, 0));
    }

private:
    Id id_ = 0;
};

struct BufferKind {
    static Id create();
    static void destroy(Id id);
};
struct VertexArrayKind {
    static Id create();
    static void destroy(Id id);
};
struct ProgramKind {
    static Id create();
    static void destroy(Id id);
};
struct FramebufferKind {
    static Id create();
    static void destroy(Id id);
};
struct RenderbufferKind {
    static Id create();
    static void destroy(Id id);
};
struct TextureKind {
    static Id create();
    static void destroy(Id id);
};
struct QueryKind {
    static Id create();
    static void destroy(Id id);
};
struct ShaderKind {
    static Id create(unsigned stage); // GL_VERTEX_SHADER, …: no default
    static void destroy(Id id);
};

using Buffer = Handle<BufferKind>;
using VertexArray = Handle<VertexArrayKind>;
using Program = Handle<ProgramKind>;
using Framebuffer = Handle<FramebufferKind>;
using Renderbuffer = Handle<RenderbufferKind>;
using Texture = Handle<TextureKind>;
using Query = Handle<QueryKind>;

// A shader of one stage (GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_GEOMETRY_SHADER).
class Shader : public Handle<ShaderKind> {
public:
    explicit Shader(unsigned stage) : Handle(wrap(ShaderKind::create(stage))) {}
    explicit Shader(NoCreateT) noexcept : Handle(NoCreate) {}
};

} // namespace shadelab::gl
