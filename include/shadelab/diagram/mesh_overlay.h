// The wireframe and normals overlay (Scene::overlay, the demo's W key) of the shapes that are not the
// sphere: the teapot at the level it is drawn at and a model's own mesh. The same lines as the sphere's
// (diagram/overlay.h: colours, kOverlayLift, the normal-matrix rule), from a TriangleMesh that has no
// subdivision hierarchy: edges found by position, normals thinned by the teapot's patch grid or by a stride.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "shadelab/diagram/overlay.h"
#include "shadelab/geometry/teapot.h"
#include "shadelab/geometry/triangle_mesh.h"
#include "shadelab/scene/camera.h"
#include "shadelab/scene/scene.h"

namespace shadelab {

// The teapot's normals overlay shows the normals of this level's grid points and faces at most: a level-n
// patch grid is (2ⁿ)², so level 2 already draws 800 vertex and 992 face normals (the sphere's level 3: 130
// and 256).
inline constexpr int kTeapotNormalsOverlayLevel = 2;
// A model's normals overlay shows at most about this many face normals and as many vertex normals (one in
// a stride of its faces and of its vertices, in the file's order).
inline constexpr std::size_t kModelNormalsShown = 512;

// In object space, as overlayLines(SphereMesh) draws the sphere's: every edge once — found by its two end
// positions, so that edges the teapot's patches share along their borders (each patch has its own
// vertices) and a model's vertices split by their normals (a cube's corners) draw once, and an edge between
// two vertices at one point (the lid's cusp) not at all — lifted off the surface by kOverlayLift − 1 of the
// mesh's bounding radius along the vertex normals; with Normals, each shown face's normal from its centroid
// and each shown vertex's normal (the analytic one for the teapot) from its lifted position, a vertex at the
// place and with the normal of an earlier one drawn once. Each normal runs along the normal matrix of
// `rule` times n in world space (DESIGN §2) and is as long there whichever way it points.
//
// The teapot thins past kTeapotNormalsOverlayLevel (level L shown as s = min(L, 2)): the vertices of
// level s's grid points ((i, j) multiples of 2^(L−s)) and, in each of its triangles, the fine triangle
// at the coarse one's centroid.
std::vector<LineVertex> teapotOverlayLines(const TeapotMesh& mesh, Overlay overlay,
                                           const glm::dmat3& worldFromObject = glm::dmat3(1),
                                           NormalMatrixRule rule = NormalMatrixRule::InverseTranspose);
// A model's (any TriangleMesh): one face in ⌈faces / kModelNormalsShown⌉ and one vertex in
// ⌈vertices / kModelNormalsShown⌉ show their normals.
std::vector<LineVertex> modelOverlayLines(const TriangleMesh& mesh, Overlay overlay,
                                          const glm::dmat3& worldFromObject = glm::dmat3(1),
                                          NormalMatrixRule rule = NormalMatrixRule::InverseTranspose);

} // namespace shadelab
