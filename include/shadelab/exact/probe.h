// The demo's probe (click a surface point): the point shaded the way the current shading mode shades it and
// exactly, term by term (DESIGN §3), with the vectors l, n, v and r or h the equation uses there. Pure CPU
// code in double, the same lighting code as the analytic reference; the window and the page show it.
#pragma once

#include <cstddef>
#include <optional>

#include <glm/glm.hpp>

#include "shadelab/geometry/sphere.h"
#include "shadelab/scene/scene.h"
#include "shadelab/shading/lighting.h"

namespace shadelab {

// A point pinned to an object's surface, so that it stays put while the view orbits or the level changes:
// a unit direction from the object's centre in object space. The exact point is that direction on the
// unit sphere; the mesh point is where the ray from the centre along it meets the mesh.
struct ProbePoint {
    std::size_t object = 0;
    glm::dvec3 directionObject{0, 0, 1};
    bool operator==(const ProbePoint&) const = default;
};

// The surface point that pixel position (x, y) of the scene's image sees (pixel (i, j)'s centre is
// (i + 0.5, j + 0.5), top row first): the nearest exact object on the ray, as the analytic reference casts
// it. nullopt on the background, and where the nearest object is a teapot or a mesh (no probe for those
// shapes: a ProbePoint is a direction from a sphere's centre).
std::optional<ProbePoint> pickSurfacePoint(const Scene& scene, double x, double y);

// One way of shading the probed point, all vectors in view space.
struct ProbeSample {
    // Where the lighting is evaluated and with which normal: flat, the triangle's centroid and face normal;
    // Gouraud, Phong and toon, the mesh point with the interpolated vertex normal; exact, the sphere's point
    // and its exact normal.
    SurfacePoint pointView;
    LightTerms terms; // unclamped; Gouraud: the three vertices' terms interpolated, as the rasterizer does
    glm::dvec3 color; // what reaches the pixel: the sum, or the scene's term alone (the demo's K), clamped
                      // (Gouraud: the clamped vertex colours interpolated)
    // For the first light that is not ambient: l, and r (Phong lighting) or h (Blinn-Phong); 0 without one.
    glm::dvec3 toLight{0.0}, specularVector{0.0};
    bool operator==(const ProbeSample&) const = default;
};

// The lecture's argument for the normal matrix at the probed point, at the exact point, in view space (unit
// vectors): a tangent t of the unit sphere there (along the object axis M stretches most, projected into
// the tangent plane: n·t = 0), M·t tangent to the drawn surface, and the normal taken both ways: M·n, which
// stays perpendicular to M·t only under rotations and uniform scales, and (M⁻¹)ᵀ·n, which always does
// ((M⁻¹)ᵀn)·(Mt) = nᵀM⁻¹Mt = n·t = 0 (DESIGN §2).
struct NormalMatrixArgument {
    glm::dvec3 tangentObject{0.0};                                             // t, in object space
    glm::dvec3 tangentByM{0.0}, normalByM{0.0}, normalByInverseTranspose{0.0}; // view space
    bool unevenScale = false; // M scales unevenly: the two normals differ (drawn only then)
    bool operator==(const NormalMatrixArgument&) const = default;
};

struct ProbeReport {
    ProbePoint point;
    int level = 0;               // the drawn level of the object's mesh
    std::size_t triangle = 0;    // the mesh triangle under the point
    glm::dvec3 barycentric{0.0}; // of the mesh point in that triangle
    int light = -1;              // the light whose l and r/h are given, −1 for none
    ProbeSample mode, exact;
    NormalMatrixArgument normalMatrix;
    bool operator==(const ProbeReport&) const = default;
};

// `mesh` is the object's mesh at its drawn level (subdivisionLevel) with the scene's vertex normals.
// Throws InputError when `point.object` is not an object of the scene or not a sphere.
ProbeReport probeSurface(const Scene& scene, const ProbePoint& point, const SphereMesh& mesh);

} // namespace shadelab
