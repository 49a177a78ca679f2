// The lecture's matrices as numbers (lecture notes, "Camera transformation" to "Normal transformation"):
// the camera frame e, u, v, w and M_cam, the projection matrix with the view volume it normalizes, and one
// object's model matrix M and normal matrix. The window's panel and the page show it live; `shadelab
// render --print-matrices` prints it for a scene.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "shadelab/scene/scene.h"

namespace shadelab::app {

// One entry of a printed matrix or vector: kEntryDigits + 1 characters, a space first (matrices_text.cpp
// says how a number is written).
inline constexpr std::size_t kEntryDigits = 9;
std::string matrixEntry(double x);

// Monospaced text for the scene as drawn (its image size gives the perspective aspect). The camera's: e, u,
// v, w, M_cam and the projection matrix with its view volume. Throws InputError for a scene sceneView
// refuses.
std::string cameraMatricesText(const Scene& scene);
// One object's (objects[object], which must exist): M and the normal matrix of the scene's rule.
std::string objectMatricesText(const Scene& scene, std::size_t object);
// What the window's panel and the page show: the camera's, then the shown object's (none: the camera's
// alone); a scene sceneView refuses gives its message instead.
std::string matricesPanelText(const Scene& scene, std::optional<std::size_t> object);

} // namespace shadelab::app
