// The GL calls that create and delete each kind of object gl/handles.h owns.
#include "shadelab/gl/handles.h"

#include <glad/gl.h>

namespace shadelab::gl {

Id BufferKind::create() {
    Id id = 0;
    glGenBuffers(1, &id);
    return id;
}
void BufferKind::destroy(Id id) {
    glDeleteBuffers(1, &id);
}

Id VertexArrayKind::create() {
    Id id = 0;
    glGenVertexArrays(1, &id);
    return id;
}
void VertexArrayKind::destroy(Id id) {
    glDeleteVertexArrays(1, &id);
}

Id ProgramKind::create() {
    return glCreateProgram();
}
void ProgramKind::destroy(Id id) {
    glDeleteProgram(id);
}

Id FramebufferKind::create() {
    Id id = 0;
    glGenFramebuffers(1, &id);
    return id;
}
void FramebufferKind::destroy(Id id) {
    glDeleteFramebuffers(1, &id);
}

Id RenderbufferKind::create() {
    Id id = 0;
    glGenRenderbuffers(1, &id);
    return id;
}
void RenderbufferKind::destroy(Id id) {
    glDeleteRenderbuffers(1, &id);
}

Id TextureKind::create() {
    Id id = 0;
    glGenTextures(1, &id);
    return id;
}
void TextureKind::destroy(Id id) {
    glDeleteTextures(1, &id);
}

Id QueryKind::create() {
    Id id = 0;
    glGenQueries(1, &id);
    return id;
}
void QueryKind::destroy(Id id) {
    glDeleteQueries(1, &id);
}

Id ShaderKind::create(unsigned stage) {
    return glCreateShader(stage);
}
void ShaderKind::destroy(Id id) {
    glDeleteShader(id);
}

} // namespace shadelab::gl
