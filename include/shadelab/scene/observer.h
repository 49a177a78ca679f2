// The observers of the outside and NDC views (lecture notes, "Camera transformation" and "Viewing and
// projection normalization"): the cameras that see the viewing camera, its view volume and the lights, or
// its NDC cube, as scenes of their own. What they are drawn with is diagram/outside_view.h.
#pragma once

#include <array>

#include "shadelab/scene/scene.h"

namespace shadelab {

// The view volume's corners: inverse(M_proj·M_cam) of the NDC cube's corners (x, y, z each ±1; index bit 0
// is x, bit 1 y, bit 2 z, so corners 4..7 lie on the near plane, z = +1 in DESIGN §2's convention), in
// world space.
std::array<glm::dvec3, 8> viewVolumeCornersWorld(const Scene& scene);

// The scene as the observer sees it: the observer's eye, target, up and a perspective projection framing
// the eye, the objects, the lights and the view volume as far as the objects reach (the far plane is
// drawn, and framed when it is near enough: a far plane 5 times beyond the objects would shrink them to a
// few pixels); scene.view.observer places it. The WebGL matrix and standard depth, and the plain scene
// view; everything else (objects, lights, shading) as in `scene`. `scene` must have the picture's size.
Scene observerScene(const Scene& scene);

// Throws InputError naming "view" when the scene shows the outside view (or a split side does) and the
// observer's camera cannot be drawn in 32-bit float (objects or lights so far that its far plane leaves
// float range): validateScene's check, so that `check` refuses what `render` would.
void checkOutsideView(const Scene& scene);

// The NDC view: the camera's normalized device coordinates, the cube [−1, 1]³ (near at z = +1, DESIGN
// §2), taken as a space of its own and seen from an observer placed by scene.view.observer in its axes
// (azimuth about y from +z, elevation towards +y), framing the cube. Its matrices (sceneView) map NDC to
// the observer's clip space; objects are drawn there through M_proj·M_cam (gl/renderer.h), so a sphere
// shows as the egg it becomes under a perspective projection.
Scene ndcObserverScene(const Scene& scene);

} // namespace shadelab
