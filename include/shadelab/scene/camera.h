// Camera frame and projection matrices (DESIGN §2), computed with GLM in double.
// Interface: near and far are positive distances. Internally DESIGN §2's formulas use the z-coordinates
// n = −near and f = −far. Near maps to NDC z = +1 and far to −1, so visibility needs GL_GREATER with a
// depth clear of 0 (see gl/renderer.cpp).
#pragma once

#include <array>
#include <string_view>

#include <glm/glm.hpp>

namespace shadelab {

struct CameraFrame {
    glm::dvec3 u, v, w; // right, up, backwards (w points from the target to the eye)
    glm::dvec3 eye;
};

// Throws InputError when eye == target or up is parallel to the view direction.
CameraFrame cameraFrame(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up);

// M_cam = [u v w e]⁻¹: world → camera (view) coordinates.
glm::dmat4 viewFromWorld(const CameraFrame& frame);

// The view volume: left/right/bottom/top on the near plane (perspective) or of the box (orthographic);
// near and far are positive distances with 0 < near < far.
struct ViewVolume {
    double left = -1, right = 1, bottom = -1, top = 1;
    double near = 1, far = 10;
};

// Throws InputError for near <= 0, near >= far, left == right, bottom == top or non-finite values.
void validateViewVolume(const ViewVolume& volume);

// Symmetric volume from a vertical field of view (0 < fovy < 180) and aspect = width / height.
ViewVolume viewVolumeFromFovy(double fovyDeg, double aspect, double near, double far);

// M_orth: [l,r]×[b,t]×[f,n] → [−1,1]³, z = n → +1, z = f → −1.
glm::dmat4 orthographicClipFromView(const ViewVolume& volume);

// The WebGL-style perspective matrix (w = −z > 0 in front of the camera). Equals
// diag(1,1,−1,1)·glm::frustumRH_NO(l, r, b, t, near, far).
glm::dmat4 perspectiveClipFromView(const ViewVolume& volume);

// The scene's "perspective_matrix": webgl is the matrix above, the perspective matrix of the lecture
// multiplied by −1 (DESIGN §2); unnegated is that matrix before the multiplication, which gives every point
// in front of the eye w = z < 0, so the clipper removes them all: the picture is empty, the lecture's reason
// for the −1, drawn on purpose. An orthographic matrix has w = 1 and no −1 to leave out.
enum class PerspectiveMatrix { WebGl, Unnegated };
inline constexpr std::array kPerspectiveMatrices = {PerspectiveMatrix::WebGl, PerspectiveMatrix::Unnegated};
std::string_view toString(PerspectiveMatrix matrix); // "webgl" | "unnegated"

// Reversed-Z for a [0, 1] clip range (glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)): near → depth 1, far →
// 0, so the float depth buffer's dense range near 0 meets 1/z's crowding near the far plane and the two
// cancel: Δd ≈ 1.2e-7·d at any near/far (DESIGN §2). x and y as in the standard matrices.
// Perspective: depth = near·(far/(−z) − 1)/(far − near); with `infiniteFar`, depth = near/(−z).
glm::dmat4 reversedPerspectiveClipFromView(const ViewVolume& volume, bool infiniteFar);
// Orthographic: depth = (z + far)/(far − near), linear.
glm::dmat4 reversedOrthographicClipFromView(const ViewVolume& volume);

// Normal matrix of the upper 3×3 of a model-view matrix: the cofactor matrix times sign(det), i.e.
// (M⁻¹)ᵀ up to a positive scale. Never divides, so it stays finite for near-singular M; normals must be
// renormalized after it.
glm::dmat3 normalMatrix(const glm::dmat4& viewFromObject);

// The scene's "normal_matrix": what takes object-space normals to view space. InverseTranspose is (M⁻¹)ᵀ
// (normalMatrix), which keeps a normal perpendicular to its surface under any M; Model is M itself, what
// students first try: right for rotations and uniform scale, wrong (tilted towards the stretched axis)
// wherever M scales unevenly (DESIGN §2). Model is the lesson's wrong picture, drawn on purpose.
enum class NormalMatrixRule { InverseTranspose, Model };
inline constexpr std::array kNormalMatrixRules = {NormalMatrixRule::InverseTranspose,
                                                  NormalMatrixRule::Model};
std::string_view toString(NormalMatrixRule rule); // "inverse-transpose" | "model"

// max |m[c][r]|: what normalViewFromObject and the ray cast divide a matrix by to keep it O(1).
double largestAbsEntry(const glm::dmat3& m);

// The normal matrix of `rule` for viewFromObject's upper 3×3, divided by its largest entry: only its
// direction counts (the shaders and the reference renormalize), and so it fits float for radii from 1e-30 to
// 1e30, where the cofactor itself scales like radius². M is scaled to O(1) before the cofactor is taken, so
// the cofactor cannot under- or overflow either.
glm::dmat3 normalViewFromObject(const glm::dmat4& viewFromObject, NormalMatrixRule rule);

} // namespace shadelab
