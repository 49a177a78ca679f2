#include "shadelab/exact/reference.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <thread>

#include "shadelab/errors.h"
#include "shadelab/exact/ray_cast.h"
#include "shadelab/shading/lighting.h"

namespace shadelab {
namespace {

void writePixel(float* pixel, const glm::dvec3& color, float alpha) {
    pixel[0] = float(color.x);
    pixel[1] = float(color.y);
    pixel[2] = float(color.z);
    pixel[3] = alpha;
}

} // namespace

ReferenceImage renderReference(const Scene& scene) {
    validateScene(scene);
    const SceneView view = sceneView(scene);
    // With the far plane at infinity the rasterizer clips nothing behind; neither does the reference.
    const double far = scene.depth == DepthMode::ReversedInfinite ? std::numeric_limits<double>::infinity()
                                                                  : view.volume.far;

    std::vector<ObjectInView> objects;
    objects.reserve(scene.objects.size());
    for (const SceneObject& object : scene.objects)
        objects.push_back(prepareObjectForCasting(object, view.viewFromWorld, scene.normalMatrix));
    std::vector<Light> lightsView;
    lightsView.reserve(scene.lights.size());
    for (const Light& light : scene.lights) lightsView.push_back(transformLight(light, view.viewFromWorld));
    const ShadeOptions options{scene.lighting, scene.shading == ShadingMode::Toon, scene.toonBands,
                               scene.term};
    const PixelRays rays{view.volume, view.orthographic, scene.width, scene.height};
    const glm::dvec3 background = clampColor(scene.background);

    ReferenceImage out{ImageF(scene.width, scene.height),
                       std::vector<int>(std::size_t(scene.width) * std::size_t(scene.height), -1)};

    auto renderRow = [&](int j) {
        for (int i = 0; i < scene.width; ++i) {
            glm::dvec3 originView, directionView;
            rays.ray(i + 0.5, j + 0.5, originView, directionView);
            RayHit hit;
            for (std::size_t k = 0; k < objects.size(); ++k)
                intersectObject(objects[k], int(k), originView, directionView, view.volume.near, far, hit);

            float* pixel = out.color.pixel(i, j);
            if (hit.object < 0) {
                writePixel(pixel, background, 0);
                continue;
            }
            const SurfacePoint point = exactSurfacePoint(objects[std::size_t(hit.object)], hit, originView,
                                                         directionView, rays.orthographic);
            if (!view.passesW(point.position)) { // clipped (the unnegated perspective matrix)
                writePixel(pixel, background, 0);
                continue;
            }
            const glm::dvec3 color = clampColor(
                shade(point, scene.objects[std::size_t(hit.object)].material, lightsView, options));
            writePixel(pixel, color, 1);
            out.objectId[std::size_t(j) * std::size_t(scene.width) + std::size_t(i)] = hit.object;
        }
    };

    // Rows are dealt out round-robin (cheap load balance: the objects sit mid-image); each thread writes
    // only its own rows, so the result does not depend on the thread count.
    const int threadCount =
        std::clamp(int(std::thread::hardware_concurrency()), 1, std::max(1, scene.height));
    {
        std::vector<std::jthread> threads;
        threads.reserve(std::size_t(threadCount));
        for (int first = 0; first < threadCount; ++first)
            threads.emplace_back([&, first] {
                for (int j = first; j < scene.height; j += threadCount) renderRow(j);
            });
    } // jthreads join here
    return out;
}

std::vector<bool> interiorMask(const std::vector<int>& ids, int width, int height, int radius) {
    if (width < 0 || height < 0 || ids.size() != std::size_t(width) * std::size_t(height))
        throw InputError("interiorMask: " + std::to_string(ids.size()) + " ids for a " +
                         std::to_string(width) + "×" + std::to_string(height) + " image");
    if (radius < 0) throw InputError("interiorMask: radius must be >= 0, got " + std::to_string(radius));
    const auto at = [width](int x, int y) { return std::size_t(y) * std::size_t(width) + std::size_t(x); };

    // Erosion by a (2r+1)² square is separable, done with runs in O(w·h) whatever the radius. Outside the
    // image counts as a different id, so pixels within `radius` of the border are never interior.
    // Pass 1: row[p] — the 2r+1 pixels centred on p in its row exist and all carry p's id (>= 0).
    std::vector<bool> row(ids.size(), false);
    for (int y = 0; y < height; ++y) {
        for (int start = 0; start < width;) {
            int end = start + 1; // the run of equal ids is [start, end)
            while (end < width && ids[at(end, y)] == ids[at(start, y)]) ++end;
            if (ids[at(start, y)] >= 0)
                for (int x = start + radius; x < end - radius; ++x) row[at(x, y)] = true;
            start = end;
        }
    }
    // Pass 2: interior — the 2r+1 pixels centred on p in its column all pass pass 1 with p's id.
    std::vector<bool> interior(ids.size(), false);
    for (int x = 0; x < width; ++x) {
        for (int start = 0; start < height;) {
            const int id = ids[at(x, start)];
            const bool passes = row[at(x, start)];
            int end = start + 1;
            while (end < height && row[at(x, end)] == passes && (!passes || ids[at(x, end)] == id)) ++end;
            if (passes)
                for (int y = start + radius; y < end - radius; ++y) interior[at(x, y)] = true;
            start = end;
        }
    }
    return interior;
}

std::vector<bool> sharedInterior(const ImageF& rendered, const ReferenceImage& reference, int erode) {
    const int w = reference.color.width, h = reference.color.height;
    if (rendered.width != w || rendered.height != h)
        throw InputError("the render is " + std::to_string(rendered.width) + "x" +
                         std::to_string(rendered.height) + " but the reference " + std::to_string(w) + "x" +
                         std::to_string(h));
    std::vector<int> renderedIds(reference.objectId.size(), -1);
    for (std::size_t i = 0; i < renderedIds.size(); ++i)
        if (rendered.rgba[4 * i + 3] > 0.5f) renderedIds[i] = reference.objectId[i];
    std::vector<bool> interior = interiorMask(reference.objectId, w, h, erode);
    const std::vector<bool> inRendered = interiorMask(renderedIds, w, h, erode);
    for (std::size_t i = 0; i < interior.size(); ++i) interior[i] = interior[i] && inRendered[i];
    return interior;
}

namespace {

// 255·|Δ| of each colour channel of pixel i: a NaN stays NaN.
std::array<double, 3> channelErrors(const ImageF& rendered, const ReferenceImage& reference, std::size_t i) {
    std::array<double, 3> errors{};
    for (std::size_t c = 0; c < 3; ++c)
        errors[c] =
            255.0 * std::abs(double(rendered.rgba[4 * i + c]) - double(reference.color.rgba[4 * i + c]));
    return errors;
}

// max that keeps a NaN of either side.
double maxKeepingNan(double a, double b) {
    return std::isnan(a) || std::isnan(b) ? std::numeric_limits<double>::quiet_NaN() : std::max(a, b);
}

} // namespace

InteriorError interiorError(const ImageF& rendered, const ReferenceImage& reference, int erode) {
    const std::vector<bool> interior = sharedInterior(rendered, reference, erode);
    InteriorError error;
    double sum = 0;
    for (std::size_t i = 0; i < interior.size(); ++i) {
        if (!interior[i]) continue;
        for (const double e : channelErrors(rendered, reference, i)) {
            sum += e;
            error.max = maxKeepingNan(error.max, e);
        }
        ++error.pixels;
    }
    error.mean = error.pixels ? sum / (3.0 * double(error.pixels)) : 0;
    return error;
}

std::vector<double> interiorPixelErrors(const ImageF& rendered, const ReferenceImage& reference, int erode) {
    const std::vector<bool> interior = sharedInterior(rendered, reference, erode);
    std::vector<double> errors;
    for (std::size_t i = 0; i < interior.size(); ++i) {
        if (!interior[i]) continue;
        double largest = 0;
        for (const double e : channelErrors(rendered, reference, i)) largest = maxKeepingNan(largest, e);
        errors.push_back(largest);
    }
    return errors;
}

} // namespace shadelab
