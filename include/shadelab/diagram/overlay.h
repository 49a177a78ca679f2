// Lines drawn over the shaded picture for teaching: the mesh's edges and normals (Scene::overlay, the demo's
// W key) and the probe's vectors l, n, v and r or h. Plain CPU data; the GL layer draws it (gl/renderer.h).
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "shadelab/exact/probe.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/scene/camera.h"
#include "shadelab/scene/scene.h"

namespace shadelab {

// Two of these make a line segment (GL_LINES). Colours are linear RGB, as everywhere in shadelab.
struct LineVertex {
    glm::vec3 position;
    glm::vec3 color;
};

inline constexpr glm::vec3 kEdgeColor{0.85f, 0.85f, 0.85f};
inline constexpr glm::vec3 kFaceNormalColor{1.0f, 0.75f, 0.1f};
inline constexpr glm::vec3 kVertexNormalColor{0.1f, 0.8f, 1.0f};
// The probe's vectors: l yellow, n white, v green, r or h magenta.
inline constexpr glm::vec3 kToLightColor{1.0f, 0.95f, 0.1f};
inline constexpr glm::vec3 kNormalColor{1.0f, 1.0f, 1.0f};
inline constexpr glm::vec3 kToViewerColor{0.2f, 1.0f, 0.3f};
inline constexpr glm::vec3 kSpecularVectorColor{1.0f, 0.2f, 1.0f};
// The normal matrix's argument where M scales unevenly: M·t blue, M·n red, (M⁻¹)ᵀ·n cyan.
inline constexpr glm::vec3 kTangentByMColor{0.45f, 0.5f, 1.0f};
inline constexpr glm::vec3 kNormalByMColor{1.0f, 0.15f, 0.15f};
inline constexpr glm::vec3 kNormalByInverseTransposeColor{0.2f, 0.95f, 0.95f};
// An orange cross marks the point: n and v often face the camera and show as dots.
inline constexpr glm::vec3 kProbeMarkColor{1.0f, 0.35f, 0.1f};

// Edges are drawn this much outside the unit sphere's mesh, so that the depth test keeps the front ones
// and hides those behind the object without fighting the faces they lie on.
inline constexpr float kOverlayLift = 1.003f;

// The normals overlay thins a mesh finer than kNormalsOverlayLevel so that it reads at any level: it draws
// the normals of that level's vertices, and of one face in faceStride (4^(level - shown level)), the
// centre descendant of each face of that level. The window's and the page's status line say so.
inline constexpr int kNormalsOverlayLevel = 3;
struct NormalsShown {
    int level;              // the level whose vertices and faces show a normal: min(level, 3)
    std::size_t faceStride; // one face normal drawn in this many (1 up to level 3)
};
NormalsShown normalsShown(int level);

// In object space: every edge once (Wireframe, Normals), and with Normals each face normal from its
// centroid and each vertex normal (of the mesh's kind) from its vertex, a little longer than an edge,
// thinned past kNormalsOverlayLevel (normalsShown). The normals are the ones the shading uses: drawn through
// the object's matrix M (`worldFromObject`, its linear part), each line runs along the normal matrix of
// `rule` times n, (M⁻¹)ᵀ·n or, wrong on purpose, M·n (DESIGN §2), and is as long in world space whichever way
// it points.
std::vector<LineVertex> overlayLines(const SphereMesh& mesh, Overlay overlay,
                                     const glm::dmat3& worldFromObject = glm::dmat3(1),
                                     NormalMatrixRule rule = NormalMatrixRule::InverseTranspose);

// In view space: the probe's n, v, l and r/h from the point where the mode evaluates the lighting, each
// `length` long (l and r/h only where a light is not ambient); where M scales unevenly, M·t, M·n and
// (M⁻¹)ᵀ·n from the same point (NormalMatrixArgument); then a cross of two segments across the point in
// the view plane, `length`/5 wide.
std::vector<LineVertex> probeLines(const ProbeReport& probe, double length);

} // namespace shadelab
