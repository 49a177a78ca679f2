#include "shadelab/gl/mesh.h"

#include "shadelab/geometry/mesh_layout.h"

#include <cstddef>

#include <glad/gl.h>

namespace shadelab::gl {
namespace {

template <typename T> void upload(GLenum target, const Buffer& buffer, const std::vector<T>& data) {
    glBindBuffer(target, buffer.get());
    glBufferData(target, GLsizeiptr(data.size() * sizeof(T)), data.data(), GL_STATIC_DRAW);
}

void attribute(GLuint location, GLsizei stride, std::size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
}

} // namespace

GpuMesh::GpuMesh(const TriangleMesh& mesh, MeshLayout layout)
    : layout_(layout), triangles_(int(mesh.triangles.size())) {
    glBindVertexArray(vao_.get());
    if (layout == MeshLayout::Smooth) {
        upload(GL_ARRAY_BUFFER, vertices_, smoothVertices(mesh));
        indices_ = Buffer();
        upload(GL_ELEMENT_ARRAY_BUFFER, indices_, smoothIndices(mesh)); // recorded in the VAO
        attribute(kPositionAttribute, sizeof(SmoothVertex), offsetof(SmoothVertex, position));
        attribute(kNormalAttribute, sizeof(SmoothVertex), offsetof(SmoothVertex, normal));
    } else {
        upload(GL_ARRAY_BUFFER, vertices_, flatVertices(mesh));
        attribute(kPositionAttribute, sizeof(FlatVertex), offsetof(FlatVertex, position));
        attribute(kNormalAttribute, sizeof(FlatVertex), offsetof(FlatVertex, faceNormal));
        attribute(kCentroidAttribute, sizeof(FlatVertex), offsetof(FlatVertex, centroid));
    }
    glBindVertexArray(0);
}

GpuMesh::GpuMesh(const TeapotMesh& proxy)
    : layout_(MeshLayout::PatchUv), triangles_(int(proxy.triangles.size())) {
    struct PatchVertex {
        glm::vec3 position, normal, patchUv;
    };
    std::vector<PatchVertex> vertices(proxy.positions.size());
    for (std::size_t i = 0; i < vertices.size(); ++i)
        vertices[i] = {glm::vec3(proxy.positions[i]), glm::vec3(proxy.vertexNormals[i]),
                       glm::vec3(proxy.patchUv[i])};
    glBindVertexArray(vao_.get());
    upload(GL_ARRAY_BUFFER, vertices_, vertices);
    indices_ = Buffer();
    upload(GL_ELEMENT_ARRAY_BUFFER, indices_, smoothIndices(proxy));
    attribute(kPositionAttribute, sizeof(PatchVertex), offsetof(PatchVertex, position));
    attribute(kNormalAttribute, sizeof(PatchVertex), offsetof(PatchVertex, normal));
    attribute(kPatchUvAttribute, sizeof(PatchVertex), offsetof(PatchVertex, patchUv));
    glBindVertexArray(0);
}

void GpuMesh::draw() const {
    glBindVertexArray(vao_.get());
    if (layout_ != MeshLayout::Flat)
        glDrawElements(GL_TRIANGLES, triangles_ * 3, GL_UNSIGNED_INT, nullptr);
    else
        glDrawArrays(GL_TRIANGLES, 0, triangles_ * 3);
    glBindVertexArray(0);
}

GpuLines::GpuLines() {
    glBindVertexArray(vao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.get());
    attribute(0, sizeof(LineVertex), offsetof(LineVertex, position));
    attribute(1, sizeof(LineVertex), offsetof(LineVertex, color));
    glBindVertexArray(0);
}

void GpuLines::set(std::span<const LineVertex> vertices) {
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size_bytes()), vertices.data(), GL_DYNAMIC_DRAW);
    vertexCount_ = int(vertices.size());
}

void GpuLines::draw() const {
    if (vertexCount_ == 0) return;
    glBindVertexArray(vao_.get());
    glDrawArrays(GL_LINES, 0, vertexCount_);
    glBindVertexArray(0);
}

void GpuLines::drawTriangles() const {
    if (vertexCount_ == 0) return;
    glBindVertexArray(vao_.get());
    glDrawArrays(GL_TRIANGLES, 0, vertexCount_);
    glBindVertexArray(0);
}

void drawWith(const Program& program, const GpuMesh& mesh) {
    glUseProgram(program.get());
    mesh.draw();
    glUseProgram(0);
}

} // namespace shadelab::gl
