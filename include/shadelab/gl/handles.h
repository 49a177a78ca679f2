// Move-only RAII owners for GL objects: every GL object has exactly one owner, and no raw id outlives a
// function scope. The deleter runs only while a context is current (handles are destroyed before it).
#pragma once

#include <utility>

namespace shadelab::gl {

using Id = unsigned int; // GLuint

template <void (*Delete)(Id)> class Handle {
public:
    Handle() = default;
    explicit Handle(Id id) : id_(id) {}
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
        if (id_ != 0) Delete(std::exchange(id_, 0));
    }

private:
    Id id_ = 0;
};

void deleteBuffer(Id id);
void deleteVertexArray(Id id);
void deleteShader(Id id);
void deleteProgram(Id id);
void deleteFramebuffer(Id id);
void deleteRenderbuffer(Id id);
void deleteTexture(Id id);

using Buffer = Handle<deleteBuffer>;
using VertexArray = Handle<deleteVertexArray>;
using Shader = Handle<deleteShader>;
using Program = Handle<deleteProgram>;
using Framebuffer = Handle<deleteFramebuffer>;
using Renderbuffer = Handle<deleteRenderbuffer>;
using Texture = Handle<deleteTexture>;

} // namespace shadelab::gl
