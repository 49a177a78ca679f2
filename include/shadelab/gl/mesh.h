// A triangle mesh (the sphere, the teapot, a model) uploaded to the GPU: indexed shared vertices for smooth
// modes, or three vertices per triangle with centroid and face normal for flat shading; the teapot's exact
// shading's proxy adds each vertex's (patch, u, v).
#pragma once

#include "shadelab/gl/handles.h"
#include <span>

#include "shadelab/diagram/overlay.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/geometry/teapot.h"

namespace shadelab::gl {

enum class MeshLayout { Smooth, Flat, PatchUv };

// Attribute locations shared with shaders/surface.vert.glsl.
inline constexpr unsigned kPositionAttribute = 0;
inline constexpr unsigned kNormalAttribute = 1;   // smooth: vertex normal; flat: face normal
inline constexpr unsigned kCentroidAttribute = 2; // flat only
inline constexpr unsigned kPatchUvAttribute = 2;  // PatchUv only (shaders/exact_patch.vert.glsl)

class GpuMesh {
public:
    GpuMesh(const TriangleMesh& mesh, MeshLayout layout); // Smooth or Flat
    explicit GpuMesh(const TeapotMesh& proxy);            // PatchUv: smooth with the (patch, u, v)
    void draw() const;
    MeshLayout layout() const { return layout_; }
    int triangleCount() const { return triangles_; }

private:
    MeshLayout layout_;
    int triangles_ = 0;
    VertexArray vao_;
    Buffer vertices_, indices_{NoCreate}; // indices: the smooth layout only
};

// Line segments (GL_LINES) of position and colour (attribute locations 0 and 1 of shaders/lines.vert.glsl):
// the overlay's edges and normals, uploaded once, or the probe's vectors, replaced with set().
class GpuLines {
public:
    GpuLines();
    explicit GpuLines(std::span<const LineVertex> vertices) : GpuLines() { set(vertices); }
    void set(std::span<const LineVertex> vertices);
    void draw() const;
    void drawTriangles() const; // the same vertices as GL_TRIANGLES (the outside view's faces)

private:
    int vertexCount_ = 0;
    VertexArray vao_;
    Buffer vertices_;
};

// Draws `mesh` with `program` and its uniforms as they are (for timing a program's first draw).
void drawWith(const Program& program, const GpuMesh& mesh);

} // namespace shadelab::gl
