#include "gl/scene_draw.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include <glad/gl.h>

#include "shadelab/diagram/outside_view.h"
#include "shadelab/errors.h"
#include "shadelab/exact/ray_cast.h"
#include "shadelab/gl/loader.h"
#include "shadelab/scene/auto_level.h"

namespace shadelab::gl {
namespace {

// The LIGHT_* code of shaders/lighting.glsl: the enum's value (ProgramVariant::defines writes them).
int lightTypeCode(LightType type) {
    return int(type);
}

void setVec3(GLint location, const glm::dvec3& value) {
    const glm::vec3 v(value);
    glUniform3fv(location, 1, glm::value_ptr(v));
}

// Calls visit(locations, light) for each light the program has a slot for: the uber program's one array
// in scene order, or a specialized program's array per type (in scene order within a type). Ambient lights
// have no slot in a specialized program (their sum is uAmbientProduct).
template <class Visit>
void forEachLightSlot(const SurfaceLocations& at, bool specialized, const std::vector<Light>& lightsView,
                      Visit visit) {
    if (!specialized) {
        const std::size_t count = std::min<std::size_t>(lightsView.size(), kMaxLights); // validateScene
        for (std::size_t i = 0; i < count; ++i) visit(at.lights[0][i], lightsView[i]);
        return;
    }
    std::size_t counts[4] = {0, 0, 0, 0};
    for (const Light& light : lightsView) {
        const auto type = std::size_t(lightTypeCode(light.type));
        if (type != 0) visit(at.lights[type].at(counts[type]++), light);
    }
}

// What the lights are and where, once per frame and program; `lightsView` is already in view space. Their
// colours depend on the object too (setLightValues).
void setLightGeometry(const SurfaceLocations& at, bool specialized, const std::vector<Light>& lightsView) {
    if (!specialized) glUniform1i(at.lightCount, std::min<int>(int(lightsView.size()), kMaxLights));
    forEachLightSlot(at, specialized, lightsView, [](const LightLocations& l, const Light& light) {
        glUniform1i(l.type, lightTypeCode(light.type)); // −1 in a specialized program: ignored
        setVec3(l.positionView, light.position);
        setVec3(l.directionView, safeNormalize(light.direction, glm::dvec3(0, 0, -1)));
    });
}

// Per object: the material multiplied into each light's colours on the CPU (lightValues: k_a·I_a,
// k_d·I_d, k_s·I_s in double, each rounded to float once), so the shaders read three colours per light
// instead of forming products of six per fragment (shaders/lighting.glsl says why that matters on
// llvmpipe); with the lights' attenuation and cones. A program with the values compiled in has none of
// these uniforms (location −1: ignored).
void setLightValues(const SurfaceLocations& at, bool specialized, const std::vector<Light>& lightsView,
                    const Material& material) {
    glUniform1f(at.shininess, shininessValue(material));
    forEachLightSlot(at, specialized, lightsView, [&](const LightLocations& l, const Light& light) {
        const LightValues v = lightValues(light, material);
        glUniform3fv(l.ambientProduct, 1, glm::value_ptr(v.ambientProduct)); // uber programs only
        glUniform3fv(l.diffuseProduct, 1, glm::value_ptr(v.diffuseProduct));
        glUniform3fv(l.specularProduct, 1, glm::value_ptr(v.specularProduct));
        glUniform3fv(l.attenuation, 1, glm::value_ptr(v.attenuation));
        glUniform1f(l.cosCutoff, v.cosCutoff);
        glUniform1f(l.exponent, v.exponent);
    });
    if (specialized) glUniform3fv(at.ambientProduct, 1, glm::value_ptr(ambientProduct(lightsView, material)));
}

void setTransforms(const SurfaceLocations& at, const glm::dmat4& clipFromView,
                   const glm::dmat4& viewFromObject, NormalMatrixRule rule) {
    // Composed in double; only the camera-relative products are rounded to float.
    const glm::mat4 clipFromObject(clipFromView * viewFromObject);
    const glm::mat4 viewFromObjectF(viewFromObject);
    const glm::mat3 normalViewFromObjectF(normalViewFromObject(viewFromObject, rule)); // O(1): fits float
    glUniformMatrix4fv(at.clipFromObject, 1, GL_FALSE, glm::value_ptr(clipFromObject));
    glUniformMatrix4fv(at.viewFromObject, 1, GL_FALSE, glm::value_ptr(viewFromObjectF));
    glUniformMatrix3fv(at.normalViewFromObject, 1, GL_FALSE, glm::value_ptr(normalViewFromObjectF));
}

// Back faces of a closed mesh lie behind its front faces: culling them halves the fragments shaded
// (measured: ~1.9 fragments per covered pixel without). Where the near plane cuts the object open its
// inside shows, as in the analytic reference, so there nothing is culled.
void cullBackFaces(const SceneObject& object, const glm::dmat4& viewFromObject, double near) {
    const double centerZ = viewFromObject[3].z;
    const double radius = object.radius * std::max({std::abs(object.scale.x), std::abs(object.scale.y),
                                                    std::abs(object.scale.z)});
    if (centerZ + radius > -near) {
        glDisable(GL_CULL_FACE);
        return;
    }
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    // Counter-clockwise from outside in object space; a mirroring transform turns that clockwise.
    glFrontFace(glm::determinant(glm::dmat3(viewFromObject)) < 0 ? GL_CW : GL_CCW);
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

} // namespace

SceneDraw::SceneDraw() = default;
SceneDraw::~SceneDraw() = default;

const GpuMesh& SceneDraw::mesh(int level, VertexNormals normals, MeshLayout layout) {
    // Flat shading reads face normals only, so both vertex-normal kinds share one flat mesh.
    if (layout == MeshLayout::Flat) normals = VertexNormals::Averaged;
    auto& slot = meshes_[{level, normals, layout}];
    if (!slot) slot = std::make_unique<GpuMesh>(buildSphere(level, normals), layout);
    return *slot;
}

const SceneDraw::DrawPlan& SceneDraw::drawPlan(const Scene& sized, const ProgramVariant& variant,
                                               Specialization specialization) {
    // The views draw several scenes a frame (a split's two sides, the error view's passes): the last few
    // plans are kept, the latest first.
    constexpr std::size_t kPlansKept = 4;
    for (std::size_t i = 0; i < plans_.size(); ++i) {
        const DrawPlan& p = plans_[i];
        if (p.specialization == specialization && p.variant == variant && p.scene == sized) {
            if (i != 0)
                std::rotate(plans_.begin(), plans_.begin() + std::ptrdiff_t(i),
                            plans_.begin() + std::ptrdiff_t(i) + 1);
            return plans_.front();
        }
    }
    DrawPlan plan{sized, variant, specialization, {}, {}};
    plan.programs.reserve(sized.objects.size());
    // One program for all, or (values compiled in) one per material, found again for the next object of
    // the same material in a row.
    const SurfaceProgram* shared = specialization == Specialization::Values ? nullptr : &program(variant);
    for (std::size_t i = 0; i < sized.objects.size(); ++i) {
        const Material& material = sized.objects[i].material;
        if (shared)
            plan.programs.push_back(shared);
        else if (i > 0 && material == sized.objects[i - 1].material)
            plan.programs.push_back(plan.programs.back());
        else
            plan.programs.push_back(&program(variant.withValues(sized, material)));
    }
    if (sized.shading != ShadingMode::Exact) {
        const MeshLayout layout = sized.shading == ShadingMode::Flat && !variant.flatGeometryShader
                                      ? MeshLayout::Flat
                                      : MeshLayout::Smooth;
        plan.meshes.reserve(sized.objects.size());
        for (const SceneObject& object : sized.objects)
            plan.meshes.push_back(&mesh(subdivisionLevel(sized, object), sized.vertexNormals, layout));
    }
    if (plans_.size() == kPlansKept) plans_.pop_back();
    plans_.insert(plans_.begin(), std::move(plan));
    return plans_.front();
}

const SurfaceProgram& SceneDraw::program(const ProgramVariant& variant) {
    auto& slot = programs_[variant];
    if (!slot) {
        slot = std::make_unique<SurfaceProgram>(buildProgram(variant), variant);
        ++programsBuilt_;
    }
    return *slot;
}

// A program keeps its uniforms: the frame's (the lights' geometry, the projection's kind, toon's bands) are
// set when it is bound, and the light values again only for an object of another material than the last.
class SceneDraw::ObjectBinder {
public:
    ObjectBinder(const DrawPlan& plan, const Scene& sized, const ProgramVariant& variant,
                 const SceneView& view, const std::vector<Light>& lightsView)
        : plan_(plan), sized_(sized), variant_(variant), view_(view), lightsView_(lightsView) {}

    // Binds the program that draws the object of that index, with the frame's and the object's uniforms
    // set; returns where the program keeps the rest.
    const SurfaceLocations& operator()(std::size_t index) {
        const SurfaceProgram& surface = *plan_.programs[index];
        const Material& material = sized_.objects[index].material;
        if (&surface != bound_) {
            glUseProgram(surface.program.get());
            setFrameUniforms(surface.at);
            bound_ = &surface;
            valuesOf_ = nullptr;
        }
        if (!valuesOf_ || *valuesOf_ != material) {
            setLightValues(surface.at, variant_.specialized, lightsView_, material);
            valuesOf_ = &material;
        }
        return surface.at;
    }

private:
    void setFrameUniforms(const SurfaceLocations& at) const {
        setLightGeometry(at, variant_.specialized, lightsView_);
        glUniform1i(at.orthographic, view_.orthographic ? 1 : 0); // uber programs (specialized: a define)
        if (sized_.shading == ShadingMode::Toon || variant_.exactToon) {
            glUniform1f(at.toonBands, float(sized_.toonBands));
            glUniform1f(at.toonBandWidth, float(1.0 / sized_.toonBands));
        }
    }

    const DrawPlan& plan_;
    const Scene& sized_;
    const ProgramVariant& variant_;
    const SceneView& view_;
    const std::vector<Light>& lightsView_;
    const SurfaceProgram* bound_ = nullptr;
    const Material* valuesOf_ = nullptr;
};

void SceneDraw::draw(const Scene& scene, const Viewport& viewport, const DrawOptions& options) {
    const int width = viewport.width, height = viewport.height, x = viewport.x;
    if (width <= 0 || height <= 0) return; // a minimized window: nothing to draw, no NaN aspect
    // Assigned, not copied: the vectors keep their storage from frame to frame.
    sized_ = scene;
    Scene& sized = sized_;
    sized.width = width;
    sized.height = height;
    // One term of the lighting sum: the other terms' coefficients are 0, and every shader's one equation
    // (lighting.glsl) draws that term alone, as its shading mode evaluates it.
    if (scene.term != LightingTerm::All)
        for (SceneObject& object : sized.objects) object.material = onlyTerm(object.material, scene.term);
    const bool ndcView = options.observerClipFromNdc.has_value();
    if (ndcView) sized.depth = DepthMode::Standard; // NDC is the cube [−1, 1]³ (DrawOptions)
    const SceneView view = sceneView(sized);

    glViewport(x, 0, width, height);
    glClearColor(float(scene.background.x), float(scene.background.y), float(scene.background.z), 0.0f);
    // DESIGN §2: near maps to NDC z = +1 (standard) or clip depth 1 (reversed), so in both modes the nearer
    // surface has the greater depth. Reversed-Z also needs the [0, 1] clip range.
    setClipDepthZeroToOne(view.depth != DepthMode::Standard, toString(view.depth));
    clearDepth(0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);

    ProgramVariant variant = ProgramVariant::forScene(sized, options.specialization != Specialization::None);
    // The geometry stage derives each face's normal from its view-space corners: the true normal, which is
    // the inverse-transpose rule's; the model rule needs the face normal attribute transformed by M.
    variant.flatGeometryShader = options.flatGeometryShader && scene.shading == ShadingMode::Flat &&
                                 scene.normalMatrix == NormalMatrixRule::InverseTranspose;
    variant.exactToon = options.exactToon && scene.shading == ShadingMode::Exact;
    variant.ndcView = ndcView;
    if (variant.ndcView) variant.flatGeometryShader = false; // its gl_Position is the camera's
    lightsView_.clear();
    for (const Light& light : scene.lights) lightsView_.push_back(transformLight(light, view.viewFromWorld));
    const DrawPlan& plan = drawPlan(sized, variant, options.specialization);
    ObjectBinder bind(plan, sized, variant, view, lightsView_);
    if (scene.shading == ShadingMode::Exact) {
        drawExact(sized, view, bind, x, options);
    } else {
        drawMeshes(sized, view, variant, plan, bind, options);
    }
    glUseProgram(0);
    glDisable(GL_CULL_FACE);
    if (scene.overlay == Overlay::Wireframe || scene.overlay == Overlay::Normals)
        drawOverlay(sized, view, options);
    if (scene.overlay == Overlay::Lights && !ndcView) drawWorld(sized, lightMarkers(sized), {}, 1, viewport);
    checkGlError("rendering the scene");
}

void SceneDraw::drawMeshes(const Scene& sized, const SceneView& view, const ProgramVariant& variant,
                           const DrawPlan& plan, ObjectBinder& bind, const DrawOptions& options) {
    for (std::size_t index = 0; index < sized.objects.size(); ++index) {
        const SceneObject& object = sized.objects[index];
        const SurfaceLocations& at = bind(index);
        const glm::dmat4 viewFromObject = view.viewFromWorld * worldFromObject(object);
        if (options.observerClipFromNdc) {
            // Both faces: the observer may look at the inside of an object the near plane cuts open.
            setTransforms(at, *options.observerClipFromNdc * view.clipFromView, viewFromObject,
                          sized.normalMatrix);
            const glm::mat4 cameraClipFromObject(view.clipFromView * viewFromObject);
            glUniformMatrix4fv(at.cameraClipFromObject, 1, GL_FALSE, glm::value_ptr(cameraClipFromObject));
            glDisable(GL_CULL_FACE);
        } else {
            setTransforms(at, view.clipFromView, viewFromObject, sized.normalMatrix);
            cullBackFaces(object, viewFromObject, view.volume.near);
        }
        if (variant.flatGeometryShader)
            glUniform1f(at.handedness, glm::determinant(glm::dmat3(viewFromObject)) < 0 ? -1.0f : 1.0f);
        plan.meshes[index]->draw();
    }
}

// Exact shading: one proxy rectangle per object, its rays cast in shaders/exact.frag.glsl with what
// ray_cast.cpp's prepareObject and PixelRays give the analytic reference.
void SceneDraw::drawExact(const Scene& sized, const SceneView& view, ObjectBinder& bind, int x,
                          const DrawOptions& options) {
    // The core profile draws only with a vertex array bound, even an empty one.
    if (!emptyVertexArray_) emptyVertexArray_ = VertexArray();
    glDisable(GL_CULL_FACE);
    const ViewVolume& v = view.volume;
    glBindVertexArray(emptyVertexArray_.get());
    for (std::size_t index = 0; index < sized.objects.size(); ++index) {
        const SceneObject& object = sized.objects[index];
        const glm::dmat4 viewFromObject = view.viewFromWorld * worldFromObject(object);
        const glm::vec4 rect = proxyRectangle(view.clipFromView, viewFromObject, v.near, view.orthographic,
                                              sized.width, sized.height);
        if (!(rect.x < rect.z)) continue;
        const SurfaceLocations& at = bind(index);
        glUniform4f(at.viewport, float(x), 0.0f, float(sized.width), float(sized.height));
        glUniform4f(at.nearRect, float(v.left), float(v.right), float(v.bottom), float(v.top));
        // An infinite far plane clips nothing behind (as the reference): the largest float's order stands
        // for it.
        glUniform2f(at.nearFar, float(v.near),
                    sized.depth == DepthMode::ReversedInfinite ? 3e38f : float(v.far));
        glUniformMatrix4fv(at.clipFromView, 1, GL_FALSE, glm::value_ptr(glm::mat4(view.clipFromView)));
        glUniform1f(at.depthZeroToOne, view.depth != DepthMode::Standard ? 1.0f : 0.0f);
        glUniform1f(at.alpha, options.exactObjectIds ? float(index + 1) : 1.0f);
        const ObjectInView prepared = prepareObject(object, view.viewFromWorld, sized.normalMatrix);
        glUniform4fv(at.ndcRect, 1, glm::value_ptr(rect));
        glUniformMatrix3fv(at.objectFromView, 1, GL_FALSE,
                           glm::value_ptr(glm::mat3(prepared.objectFromView3)));
        glUniform3fv(at.centerView, 1, glm::value_ptr(glm::vec3(prepared.originView)));
        glUniformMatrix3fv(at.normalViewFromObject, 1, GL_FALSE,
                           glm::value_ptr(glm::mat3(prepared.normalViewFromObject)));
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    }
    glBindVertexArray(0);
}

} // namespace shadelab::gl
