#include "shadelab/exact/probe.h"

#include <algorithm>
#include <array>
#include <limits>
#include <string>

#include "shadelab/errors.h"
#include "shadelab/exact/ray_cast.h"

namespace shadelab {
namespace {

// The triangle whose cone from the centre holds `u` (the mesh is star-shaped around its centre: every
// direction meets exactly one triangle, or an edge shared by two), and u's barycentric coordinates on it.
std::pair<std::size_t, glm::dvec3> triangleUnder(const SphereMesh& mesh, const glm::dvec3& u) {
    std::size_t best = 0;
    glm::dvec3 bestWeights(1.0 / 3);
    double bestInside = -std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::uvec3 tri = mesh.triangles[t];
        const glm::dvec3 &a = mesh.positions[tri.x], &b = mesh.positions[tri.y], &c = mesh.positions[tri.z];
        if (glm::dot(u, mesh.faceNormals[t]) <= 0) continue;
        // Signed volumes: all >= 0 inside the cone (counter-clockwise seen from outside).
        const double wa = glm::dot(u, glm::cross(b, c)), wb = glm::dot(u, glm::cross(c, a)),
                     wc = glm::dot(u, glm::cross(a, b));
        const double inside = std::min({wa, wb, wc}); // the most inside wins a tie on a shared edge
        if (inside > bestInside) {
            bestInside = inside;
            best = t;
            bestWeights = glm::dvec3(wa, wb, wc) / (wa + wb + wc); // projective: the point on the plane
        }
        if (inside >= 0) break;
    }
    return {best, bestWeights};
}

struct ObjectFrame {
    glm::dmat4 viewFromObject;
    ObjectInView prepared; // its normal matrix, rescaled to O(1)

    glm::dvec3 positionView(const glm::dvec3& pointObject) const {
        return glm::dvec3(viewFromObject * glm::dvec4(pointObject, 1.0));
    }
    glm::dvec3 normalView(const glm::dvec3& normalObject) const {
        return safeNormalize(prepared.normalViewFromObject * normalObject, glm::dvec3(0, 0, 1));
    }
};

ProbeSample sampleAt(const SurfacePoint& point, const Material& material,
                     const std::vector<Light>& lightsView, int light, const ShadeOptions& options) {
    ProbeSample sample{point, shadeTerms(point, material, lightsView, options), {}, {}, {}};
    sample.color = clampColor(sample.terms.of(options.term)); // what is drawn: the sum, or the term shown
    if (light >= 0) {
        sample.toLight = toLight(lightsView[std::size_t(light)], point).first;
        sample.specularVector = specularVector(point, sample.toLight, options.model);
    }
    return sample;
}

} // namespace

std::optional<ProbePoint> pickSurfacePoint(const Scene& scene, double x, double y) {
    const SceneView view = sceneView(scene);
    const double far = scene.depth == DepthMode::ReversedInfinite ? std::numeric_limits<double>::infinity()
                                                                  : view.volume.far;
    const PixelRays rays{view.volume, view.orthographic, scene.width, scene.height};
    glm::dvec3 originView, directionView;
    rays.ray(x, y, originView, directionView);
    RayHit hit;
    for (std::size_t k = 0; k < scene.objects.size(); ++k)
        intersectObject(prepareObjectForCasting(scene.objects[k], view.viewFromWorld, scene.normalMatrix),
                        int(k), originView, directionView, view.volume.near, far, hit);
    if (hit.object < 0 || !view.passesW(originView + hit.s * directionView)) return std::nullopt; // as drawn
    // A probe point is a direction from a sphere's centre (ProbePoint): the teapot and meshes, which it
    // cannot pin, hide what lies behind them but give no probe.
    if (scene.objects[std::size_t(hit.object)].shape != Shape::Sphere) return std::nullopt;
    return ProbePoint{std::size_t(hit.object), unitDirection(hit.pointObject)};
}

namespace {

// The normal-matrix argument at the unit sphere's point u of `object` (NormalMatrixArgument).
NormalMatrixArgument normalMatrixArgument(const SceneObject& object, const glm::dmat4& viewFromObject,
                                          const glm::dvec3& u) {
    NormalMatrixArgument a;
    const glm::dvec3 scale = glm::abs(object.scale);
    a.unevenScale = scale.x != scale.y || scale.y != scale.z;
    // The most stretched axis first; the next one where u lies along it (no tangent part).
    int axes[3] = {0, 1, 2};
    std::sort(axes, axes + 3, [&](int i, int j) { return scale[i] > scale[j]; });
    for (const int axis : axes) {
        glm::dvec3 e(0.0);
        e[axis] = 1;
        const glm::dvec3 tangent = e - glm::dot(e, u) * u;
        if (glm::length(tangent) > 1e-3) {
            a.tangentObject = glm::normalize(tangent);
            break;
        }
    }
    const glm::dmat3 m(viewFromObject);
    a.tangentByM = safeNormalize(m * a.tangentObject, glm::dvec3(1, 0, 0));
    a.normalByM = safeNormalize(m * u, glm::dvec3(0, 0, 1));
    a.normalByInverseTranspose = safeNormalize(
        normalViewFromObject(viewFromObject, NormalMatrixRule::InverseTranspose) * u, glm::dvec3(0, 0, 1));
    return a;
}

} // namespace

ProbeReport probeSurface(const Scene& scene, const ProbePoint& point, const SphereMesh& mesh) {
    if (point.object >= scene.objects.size())
        throw InputError("probe: object " + std::to_string(point.object) + " of a scene with " +
                         std::to_string(scene.objects.size()) + " objects");
    const SceneObject& object = scene.objects[point.object];
    if (object.shape != Shape::Sphere)
        throw InputError("probe: object " + std::to_string(point.object) + " is a " +
                         std::string(toString(object.shape)) + ": no probe for this shape (spheres only)");
    const SceneView view = sceneView(scene);
    const ObjectFrame frame{view.viewFromWorld * worldFromObject(object),
                            prepareObject(object, view.viewFromWorld, scene.normalMatrix)};
    std::vector<Light> lightsView;
    int light = -1;
    for (const Light& l : scene.lights) {
        if (light < 0 && l.type != LightType::Ambient) light = int(lightsView.size());
        lightsView.push_back(transformLight(l, view.viewFromWorld));
    }
    const ShadeOptions options{scene.lighting, scene.shading == ShadingMode::Toon, scene.toonBands,
                               scene.term};
    auto surface = [&](const glm::dvec3& positionObject, const glm::dvec3& normalObject) {
        const glm::dvec3 p = frame.positionView(positionObject);
        const glm::dvec3 n = frame.normalView(normalObject);
        return SurfacePoint{p, n, toViewer(p, n, view.orthographic)};
    };

    ProbeReport report;
    report.point = point;
    report.level = mesh.level;
    report.light = light;
    const glm::dvec3 u = unitDirection(point.directionObject);
    report.exact = sampleAt(surface(u, u), object.material, lightsView, light, options);
    report.normalMatrix = normalMatrixArgument(object, frame.viewFromObject, u);

    const auto [t, w] = triangleUnder(mesh, u);
    report.triangle = t;
    report.barycentric = w;
    const glm::uvec3 tri = mesh.triangles[t];
    const std::array<glm::dvec3, 3> corners = {mesh.positions[tri.x], mesh.positions[tri.y],
                                               mesh.positions[tri.z]};
    const std::array<glm::dvec3, 3> normals = {mesh.vertexNormals[tri.x], mesh.vertexNormals[tri.y],
                                               mesh.vertexNormals[tri.z]};
    const glm::dvec3 meshPoint = w.x * corners[0] + w.y * corners[1] + w.z * corners[2];
    // Interpolating the object-space normal and then transforming it is the same linear map as the
    // rasterizer interpolating the transformed one; both are normalized afterwards.
    const glm::dvec3 interpolatedNormal = w.x * normals[0] + w.y * normals[1] + w.z * normals[2];

    switch (scene.shading) {
    case ShadingMode::Flat: {
        const glm::dvec3 centroid = (corners[0] + corners[1] + corners[2]) / 3.0;
        report.mode =
            sampleAt(surface(centroid, mesh.faceNormals[t]), object.material, lightsView, light, options);
        break;
    }
    case ShadingMode::Gouraud: {
        report.mode =
            sampleAt(surface(meshPoint, interpolatedNormal), object.material, lightsView, light, options);
        LightTerms terms;
        glm::dvec3 color(0.0);
        for (int i = 0; i < 3; ++i) {
            const LightTerms atVertex = shadeTerms(surface(corners[std::size_t(i)], normals[std::size_t(i)]),
                                                   object.material, lightsView, options);
            terms.ambient += w[i] * atVertex.ambient;
            terms.diffuse += w[i] * atVertex.diffuse;
            terms.specular += w[i] * atVertex.specular;
            color += w[i] * clampColor(atVertex.of(options.term)); // clamped per vertex, then interpolated
        }
        report.mode.terms = terms;
        report.mode.color = color;
        break;
    }
    case ShadingMode::Phong:
    case ShadingMode::Toon:
        report.mode =
            sampleAt(surface(meshPoint, interpolatedNormal), object.material, lightsView, light, options);
        break;
    case ShadingMode::Exact: // the ray-cast sphere itself: no mesh between it and the exact value
        report.mode = report.exact;
        break;
    }
    return report;
}

} // namespace shadelab
