// The error figures of a report row against the analytic reference: the render's interior error, PSNR and
// SSIM (measureError) and the mesh's worst face normal (maxFaceNormalErrorDeg). CPU functions of an image
// or a mesh, no GL: the GL tests hold the error view to the same measure.
#include "app/report/report.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "shadelab/errors.h"

namespace shadelab::app {

namespace {

// Clamped to [0, 1]; NaN → 0.
double unit(float v) {
    return v > 0 ? (v < 1 ? v : 1) : 0;
}

std::vector<double> luminance(const float* rgba, std::size_t pixels) {
    std::vector<double> y(pixels);
    for (std::size_t i = 0; i < pixels; ++i)
        y[i] = 0.2126 * unit(rgba[4 * i]) + 0.7152 * unit(rgba[4 * i + 1]) + 0.0722 * unit(rgba[4 * i + 2]);
    return y;
}

// Separable Gaussian blur, σ = 1.5 px, 11 taps; where the window leaves the image its weights are
// renormalized over the part inside (separable, so the 2-D window is renormalized too).
std::vector<double> gaussianBlur(const std::vector<double>& in, int w, int h) {
    constexpr int kRadius = 5;
    constexpr double kSigma = 1.5;
    std::array<double, 2 * kRadius + 1> weight{};
    for (std::size_t i = 0; i < weight.size(); ++i) {
        const double k = double(i) - kRadius;
        weight[i] = std::exp(-k * k / (2 * kSigma * kSigma));
    }
    auto pass = [&](const std::vector<double>& src, bool horizontal) {
        std::vector<double> dst(src.size());
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                double sum = 0, norm = 0;
                for (std::size_t i = 0; i < weight.size(); ++i) {
                    const int k = int(i) - kRadius;
                    const int sx = horizontal ? x + k : x, sy = horizontal ? y : y + k;
                    if (sx < 0 || sx >= w || sy < 0 || sy >= h) continue;
                    const double wk = weight[i];
                    sum += wk * src[std::size_t(sy) * w + sx];
                    norm += wk;
                }
                dst[std::size_t(y) * w + x] = sum / norm;
            }
        return dst;
    };
    return pass(pass(in, true), false);
}

double meanSsim(const std::vector<double>& a, const std::vector<double>& b, int w, int h) {
    constexpr double kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03; // (K·L)² with L = 1
    std::vector<double> aa(a.size()), bb(a.size()), ab(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        aa[i] = a[i] * a[i];
        bb[i] = b[i] * b[i];
        ab[i] = a[i] * b[i];
    }
    const auto muA = gaussianBlur(a, w, h), muB = gaussianBlur(b, w, h);
    const auto eAA = gaussianBlur(aa, w, h), eBB = gaussianBlur(bb, w, h), eAB = gaussianBlur(ab, w, h);
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double varA = eAA[i] - muA[i] * muA[i], varB = eBB[i] - muB[i] * muB[i];
        const double cov = eAB[i] - muA[i] * muB[i];
        sum += ((2 * muA[i] * muB[i] + kC1) * (2 * cov + kC2)) /
               ((muA[i] * muA[i] + muB[i] * muB[i] + kC1) * (varA + varB + kC2));
    }
    return a.empty() ? 1 : sum / double(a.size());
}

} // namespace

ReportError measureError(const ImageF& rendered, const ReferenceImage& reference) {
    const int w = reference.color.width, h = reference.color.height;
    if (rendered.width != w || rendered.height != h)
        throw RuntimeError("report: the render is " + std::to_string(rendered.width) + "x" +
                           std::to_string(rendered.height) + " but the reference " + std::to_string(w) + "x" +
                           std::to_string(h));
    const std::size_t pixels = std::size_t(w) * std::size_t(h);
    ReportError e;
    for (std::size_t i = 0; i < pixels; ++i)
        if ((rendered.rgba[4 * i + 3] > 0.5f) != (reference.objectId[i] >= 0)) ++e.coverageMismatch;
    const InteriorError interior = interiorError(rendered, reference, 2); // DESIGN §6: eroded by 2 px
    e.interiorMean = interior.mean;
    e.interiorMax = interior.max;
    e.interiorPixels = interior.pixels;
    double squaredSum = 0;
    for (std::size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c) {
            const double d = unit(rendered.rgba[4 * i + c]) - unit(reference.color.rgba[4 * i + c]);
            squaredSum += d * d;
        }
    const double mse = pixels ? squaredSum / (3.0 * double(pixels)) : 0;
    e.psnrDb = mse > 0 ? std::min(kMaxPsnrDb, -10 * std::log10(mse)) : kMaxPsnrDb;
    e.ssim = meanSsim(luminance(rendered.rgba.data(), pixels), luminance(reference.color.rgba.data(), pixels),
                      w, h);
    return e;
}

double maxFaceNormalErrorDeg(const SphereMesh& mesh) {
    double worst = 0;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3& t = mesh.triangles[i];
        const glm::dvec3 centroid = mesh.positions[t.x] + mesh.positions[t.y] + mesh.positions[t.z];
        const glm::dvec3& n = mesh.faceNormals[i];
        // atan2 keeps its precision at tiny angles, where acos(dot) would round to 0.
        worst = std::max(worst, std::atan2(glm::length(glm::cross(n, centroid)), glm::dot(n, centroid)));
    }
    return worst * 180 / std::numbers::pi;
}

double maxFaceNormalErrorDeg(const TeapotMesh& mesh) {
    double worst = 0;
    const auto& patches = teapotPatches();
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3& t = mesh.triangles[i];
        // The corners of a triangle share their patch; their (u, v) average is the centroid's parameters.
        const glm::dvec3 uv = (mesh.patchUv[t.x] + mesh.patchUv[t.y] + mesh.patchUv[t.z]) / 3.0;
        const glm::dvec3 exact = patchNormal(patches[std::size_t(mesh.patchUv[t.x].x)], uv.y, uv.z);
        const glm::dvec3& n = mesh.faceNormals[i];
        worst = std::max(worst, std::atan2(glm::length(glm::cross(n, exact)), glm::dot(n, exact)));
    }
    return worst * 180 / std::numbers::pi;
}

} // namespace shadelab::app
