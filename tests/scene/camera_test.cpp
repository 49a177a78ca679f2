// Camera frame, projections and the normal matrix against DESIGN §2 and GLM's own matrices.
#include "shadelab/scene/camera.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "input_error.h"
#include "shadelab/errors.h"

namespace shadelab {
namespace {

using test::inputErrorOf;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

template <int C, int R>
double maxAbsDifference(const glm::mat<C, R, double>& a, const glm::mat<C, R, double>& b) {
    double worst = 0;
    for (int c = 0; c < C; ++c)
        for (int r = 0; r < R; ++r) worst = std::max(worst, std::abs(a[c][r] - b[c][r]));
    return worst;
}

template <int C, int R> bool allFinite(const glm::mat<C, R, double>& m) {
    for (int c = 0; c < C; ++c)
        for (int r = 0; r < R; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

std::string str(const glm::dvec3& v) {
    std::ostringstream out;
    out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return out.str();
}

// The message of the InputError `f` throws ("" if it throws nothing; another exception type fails the test).
glm::dvec3 randomVector(std::mt19937_64& rng, double range) {
    std::uniform_real_distribution<double> d(-range, range);
    return {d(rng), d(rng), d(rng)};
}

// ---- camera frame ----

struct LookAtCase {
    glm::dvec3 eye, target, up;
};

std::vector<LookAtCase> lookAtCases() {
    std::vector<LookAtCase> cases = {
        {{0, 0, 4}, {0, 0, 0}, {0, 1, 0}},              // the default camera
        {{3, 3, 5}, {0.5, -1, 2}, {0, 0, 1}},           // z up
        {{0, 10, 0.001}, {0, 0, 0}, {0, 1, 0}},         // looking almost straight down the up axis
        {{-7, 2, -9}, {40, -3, 11}, {0.2, 7, -0.3}},    // up neither unit nor perpendicular to the view
        {{1e-3, 2e-3, 0}, {0, 0, 0}, {5, -1, 1}},       // tiny distance
        {{250, -400, 90}, {251, -399, 91}, {-1, 0, 0}}, // far from the origin
        {{0, 0, -4}, {0, 0, 0}, {0, -1, 0}},            // upside down, behind the origin
    };
    std::mt19937_64 rng(20240611);
    while (cases.size() < 40) {
        const glm::dvec3 eye = randomVector(rng, 20), target = randomVector(rng, 20),
                         up = randomVector(rng, 3);
        if (glm::length(glm::cross(up, eye - target)) > 1e-3 * glm::length(up) * glm::length(eye - target))
            cases.push_back({eye, target, up});
    }
    return cases;
}

TEST(CameraFrame, ViewFromWorldEqualsGlmLookAt) {
    for (const LookAtCase& c : lookAtCases()) {
        SCOPED_TRACE("eye " + str(c.eye) + " target " + str(c.target) + " up " + str(c.up));
        const glm::dmat4 view = viewFromWorld(cameraFrame(c.eye, c.target, c.up));
        const glm::dmat4 expected = glm::lookAt(c.eye, c.target, c.up);
        // Translation entries are dot products with the eye: their rounding scales with |eye|.
        EXPECT_LE(maxAbsDifference(view, expected), 1e-12 * std::max(1.0, glm::length(c.eye)));
    }
}

TEST(CameraFrame, IsOrthonormalRightHandedAndLooksAtTheTarget) {
    for (const LookAtCase& c : lookAtCases()) {
        SCOPED_TRACE("eye " + str(c.eye) + " target " + str(c.target) + " up " + str(c.up));
        const CameraFrame f = cameraFrame(c.eye, c.target, c.up);
        EXPECT_NEAR(glm::length(f.u), 1, 1e-14);
        EXPECT_NEAR(glm::length(f.v), 1, 1e-14);
        EXPECT_NEAR(glm::length(f.w), 1, 1e-14);
        EXPECT_NEAR(glm::dot(f.u, f.v), 0, 1e-14);
        EXPECT_NEAR(glm::dot(f.v, f.w), 0, 1e-14);
        EXPECT_NEAR(glm::dot(f.w, f.u), 0, 1e-14);
        EXPECT_LE(glm::length(glm::cross(f.u, f.v) - f.w), 1e-14);             // right-handed
        EXPECT_LE(glm::length(f.w - glm::normalize(c.eye - c.target)), 1e-14); // w points back at the eye
        EXPECT_EQ(f.eye, c.eye);
        EXPECT_NEAR(glm::dot(f.u, c.up), 0, 1e-14 * glm::length(c.up)); // right is horizontal
        EXPECT_GT(glm::dot(f.v, c.up), 0);                              // up stays up
        // The target lies on the view axis in front of the camera.
        const glm::dvec4 targetView = viewFromWorld(f) * glm::dvec4(c.target, 1);
        const double distance = glm::length(c.eye - c.target);
        EXPECT_NEAR(targetView.x, 0, 1e-12 * std::max(1.0, glm::length(c.eye)));
        EXPECT_NEAR(targetView.y, 0, 1e-12 * std::max(1.0, glm::length(c.eye)));
        EXPECT_NEAR(targetView.z, -distance, 1e-12 * std::max(1.0, glm::length(c.eye)));
    }
}

// |e − t|² overflows double for an eye at 1.4e154; the frame used to be refused with a false "up is
// parallel to the view direction [-0, -0, -0]". Scale-free normalization gives the exact frame.
TEST(CameraFrame, HugeAndTinyEyeDistancesGiveTheExactFrame) {
    for (double z : {1.4e154, 1e300, 1e-300, 4.9e-324}) {
        SCOPED_TRACE(z);
        const CameraFrame f = cameraFrame({0, 0, z}, {0, 0, 0}, {0, 1, 0});
        EXPECT_EQ(f.w, glm::dvec3(0, 0, 1));
        EXPECT_EQ(f.u, glm::dvec3(1, 0, 0));
        EXPECT_EQ(f.v, glm::dvec3(0, 1, 0));
    }
    const CameraFrame tinyUp = cameraFrame({0, 0, 3}, {0, 0, 0}, {0, 1e-320, 0});
    EXPECT_EQ(tinyUp.v, glm::dvec3(0, 1, 0));
}

TEST(CameraFrame, UpParallelToTheViewDirectionIsAnInputError) {
    const glm::dvec3 eye{1, 2, 3}, target{-2, 0.5, 7};
    const glm::dvec3 forward = target - eye;
    const std::vector<glm::dvec3> ups = {
        forward,                           // parallel
        -forward,                          // anti-parallel
        3.5 * forward,                     // parallel, longer
        1e-20 * forward,                   // tiny and parallel
        -1e-30 * forward,                  // tiny and anti-parallel
        {0, 0, 0},                         // no up at all
        forward + glm::dvec3(0, 0, 1e-15), // parallel up to rounding
    };
    for (const glm::dvec3& up : ups) {
        const std::string message = inputErrorOf([&] { cameraFrame(eye, target, up); });
        EXPECT_NE(message.find("up"), std::string::npos) << "up " << str(up) << ": \"" << message << "\"";
    }
    // Looking straight down the y axis with y up, and straight up it.
    EXPECT_THROW(cameraFrame({0, 5, 0}, {0, 0, 0}, {0, 1, 0}), InputError);
    EXPECT_THROW(cameraFrame({0, -5, 0}, {0, 0, 0}, {0, 1, 0}), InputError);
}

TEST(CameraFrame, EyeAtTheTargetIsAnInputError) {
    for (const glm::dvec3& eye : {glm::dvec3(0, 0, 0), glm::dvec3(1.5, -2, 3)}) {
        const std::string message = inputErrorOf([&] { cameraFrame(eye, eye, {0, 1, 0}); });
        EXPECT_NE(message.find("eye"), std::string::npos) << "\"" << message << "\"";
        EXPECT_NE(message.find("target"), std::string::npos) << "\"" << message << "\"";
    }
}

TEST(CameraFrame, NonFiniteInputsAreInputErrorsNamingTheField) {
    const glm::dvec3 eye{0, 0, 4}, target{0, 0, 0}, up{0, 1, 0};
    for (double bad : {kNaN, kInf, -kInf}) {
        for (int axis = 0; axis < 3; ++axis) {
            glm::dvec3 e = eye, g = target, t = up;
            e[axis] = bad;
            EXPECT_NE(inputErrorOf([&] { cameraFrame(e, target, up); }).find("eye"), std::string::npos);
            g[axis] = bad;
            EXPECT_NE(inputErrorOf([&] { cameraFrame(eye, g, up); }).find("target"), std::string::npos);
            t[axis] = bad;
            EXPECT_NE(inputErrorOf([&] { cameraFrame(eye, target, t); }).find("up"), std::string::npos);
        }
    }
}

// Whatever the up vector (any length, nearly parallel), the result is an InputError or a finite orthonormal
// frame: never NaN, never a frame that is only roughly unit length.
TEST(CameraFrame, ReturnsAnOrthonormalFrameOrAnInputErrorForAnyUp) {
    std::mt19937_64 rng(7);
    const glm::dvec3 eye{0.3, -1, 2}, target{0, 0, 0};
    const glm::dvec3 forward = glm::normalize(target - eye);
    for (int i = 0; i < 200; ++i) {
        // Ups within ~1e-8 .. 1e-16 of the view direction and of every scale from 1e-150 to 1e150.
        const double tilt = std::pow(10.0, -8 - 8 * (i % 10) / 9.0);
        const double scale = std::pow(10.0, -150 + 300 * ((i / 10) % 20) / 19.0);
        const glm::dvec3 up = scale * (forward + tilt * randomVector(rng, 1)) * (i % 2 ? 1.0 : -1.0);
        try {
            const CameraFrame f = cameraFrame(eye, target, up);
            SCOPED_TRACE("up " + str(up));
            EXPECT_NEAR(glm::length(f.u), 1, 1e-12);
            EXPECT_NEAR(glm::length(f.v), 1, 1e-12);
            EXPECT_NEAR(glm::dot(f.u, f.v), 0, 1e-12);
            EXPECT_TRUE(allFinite(viewFromWorld(f)));
        } catch (const InputError&) {
        }
    }
}

// ---- projections ----

const ViewVolume kSymmetric{-1, 1, -0.75, 0.75, 0.5, 20};
const ViewVolume kOffCentre{-0.3, 0.7, -0.2, 0.5, 0.1, 100};
const ViewVolume kFarOffCentre{2, 5, -4, -1, 3, 7.5}; // entirely to one side of the axis

TEST(Projection, PerspectiveEqualsFlippedGlmFrustum) {
    const glm::dmat4 flipZ = glm::scale(glm::dmat4(1.0), glm::dvec3(1, 1, -1));
    for (const ViewVolume& vv : {kSymmetric, kOffCentre, kFarOffCentre}) {
        SCOPED_TRACE("l " + std::to_string(vv.left) + " near " + std::to_string(vv.near));
        const glm::dmat4 expected =
            flipZ * glm::frustumRH_NO(vv.left, vv.right, vv.bottom, vv.top, vv.near, vv.far);
        EXPECT_LE(maxAbsDifference(perspectiveClipFromView(vv), expected), 1e-12);
    }
}

// Near → NDC z = +1, far → −1 (the reason for GL_GREATER), w > 0 in front; the near rectangle → [−1, 1]².
TEST(Projection, PerspectiveMapsNearToPlusOneAndFarToMinusOne) {
    for (const ViewVolume& vv : {kSymmetric, kOffCentre, kFarOffCentre}) {
        const glm::dmat4 p = perspectiveClipFromView(vv);
        SCOPED_TRACE("l " + std::to_string(vv.left) + " near " + std::to_string(vv.near));
        const double scale = vv.far / vv.near; // the far rectangle is the near one scaled by far/near
        for (double s : {0.0, 0.25, 1.0}) {
            const double x = vv.left + s * (vv.right - vv.left), y = vv.top - s * (vv.top - vv.bottom);
            const glm::dvec4 nearClip = p * glm::dvec4(x, y, -vv.near, 1);
            const glm::dvec4 farClip = p * glm::dvec4(scale * x, scale * y, -vv.far, 1);
            EXPECT_GT(nearClip.w, 0);
            EXPECT_GT(farClip.w, 0);
            EXPECT_NEAR(nearClip.z / nearClip.w, 1, 1e-12);
            EXPECT_NEAR(farClip.z / farClip.w, -1, 1e-12);
            // x and y land at the same NDC position on both planes.
            EXPECT_NEAR(nearClip.x / nearClip.w, -1 + 2 * s, 1e-12);
            EXPECT_NEAR(nearClip.y / nearClip.w, 1 - 2 * s, 1e-12);
            EXPECT_NEAR(farClip.x / farClip.w, -1 + 2 * s, 1e-12);
            EXPECT_NEAR(farClip.y / farClip.w, 1 - 2 * s, 1e-12);
        }
        // Nearer points get a larger depth: GL_GREATER keeps the nearest.
        double previous = 2;
        for (double z = vv.near; z <= vv.far; z += (vv.far - vv.near) / 16) {
            const glm::dvec4 clip = p * glm::dvec4(0, 0, -z, 1);
            EXPECT_NEAR(clip.w, z, 1e-12 * z); // w = −z
            EXPECT_LT(clip.z / clip.w, previous);
            previous = clip.z / clip.w;
        }
        EXPECT_LT((p * glm::dvec4(0, 0, 1, 1)).w, 0); // behind the camera
    }
}

TEST(Projection, OrthographicMapsTheBoxCornersToTheNdcCube) {
    for (const ViewVolume& vv : {kSymmetric, kOffCentre, kFarOffCentre}) {
        const glm::dmat4 p = orthographicClipFromView(vv);
        SCOPED_TRACE("l " + std::to_string(vv.left) + " near " + std::to_string(vv.near));
        for (int corner = 0; corner < 8; ++corner) {
            const bool right = corner & 1, top = corner & 2, nearPlane = corner & 4;
            const glm::dvec4 view(right ? vv.right : vv.left, top ? vv.top : vv.bottom,
                                  nearPlane ? -vv.near : -vv.far, 1);
            const glm::dvec4 clip = p * view;
            EXPECT_GT(clip.w, 0);
            EXPECT_NEAR(clip.w, 1, 1e-15);
            EXPECT_NEAR(clip.x, right ? 1 : -1, 1e-12) << "corner " << corner;
            EXPECT_NEAR(clip.y, top ? 1 : -1, 1e-12) << "corner " << corner;
            EXPECT_NEAR(clip.z, nearPlane ? 1 : -1, 1e-12) << "corner " << corner;
        }
        // The box centre goes to the NDC origin.
        const glm::dvec4 centre =
            p * glm::dvec4((vv.left + vv.right) / 2, (vv.bottom + vv.top) / 2, -(vv.near + vv.far) / 2, 1);
        EXPECT_NEAR(glm::length(glm::dvec3(centre)), 0, 1e-12);
    }
}

TEST(Projection, ViewVolumeFromFovy) {
    struct Case {
        double fovyDeg, aspect, near, far;
    };
    for (const Case c :
         {Case{60, 1.5, 0.5, 20}, Case{90, 1, 1, 10}, Case{40, 0.25, 0.01, 1e4}, Case{179, 2, 2, 3}}) {
        SCOPED_TRACE("fovy " + std::to_string(c.fovyDeg));
        const ViewVolume vv = viewVolumeFromFovy(c.fovyDeg, c.aspect, c.near, c.far);
        const double top = c.near * std::tan(c.fovyDeg / 2 * std::numbers::pi / 180);
        EXPECT_NEAR(vv.top, top, 1e-14 * top);
        EXPECT_NEAR(vv.bottom, -top, 1e-14 * top);
        EXPECT_NEAR(vv.right, top * c.aspect, 1e-14 * top * c.aspect);
        EXPECT_NEAR(vv.left, -top * c.aspect, 1e-14 * top * c.aspect);
        EXPECT_EQ(vv.near, c.near);
        EXPECT_EQ(vv.far, c.far);
    }
    // 90°: the near rectangle's half-height is the near distance; it matches glm::perspective.
    const ViewVolume vv = viewVolumeFromFovy(90, 1.6, 0.5, 50);
    EXPECT_NEAR(vv.top, 0.5, 1e-15);
    const glm::dmat4 flipZ = glm::scale(glm::dmat4(1.0), glm::dvec3(1, 1, -1));
    EXPECT_LE(maxAbsDifference(perspectiveClipFromView(vv),
                               flipZ * glm::perspectiveRH_NO(glm::radians(90.0), 1.6, 0.5, 50.0)),
              1e-12);
}

// Every bad volume is an InputError naming the offending field, from every entry point — never a NaN matrix.
TEST(Projection, BadViewVolumesAreInputErrorsNamingTheField) {
    struct Case {
        const char* what;
        ViewVolume volume;
        const char* field;
    };
    const ViewVolume ok{-1, 1, -1, 1, 1, 10};
    auto with = [&](double ViewVolume::*member, double value) {
        ViewVolume v = ok;
        v.*member = value;
        return v;
    };
    const std::vector<Case> cases = {
        {"near 0", with(&ViewVolume::near, 0), "near"},
        {"near < 0", with(&ViewVolume::near, -1), "near"},
        {"near == far", with(&ViewVolume::near, 10), "far"},
        {"near > far", with(&ViewVolume::far, 0.5), "far"},
        {"left == right", with(&ViewVolume::left, 1), "left"},
        {"bottom == top", with(&ViewVolume::bottom, 1), "bottom"},
        {"NaN left", with(&ViewVolume::left, kNaN), "left"},
        {"NaN right", with(&ViewVolume::right, kNaN), "right"},
        {"NaN bottom", with(&ViewVolume::bottom, kNaN), "bottom"},
        {"NaN top", with(&ViewVolume::top, kNaN), "top"},
        {"NaN near", with(&ViewVolume::near, kNaN), "near"},
        {"NaN far", with(&ViewVolume::far, kNaN), "far"},
        {"infinite far", with(&ViewVolume::far, kInf), "far"},
        {"-infinite left", with(&ViewVolume::left, -kInf), "left"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        const std::string message = inputErrorOf([&] { validateViewVolume(c.volume); });
        EXPECT_FALSE(message.empty()) << "accepted";
        EXPECT_NE(message.find(c.field), std::string::npos)
            << "\"" << message << "\" does not name " << c.field;
        EXPECT_THROW(perspectiveClipFromView(c.volume), InputError);
        EXPECT_THROW(orthographicClipFromView(c.volume), InputError);
    }
}

TEST(Projection, BadFieldsOfViewAreInputErrorsNamingTheField) {
    for (double fovy : {0.0, 180.0, -30.0, 200.0, kNaN, kInf}) {
        const std::string message = inputErrorOf([&] { viewVolumeFromFovy(fovy, 1, 0.5, 20); });
        EXPECT_NE(message.find("fovy"), std::string::npos) << "fovy " << fovy << ": \"" << message << "\"";
    }
    for (double aspect : {0.0, -1.0, kNaN, kInf}) {
        const std::string message = inputErrorOf([&] { viewVolumeFromFovy(40, aspect, 0.5, 20); });
        EXPECT_NE(message.find("aspect"), std::string::npos)
            << "aspect " << aspect << ": \"" << message << "\"";
    }
    struct Case {
        double near, far;
        const char* field;
    };
    for (const Case c : {Case{0, 20, "near"}, Case{-1, 20, "near"}, Case{5, 5, "far"}, Case{5, 1, "far"},
                         Case{kNaN, 20, "near"}, Case{0.5, kNaN, "far"}}) {
        const std::string message = inputErrorOf([&] { viewVolumeFromFovy(40, 1, c.near, c.far); });
        EXPECT_NE(message.find(c.field), std::string::npos)
            << "near " << c.near << " far " << c.far << ": \"" << message << "\"";
    }
}

// ---- normal matrix ----

// N = s·(M₃⁻¹)ᵀ with s > 0: the best-fit s, then the residual.
void expectPositiveMultipleOfInverseTranspose(const glm::dmat3& n, const glm::dmat3& m3) {
    const glm::dmat3 r = glm::transpose(glm::inverse(m3));
    double nr = 0, rr = 0, nn = 0;
    for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) {
            nr += n[c][k] * r[c][k];
            rr += r[c][k] * r[c][k];
            nn += n[c][k] * n[c][k];
        }
    const double s = nr / rr;
    EXPECT_GT(s, 0) << "the normal matrix flips normals";
    EXPECT_LE(maxAbsDifference(n, s * r), 1e-12 * std::sqrt(nn));
}

TEST(NormalMatrix, IsAPositiveMultipleOfTheInverseTranspose) {
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> entry(-2, 2);
    int negative = 0, tested = 0;
    while (tested < 30) {
        glm::dmat4 m(1.0);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 3; ++r) m[c][r] = entry(rng); // upper 3×3 and translation
        const glm::dmat3 m3(m);
        if (std::abs(glm::determinant(m3)) < 0.1) continue;
        negative += glm::determinant(m3) < 0;
        ++tested;
        SCOPED_TRACE("matrix " + std::to_string(tested));
        const glm::dmat3 n = normalMatrix(m);
        expectPositiveMultipleOfInverseTranspose(n, m3);
        // The translation column is ignored.
        glm::dmat4 moved = m;
        moved[3] = glm::dvec4(100, -50, 7, 1);
        EXPECT_LE(maxAbsDifference(normalMatrix(moved), n), 0.0);
    }
    EXPECT_GT(negative, 0) << "the random set should include mirroring matrices";
}

// N·p stays perpendicular to the transformed surface: for a tangent τ ⟂ p of the unit sphere, (N·p)·(M·τ) =
// 0, and it points away from the transformed centre: (N·p)·(M·p) > 0 — also when M mirrors.
TEST(NormalMatrix, TransformedSphereNormalsArePerpendicularAndOutward) {
    const glm::dmat4 rotateMove = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(3, -2, 5)), 0.7,
                                              glm::normalize(glm::dvec3(1, 2, -1)));
    const std::vector<std::pair<const char*, glm::dmat4>> matrices = {
        {"mirror x", glm::scale(glm::dmat4(1.0), glm::dvec3(-1, 1, 1))},
        {"mirror x·y·z", glm::scale(glm::dmat4(1.0), glm::dvec3(-1, -1, -1))},
        {"ellipsoid", glm::scale(glm::dmat4(1.0), glm::dvec3(3, 1, 0.5))},
        {"mirrored ellipsoid in a view", rotateMove * glm::scale(glm::dmat4(1.0), glm::dvec3(2, -0.5, 1.5))},
        {"shear", glm::dmat4(glm::dvec4(1, 0, 0, 0), glm::dvec4(0.8, 1, 0, 0), glm::dvec4(0, -0.4, 1, 0),
                             glm::dvec4(0, 0, 0, 1))},
    };
    std::mt19937_64 rng(3);
    for (const auto& [name, m] : matrices) {
        SCOPED_TRACE(name);
        const glm::dmat3 n = normalMatrix(m), m3(m);
        for (int i = 0; i < 50; ++i) {
            const glm::dvec3 p = glm::normalize(randomVector(rng, 1));
            const glm::dvec3 tangent = glm::normalize(glm::cross(p, randomVector(rng, 1)));
            const glm::dvec3 normal = glm::normalize(n * p);
            EXPECT_GT(glm::dot(normal, m3 * p), 0) << "p " << str(p);
            EXPECT_NEAR(glm::dot(normal, m3 * tangent), 0, 1e-12) << "p " << str(p);
        }
    }
}

TEST(NormalMatrix, StaysFiniteForNearSingularAndSingularMatrices) {
    const std::vector<std::pair<const char*, glm::dvec3>> scales = {
        {"1e-6", {1e-6, 1, 1}}, {"1e6", {1e6, 1, 1}}, {"1e-12 1e12", {1e-12, 1e12, 1}}};
    for (const auto& [name, s] : scales) {
        SCOPED_TRACE(name);
        const glm::dmat4 m = glm::scale(glm::dmat4(1.0), s);
        const glm::dmat3 n = normalMatrix(m);
        EXPECT_TRUE(allFinite(n));
        expectPositiveMultipleOfInverseTranspose(n, glm::dmat3(m));
        // The flattened sphere's normals point along the squashed axis wherever it is not an edge-on rim.
        const glm::dvec3 p = glm::normalize(glm::dvec3(1, 1, 1));
        EXPECT_LE(glm::length(glm::normalize(n * p) - glm::normalize(p / s)), 1e-12);
    }

    // Exactly singular: a sphere flattened into the x = 0 disc. Its normal is ±x; nothing divides by det = 0.
    const glm::dmat3 flat = normalMatrix(glm::scale(glm::dmat4(1.0), glm::dvec3(0, 1, 1)));
    EXPECT_TRUE(allFinite(flat));
    const glm::dvec3 disc = flat * glm::normalize(glm::dvec3(0.3, 0.5, -0.2));
    EXPECT_GT(glm::length(disc), 0);
    EXPECT_NEAR(std::abs(glm::normalize(disc).x), 1, 1e-15);

    EXPECT_TRUE(allFinite(normalMatrix(glm::dmat4(0.0))));
    glm::dmat4 rankOne(0.0);
    rankOne[0] = glm::dvec4(1, 2, 3, 0);
    rankOne[3][3] = 1;
    EXPECT_TRUE(allFinite(normalMatrix(rankOne)));
}

// normalViewFromObject: the model rule's matrix is M's own 3×3 and the inverse-transpose rule's is (M⁻¹)ᵀ,
// each up to a positive scale that makes its largest entry 1, also for radii of 1e-30 and 1e30. Checked
// against GLM's own inverseTranspose and M itself: for the ellipsoid diag(4, 1, 0.5), the normal at
// p = (1, 1, 1)/√3 goes along (4, 1, 0.5) by M and along (1/4, 1, 2) by (M⁻¹)ᵀ.
TEST(NormalMatrix, EachRuleIsItsMatrixScaledToLargestEntryOne) {
    const glm::dmat4 view = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(3, -2, 5)), 0.7,
                                        glm::normalize(glm::dvec3(1, 2, -1)));
    for (const double radius : {1e-30, 1.0, 1e30}) {
        for (const glm::dvec3 scale : {glm::dvec3(4, 1, 0.5), glm::dvec3(-2, 0.5, 1.5)}) {
            const glm::dmat4 m = view * glm::scale(glm::dmat4(1.0), radius * scale);
            const glm::dmat3 m3(view);
            SCOPED_TRACE("radius " + std::to_string(radius) + ", scale " + str(scale));
            for (const NormalMatrixRule rule : kNormalMatrixRules) {
                const glm::dmat3 n = normalViewFromObject(m, rule);
                EXPECT_TRUE(allFinite(n));
                double largest = 0;
                for (int c = 0; c < 3; ++c)
                    for (int r = 0; r < 3; ++r) largest = std::max(largest, std::abs(n[c][r]));
                EXPECT_NEAR(largest, 1, 1e-15) << toString(rule);
                const glm::dvec3 p = glm::normalize(glm::dvec3(1, 1, 1));
                // Independently: M·p, or (M⁻¹)ᵀ·p from GLM at the unit radius (the direction is radius-free).
                const glm::dmat3 unitM = m3 * glm::dmat3(glm::scale(glm::dmat4(1.0), scale));
                const glm::dvec3 expected =
                    rule == NormalMatrixRule::Model ? unitM * p : glm::inverseTranspose(unitM) * p;
                EXPECT_LE(glm::length(glm::normalize(n * p) - glm::normalize(expected)), 1e-12)
                    << toString(rule) << ": " << str(glm::normalize(n * p)) << " against "
                    << str(glm::normalize(expected));
            }
            // The two rules differ under this uneven scale (the lesson's whole point).
            const glm::dvec3 p = glm::normalize(glm::dvec3(1, 1, 1));
            EXPECT_GT(
                glm::length(glm::normalize(normalViewFromObject(m, NormalMatrixRule::Model) * p) -
                            glm::normalize(normalViewFromObject(m, NormalMatrixRule::InverseTranspose) * p)),
                0.5);
        }
    }
}

} // namespace
} // namespace shadelab
