// The GL calls that create and delete each kind of object gl/handles.h owns.
#include "shadelab/gl/handles.h"

#include <glad/gl.h>

namespace shadelab::gl {
namespace {

// One name from a glGen* function.
template <class Generate> Id generated(Generate generate) {
    Id id = 0;
    generate(1, &id);
    return id;
}

} // namespace

Id BufferKind::create() {
    return generated(glGenBuffers);
}
void BufferKind::destroy(Id id) {
    glDeleteBuffers(1, &id);
}

Id VertexArrayKind::create() {
    return generated(glGenVertexArrays);
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
    return generated(glGenFramebuffers);
}
void FramebufferKind::destroy(Id id) {
    glDeleteFramebuffers(1, &id);
}

Id RenderbufferKind::create() {
    return generated(glGenRenderbuffers);
}
void RenderbufferKind::destroy(Id id) {
    glDeleteRenderbuffers(1, &id);
}

Id TextureKind::create() {
    return generated(glGenTextures);
}
void TextureKind::destroy(Id id) {
    glDeleteTextures(1, &id);
}

Id QueryKind::create() {
    return generated(glGenQueries);
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
