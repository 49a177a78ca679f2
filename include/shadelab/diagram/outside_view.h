// The outside view (lecture notes, "Camera transformation" and "Viewing and projection normalization"):
// the scene seen from an observer who sees the viewing camera too: its eye e and axes u, v, w, its view
// volume between the near and far planes, and every light. Plain CPU data in world space; the GL layer
// draws it (gl/views.cpp) over the observer's render of the objects.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "shadelab/diagram/overlay.h"
#include "shadelab/scene/observer.h"
#include "shadelab/scene/scene.h"

namespace shadelab {

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
