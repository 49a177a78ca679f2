#include "gl/gl_test_support.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "shadelab/diagram/outside_view.h"
#include "shadelab/errors.h"

namespace shadelab::test {

ContextRequest contextUnderTest() {
    const char* name = std::getenv("SHADELAB_TEST_BACKEND");
    if (!name) return {};
    if (std::string_view(name) == "gles") return {Backend::Egl, Api::Gles, std::nullopt};
    const auto backend = parseBackend(name);
    if (!backend) throw InputError(std::string("SHADELAB_TEST_BACKEND: unknown backend ") + name);
    return {*backend, Api::Gl, std::nullopt};
}

HeadlessRenderer* glRenderer(std::string& why) {
    static std::unique_ptr<HeadlessRenderer> renderer;
    static std::string failure;
    if (!renderer && failure.empty()) {
        try {
            renderer = std::make_unique<HeadlessRenderer>(contextUnderTest());
        } catch (const std::exception& e) {
            failure = e.what();
        }
    }
    why = failure;
    return renderer.get();
}

double silhouetteShiftPx(const ImageF& image, const ReferenceImage& reference) {
    const int w = image.width, h = image.height;
    auto refCovered = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < w && y < h && reference.objectId[std::size_t(y) * w + x] >= 0;
    };
    std::size_t differing = 0, edge = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            differing += (image.pixel(x, y)[3] > 0.5f) != refCovered(x, y);
            edge += refCovered(x, y) && !(refCovered(x - 1, y) && refCovered(x + 1, y) &&
                                          refCovered(x, y - 1) && refCovered(x, y + 1));
        }
    return edge ? double(differing) / double(edge) : double(differing);
}

std::size_t interiorPixelsOver(const ImageF& rendered, const ReferenceImage& reference, double limit255) {
    const std::vector<bool> interior = sharedInterior(rendered, reference);
    std::size_t over = 0;
    for (std::size_t i = 0; i < interior.size(); ++i) {
        if (!interior[i]) continue;
        for (int c = 0; c < 3; ++c)
            if (std::abs(rendered.rgba[i * 4 + c] - reference.color.rgba[i * 4 + c]) * 255 > limit255) {
                ++over;
                break;
            }
    }
    return over;
}

Scene litSphereScene(int size, LightType type) {
    Scene scene;
    scene.width = scene.height = size;
    Light light;
    light.type = type;
    light.ambient = {0.1, 0.1, 0.1};
    light.diffuse = {1, 1, 1};
    light.specular = {1, 1, 1};
    light.position = {2, 2, 3};
    light.direction = {-2, -2, -3};
    if (type == LightType::Ambient) light.ambient = {0.6, 0.6, 0.6};
    if (type == LightType::Point || type == LightType::Spot) light.attenuation = {0.6, 0.05, 0.01};
    if (type == LightType::Spot) {
        light.cutoffDeg = 12;
        light.exponent = 8;
    }
    scene.lights = {light};
    return scene;
}

static Scene withObjects(Scene scene, std::vector<SceneObject> objects) {
    scene.objects = std::move(objects);
    return scene;
}

const AnalyticCase& analyticCase(std::string_view name) {
    for (const AnalyticCase& c : analyticCases())
        if (name == c.name) return c;
    throw std::logic_error("no analytic case " + std::string(name));
}

const std::vector<AnalyticCase>& analyticCases() {
    static const std::vector<AnalyticCase> cases = {
        {"perspective_point", [] { return litSphereScene(256, LightType::Point); }},
        {"directional", [] { return litSphereScene(256, LightType::Directional); }},
        {"spot", [] { return litSphereScene(256, LightType::Spot); }},
        {"ambient_only", [] { return litSphereScene(256, LightType::Ambient); }},
        {"off_centre_frustum",
         [] {
             Scene s = litSphereScene(256, LightType::Point);
             s.projection = {ProjectionType::Frustum, 40, -0.05, 0.2, -0.15, 0.1, 0.5, 20};
             return s;
         }},
        {"orthographic",
         [] {
             Scene s = litSphereScene(256, LightType::Point);
             s.projection = {ProjectionType::Orthographic, 40, -1.4, 1.4, -1.4, 1.4, 0.5, 20};
             return s;
         }},
        {"ellipsoid",
         [] {
             SceneObject o;
             o.scale = {1.3, 0.7, 0.9};
             return withObjects(litSphereScene(256, LightType::Point), {o});
         }},
        {"two_overlapping_spheres",
         [] {
             SceneObject a, b;
             a.center = {-0.45, 0, 0.5};
             a.radius = 0.7;
             b.center = {0.45, 0.1, -0.4};
             b.material.diffuse = {0.2, 0.3, 0.8};
             return withObjects(litSphereScene(256, LightType::Point), {a, b});
         }},
    };
    return cases;
}

Scene scaledSphereScene(int size, double r) {
    Scene scene = litSphereScene(size, LightType::Point);
    scene.objects[0].radius = r;
    scene.eye *= r;
    scene.target *= r;
    scene.projection.near *= r;
    scene.projection.far *= r;
    Light& light = scene.lights[0];
    light.position *= r;
    light.attenuation = {light.attenuation.x, light.attenuation.y / r, light.attenuation.z / (r * r)};
    return scene;
}

std::vector<Scene> modeScenes(int size, int level) {
    std::vector<Scene> scenes;
    for (ShadingMode mode : kShadingModes)
        for (LightingModel model : kLightingModels) {
            Scene scene = litSphereScene(size, LightType::Spot);
            scene.lights.push_back(litSphereScene(size, LightType::Point).lights[0]);
            scene.objects[0].subdivisions = level;
            scene.shading = mode;
            scene.lighting = model;
            scenes.push_back(scene);
        }
    return scenes;
}

glm::dmat4 webGlClipFromView(const Scene& scene) {
    const Projection& p = scene.projection;
    const glm::dmat4 flipZ = glm::scale(glm::dmat4(1), glm::dvec3(1, 1, -1));
    if (p.type == ProjectionType::Orthographic)
        return flipZ * glm::orthoRH_NO(p.left, p.right, p.bottom, p.top, p.near, p.far);
    if (p.type == ProjectionType::Frustum)
        return flipZ * glm::frustumRH_NO(p.left, p.right, p.bottom, p.top, p.near, p.far);
    return flipZ *
           glm::perspectiveRH_NO(glm::radians(p.fovyDeg), double(scene.width) / scene.height, p.near, p.far);
}

std::vector<std::string> outsideCornerMisses(const Image& image, const Scene& scene) {
    const glm::dmat4 worldFromClip =
        glm::inverse(webGlClipFromView(scene) * glm::lookAt(scene.eye, scene.target, scene.up));
    const Scene observer = observerScene(scene);
    const glm::dmat4 observerClipFromWorld =
        webGlClipFromView(observer) * glm::lookAt(observer.eye, observer.target, observer.up);
    std::array<glm::dvec2, 8> pixel; // continuous pixel coordinates from the top left
    for (int i = 0; i < 8; ++i) {
        glm::dvec4 world = worldFromClip * glm::dvec4(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1, 1);
        const glm::dvec4 clip = observerClipFromWorld * glm::dvec4(glm::dvec3(world) / world.w, 1);
        pixel[std::size_t(i)] = {(clip.x / clip.w + 1) / 2 * image.width,
                                 (1 - clip.y / clip.w) / 2 * image.height};
    }
    const glm::vec3 colour = leavesOutTheMinusOne(scene) ? kClippedVolumeColor : kVolumeEdgeColor;
    const glm::ivec3 expected(glm::round(colour * 255.0f));
    auto isEdge = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= image.width || y >= image.height) return false;
        const std::size_t k = (std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4;
        for (int c = 0; c < 3; ++c)
            if (std::abs(int(image.rgba[k + std::size_t(c)]) - expected[c]) > 2) return false;
        return true;
    };
    auto edgeNear = [&](glm::dvec2 p) {
        const int x = int(std::floor(p.x)), y = int(std::floor(p.y));
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if (isEdge(x + dx, y + dy)) return true;
        return false;
    };
    std::vector<std::string> misses;
    auto miss = [&](int corner, const std::string& what, glm::dvec2 p) {
        char text[160];
        std::snprintf(text, sizeof text, "corner %d at (%.1f, %.1f): %s (checked at (%.1f, %.1f))", corner,
                      pixel[std::size_t(corner)].x, pixel[std::size_t(corner)].y, what.c_str(), p.x, p.y);
        misses.emplace_back(text);
    };
    for (int i = 0; i < 8; ++i) {
        const glm::dvec2 at = pixel[std::size_t(i)];
        if (!edgeNear(at)) miss(i, "no edge pixel within 1 px of the corner", at);
        std::vector<glm::dvec2> directions;
        for (int bit : {1, 2, 4}) {
            const glm::dvec2 along = pixel[std::size_t(i ^ bit)] - at;
            if (glm::length(along) >= 12) directions.push_back(glm::normalize(along));
        }
        for (const glm::dvec2& d : directions) {
            if (!edgeNear(at + 4.0 * d)) miss(i, "no edge pixel 4 px along an edge", at + 4.0 * d);
            // Past the corner nothing of the volume's colour, where the other edges leave at 30° or more.
            bool clear = true;
            for (const glm::dvec2& other : directions)
                if (&other != &d && glm::dot(-d, other) > std::cos(glm::radians(30.0))) clear = false;
            const glm::dvec2 past = at - 3.0 * d;
            if (clear && isEdge(int(std::floor(past.x)), int(std::floor(past.y))))
                miss(i, "an edge pixel 3 px past the corner: the drawn corner lies beyond it", past);
        }
    }
    return misses;
}

} // namespace shadelab::test
