// The outside view (lecture notes, "Camera transformation" and "Viewing and projection normalization"):
// the scene seen from an observer who sees the viewing camera too: its eye e and axes u, v, w, its view
// volume between the near and far planes, and every light. Plain CPU data in world space; the GL layer
// draws it (gl/views.cpp) over the observer's render of the objects.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "shadelab/geometry/overlay.h"
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

struct OutsideLabel {
    glm::dvec3 positionWorld;
    std::string text;
    bool leftOfPoint = false; // drawn ending left of the point instead of starting right of it
};

// What the outside view draws over the objects, in world space: lines (GL_LINES pairs) for the view
// volume's edges and the lines from e to its near corners, e and the axes u, v, w from it, and the light
// markers (a point light a small wire sphere, a directional light three parallel arrows along its
// direction, a spot light its cone at the cutoff angle); translucent triangles for the near and far
// faces; and the labels. With the unnegated perspective matrix the volume is drawn red, labelled "w < 0",
// and its point reflection through e (where w > 0, behind the eye) green.
struct OutsideDrawing {
    std::vector<LineVertex> lines;
    std::vector<LineVertex> faces;
    std::vector<OutsideLabel> labels;
};
OutsideDrawing outsideDrawing(const Scene& scene);

// The NDC view: the camera's normalized device coordinates, the cube [−1, 1]³ (near at z = +1, DESIGN
// §2), taken as a space of its own and seen from an observer placed by scene.view.observer in its axes
// (azimuth about y from +z, elevation towards +y), framing the cube. Its matrices (sceneView) map NDC to
// the observer's clip space; objects are drawn there through M_proj·M_cam (gl/renderer.h), so a sphere
// shows as the egg it becomes under a perspective projection.
Scene ndcObserverScene(const Scene& scene);
// The cube's edges, its near face (z = +1) and far face (z = −1) translucent, and their labels, in NDC.
OutsideDrawing ndcCubeDrawing();
inline constexpr glm::vec3 kCubeEdgeColor{0.8f, 0.8f, 0.8f};

// The lights' markers alone, as the outside view draws them (the overlay "lights" in the camera's picture).
std::vector<LineVertex> lightMarkers(const Scene& scene);

// Colours of the drawing, linear RGB.
inline constexpr glm::vec3 kVolumeEdgeColor{1.0f, 0.85f, 0.2f};
inline constexpr glm::vec3 kClippedVolumeColor{1.0f, 0.25f, 0.2f}; // unnegated: w < 0 in the volume
inline constexpr glm::vec3 kBehindEyeColor{0.3f, 1.0f, 0.4f};      // unnegated: where w > 0
inline constexpr glm::vec3 kNearFaceColor{0.2f, 0.8f, 1.0f};
inline constexpr glm::vec3 kFarFaceColor{0.9f, 0.3f, 1.0f};
inline constexpr glm::vec3 kAxisUColor{1.0f, 0.3f, 0.3f};
inline constexpr glm::vec3 kAxisVColor{0.3f, 1.0f, 0.3f};
inline constexpr glm::vec3 kAxisWColor{0.35f, 0.55f, 1.0f};
inline constexpr float kFaceAlpha = 0.18f;

} // namespace shadelab
