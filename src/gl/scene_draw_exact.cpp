// Exact shading in the scene draw (DESIGN §3): the sphere ray-cast through a screen rectangle, the teapot's
// patches refined from a proxy mesh, and what both need of the ray.
#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include <glad/gl.h>

#include "shadelab/exact/ray_cast.h"
#include "shadelab/geometry/teapot.h"

#include "gl/scene_draw.h"

namespace shadelab::gl {
namespace {

// How far, in (u, v), the GPU's refined hit may lie beyond each border of a patch (u = 0, u = 1, v = 0,
// v = 1; shaders/exact_patch.frag.glsl): Newton's iteration converges to float's precision, so a ray through
// a seam may land just beyond it on either side; beyond a seam the surface extrapolated is the next patch's
// to second order. A free border (the lid's rim, the spout's tip) takes float's rounding only, or the
// surface would grow. A border collapsed to a cusp takes more: a ray near the cusp converges to negative u,
// where the extrapolated patch is the far side of the cusp to second order.
std::array<float, 4> borderMargins(const TeapotPatch& patch,
                                   const std::array<TeapotPatch, kTeapotPatchCount>& all, std::size_t self) {
    static constexpr std::array<std::array<int, 4>, 4> kBorders = {
        {{0, 1, 2, 3}, {12, 13, 14, 15}, {0, 4, 8, 12}, {3, 7, 11, 15}}};
    const auto same = [](const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b) < 1e-9; };
    std::array<float, 4> margins{};
    for (std::size_t b = 0; b < 4; ++b) {
        const auto& border = kBorders[b];
        bool collapsed = true;
        for (const int k : border)
            collapsed = collapsed && same(patch[std::size_t(k)], patch[std::size_t(border[0])]);
        bool seam = false;
        for (std::size_t other = 0; other < all.size() && !seam; ++other)
            for (const auto& theirs : kBorders) {
                if (other == self && &theirs == &border) continue;
                bool forward = true, backward = true;
                for (std::size_t k = 0; k < 4; ++k) {
                    forward =
                        forward && same(patch[std::size_t(border[k])], all[other][std::size_t(theirs[k])]);
                    backward = backward &&
                               same(patch[std::size_t(border[k])], all[other][std::size_t(theirs[3 - k])]);
                }
                seam = seam || forward || backward;
            }
        margins[b] = collapsed ? 0.2f : seam ? 0.02f : 1e-5f;
    }
    return margins;
}

// The screen-space rectangle, in NDC, that holds the object's projection: the projected corners of its
// bounding box, widened by two pixels, clipped to the viewport. Where the box reaches the near plane (the
// object may be cut open) or behind the eye, the whole viewport. Empty (x0 > x1) when nothing is visible.
glm::vec4 proxyRectangle(const glm::dmat4& clipFromView, const glm::dmat4& viewFromObject, double near,
                         bool orthographic, int width, int height) {
    glm::dvec2 lo(1e300), hi(-1e300);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec4 view =
            viewFromObject * glm::dvec4(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1, 1);
        if (!orthographic && !(view.z < -near)) return {-1, -1, 1, 1};
        const glm::dvec4 clip = clipFromView * view;
        const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    const glm::dvec2 pad(4.0 / width, 4.0 / height); // two pixels
    lo = glm::max(lo - pad, glm::dvec2(-1));
    hi = glm::min(hi + pad, glm::dvec2(1));
    if (!(lo.x < hi.x && lo.y < hi.y)) return {1, 1, -1, -1};
    return {float(lo.x), float(lo.y), float(hi.x), float(hi.y)};
}
// What casting a pixel's ray needs (shaders/exact.frag.glsl, exact_patch.frag.glsl): what ray_cast.cpp's
// prepareObject and PixelRays give the analytic reference.
void setRayUniforms(const SurfaceLocations& at, const Scene& sized, const SceneView& view,
                    const SceneObject& object, std::size_t index, int x, const DrawOptions& options) {
    const ViewVolume& v = view.volume;
    glUniform4f(at.viewport, float(x), 0.0f, float(sized.width), float(sized.height));
    glUniform4f(at.nearRect, float(v.left), float(v.right), float(v.bottom), float(v.top));
    // An infinite far plane clips nothing behind (as the reference): the largest float's order stands for it.
    glUniform2f(at.nearFar, float(v.near), sized.depth == DepthMode::ReversedInfinite ? 3e38f : float(v.far));
    glUniformMatrix4fv(at.clipFromView, 1, GL_FALSE, glm::value_ptr(glm::mat4(view.clipFromView)));
    glUniform1f(at.depthZeroToOne, view.depth != DepthMode::Standard ? 1.0f : 0.0f);
    glUniform1f(at.alpha, options.exactObjectIds ? float(index + 1) : 1.0f);
    const ObjectInView prepared = prepareObject(object, view.viewFromWorld, sized.normalMatrix);
    glUniformMatrix3fv(at.objectFromView, 1, GL_FALSE, glm::value_ptr(glm::mat3(prepared.objectFromView3)));
    glUniform3fv(at.centerView, 1, glm::value_ptr(glm::vec3(prepared.originView)));
    glUniformMatrix3fv(at.normalViewFromObject, 1, GL_FALSE,
                       glm::value_ptr(glm::mat3(prepared.normalViewFromObject)));
}

} // namespace

// The teapot's bounding radius in object units: its control points' largest |p| (a Bézier patch lies in the
// convex hull of its control points), so it holds every level's mesh and the exact surface.
double teapotBoundRadius() {
    double largest = 0;
    for (const TeapotPatch& patch : teapotPatches())
        for (const glm::dvec3& p : patch) largest = std::max(largest, glm::length(p));
    return largest;
}

// The teapot's exact-shading proxy: the level's mesh with each vertex pushed out by the mesh's distance
// bound e (teapotMeshError: a mesh point and the surface point of the same (u, v) lie within e) along its
// normal, and a vertex on a patch's border by e across the border too (along ∓∂P/∂u, ∓∂P/∂v), so that it
// covers the pixels its patch covers: the chords of a convex part lie inside the surface, and those of a
// border inside the border's curve (where the next patch lies behind, as the lid's rim over the body).
TeapotMesh exactTeapotProxy(int level) {
    TeapotMesh proxy = buildTeapot(level);
    const double e = teapotMeshError(level);
    const auto& patches = teapotPatches();
    // A border collapsed to a point (a cusp: the lid's top, the bottom's centre) has nothing to cross: its
    // copies of the point would be pushed apart, opening the tip.
    const auto collapsed = [&](std::size_t patch, bool alongU, double at) {
        const glm::dvec3 a = alongU ? evaluatePatch(patches[patch], at, 0).position
                                    : evaluatePatch(patches[patch], 0, at).position;
        const glm::dvec3 b = alongU ? evaluatePatch(patches[patch], at, 1).position
                                    : evaluatePatch(patches[patch], 1, at).position;
        return glm::length(a - b) < 1e-9;
    };
    const auto unit = [](const glm::dvec3& d) {
        const double length = glm::length(d);
        return length > 0 ? d / length : glm::dvec3(0);
    };
    for (std::size_t i = 0; i < proxy.positions.size(); ++i) {
        const glm::dvec3 patchUv = proxy.patchUv[i];
        const auto patch = std::size_t(patchUv.x);
        const PatchPoint at = evaluatePatch(patches[patch], patchUv.y, patchUv.z);
        glm::dvec3 across(0);
        if ((patchUv.y == 0 || patchUv.y == 1) && !collapsed(patch, true, patchUv.y))
            across += (patchUv.y == 0 ? -1.0 : 1.0) * unit(at.du);
        if ((patchUv.z == 0 || patchUv.z == 1) && !collapsed(patch, false, patchUv.z))
            across += (patchUv.z == 0 ? -1.0 : 1.0) * unit(at.dv);
        proxy.positions[i] += e * (proxy.vertexNormals[i] + across);
    }
    return proxy;
}

// The exact sphere: one proxy rectangle, its rays cast in shaders/exact.frag.glsl.
void SceneDraw::drawExactSphere(const Scene& sized, const SceneView& view, std::size_t index,
                                const SurfaceLocations& at, int x, const DrawOptions& options) {
    const SceneObject& object = sized.objects[index];
    const glm::dmat4 viewFromObject = view.viewFromWorld * worldFromObject(object);
    const glm::vec4 rect = proxyRectangle(view.clipFromView, viewFromObject, view.volume.near,
                                          view.orthographic, sized.width, sized.height);
    if (!(rect.x < rect.z)) return;
    // The core profile draws only with a vertex array bound, even an empty one.
    if (!emptyVertexArray_) emptyVertexArray_ = VertexArray();
    glDisable(GL_CULL_FACE);
    setRayUniforms(at, sized, view, object, index, x, options);
    glUniform4fv(at.ndcRect, 1, glm::value_ptr(rect));
    glBindVertexArray(emptyVertexArray_.get());
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

// The exact teapot: its proxy mesh (exactTeapotProxy), each fragment refining the
// ray's hit on its patch (shaders/exact_patch.frag.glsl). Both faces: the ray decides the side it sees.
void SceneDraw::drawExactPatches(const Scene& sized, const SceneView& view, const ObjectPlan& plan,
                                 std::size_t index, const SurfaceLocations& at, int x,
                                 const DrawOptions& options) {
    if (!teapotPatches_) {
        std::vector<glm::vec4> controlPointsObject;
        controlPointsObject.reserve(std::size_t(kTeapotPatchCount) * 16);
        const auto& patches = teapotPatches();
        for (std::size_t p = 0; p < patches.size(); ++p) {
            const std::array<float, 4> margins = borderMargins(patches[p], patches, p);
            for (std::size_t k = 0; k < 16; ++k)
                controlPointsObject.emplace_back(glm::vec3(patches[p][k]), k < 4 ? margins[k] : 0.0f);
        }
        teapotPatches_ = Buffer();
        glBindBuffer(GL_UNIFORM_BUFFER, teapotPatches_.get());
        glBufferData(GL_UNIFORM_BUFFER, GLsizeiptr(controlPointsObject.size() * sizeof(glm::vec4)),
                     controlPointsObject.data(), GL_STATIC_DRAW);
        glBindBuffer(GL_UNIFORM_BUFFER, 0);
    }
    const SceneObject& object = sized.objects[index];
    const glm::dmat4 viewFromObject = view.viewFromWorld * worldFromObject(object);
    glDisable(GL_CULL_FACE);
    setRayUniforms(at, sized, view, object, index, x, options);
    glUniformMatrix4fv(at.clipFromObject, 1, GL_FALSE,
                       glm::value_ptr(glm::mat4(view.clipFromView * viewFromObject)));
    glBindBufferBase(GL_UNIFORM_BUFFER, kTeapotPatchesBinding, teapotPatches_.get());
    plan.mesh->mesh->draw();
}
} // namespace shadelab::gl
