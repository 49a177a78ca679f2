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

// Which winding is front: counter-clockwise from outside in object space, which a mirroring transform
// turns clockwise. The NDC view's observer looks at the camera's NDC space, which the projection mirrors
// (view space is right-handed, NDC left-handed), so there it turns once more.
void setFrontFace(const glm::dmat4& viewFromObject, bool ndcView) {
    const bool mirrored = (glm::determinant(glm::dmat3(viewFromObject)) < 0) != ndcView;
    glFrontFace(mirrored ? GL_CW : GL_CCW);
}

// Back faces of a closed mesh lie behind its front faces: culling them halves the fragments shaded
// (measured: ~1.9 fragments per covered pixel without). Where the near plane cuts the object open (its
// bounding sphere, of `boundRadiusObject` in object units, reaches it) its inside shows, as in the analytic
// reference, so there nothing is culled. An open surface is never culled: its back faces show through its
// openings and are lit two-sided (DESIGN §3 "Open surfaces"), which needs front to mean the outside.
void cullBackFaces(const SceneObject& object, const glm::dmat4& viewFromObject, double near, bool closed,
                   double boundRadiusObject) {
    setFrontFace(viewFromObject, false);
    const double centerZ = viewFromObject[3].z;
    const double radius =
        boundRadiusObject * object.radius *
        std::max({std::abs(object.scale.x), std::abs(object.scale.y), std::abs(object.scale.z)});
    if (!closed || centerZ + radius > -near) {
        glDisable(GL_CULL_FACE);
        return;
    }
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
}

// The largest |p| of a mesh's vertices, in object units: the radius of a bounding sphere about the origin.
double boundRadius(const TriangleMesh& mesh) {
    double largest = 0;
    for (const glm::dvec3& p : mesh.positions) largest = std::max(largest, glm::length(p));
    return largest;
}

} // namespace

SceneDraw::SceneDraw() = default;
SceneDraw::~SceneDraw() = default;

const SceneDraw::CachedMesh& SceneDraw::mesh(const Scene& sized, const SceneObject& object,
                                             MeshLayout layout) {
    const Model* model = object.shape == Shape::Mesh ? object.model.get() : nullptr;
    if (object.shape == Shape::Mesh && !model)
        throw RuntimeError("internal error: a mesh object (" + object.mesh +
                           ") was drawn before its model was loaded");
    const int level = object.shape == Shape::Mesh     ? 0
                      : layout == MeshLayout::PatchUv ? kExactProxyLevel
                                                      : subdivisionLevel(sized, object);
    // Flat shading reads face normals only, so both vertex-normal kinds share one flat mesh; the teapot's
    // and a model's normals are their own.
    const VertexNormals normals = object.shape != Shape::Sphere || layout == MeshLayout::Flat
                                      ? VertexNormals::Averaged
                                      : sized.vertexNormals;
    CachedMesh& slot = meshes_[{object.shape, model, level, normals, layout}];
    if (slot.mesh) return slot;
    if (object.shape == Shape::Sphere) {
        slot.mesh = std::make_unique<GpuMesh>(buildSphere(level, normals), layout);
        slot.boundRadiusObject = 1;
    } else if (object.shape == Shape::Teapot) {
        slot.mesh = layout == MeshLayout::PatchUv ? std::make_unique<GpuMesh>(exactTeapotProxy(level))
                                                  : std::make_unique<GpuMesh>(buildTeapot(level), layout);
        slot.boundRadiusObject = teapotBoundRadius();
    } else {
        slot.model = object.model;
        slot.mesh = std::make_unique<GpuMesh>(model->mesh, layout);
        slot.boundRadiusObject = boundRadius(model->mesh);
    }
    return slot;
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
    DrawPlan plan{sized, variant, specialization, {}};
    plan.objects.reserve(sized.objects.size());
    for (const SceneObject& object : sized.objects)
        plan.objects.push_back(objectPlan(sized, object, variant, specialization));
    if (plans_.size() == kPlansKept) plans_.pop_back();
    plans_.insert(plans_.begin(), std::move(plan));
    return plans_.front();
}

SceneDraw::ObjectPlan SceneDraw::objectPlan(const Scene& sized, const SceneObject& object,
                                            const ProgramVariant& frameVariant,
                                            Specialization specialization) {
    ObjectPlan plan;
    plan.closed = isClosed(object);
    ProgramVariant variant = frameVariant;
    variant.twoSided = !plan.closed;
    MeshLayout layout = sized.shading == ShadingMode::Flat && !variant.flatGeometryShader
                            ? MeshLayout::Flat
                            : MeshLayout::Smooth;
    if (sized.shading == ShadingMode::Exact) {
        if (object.shape == Shape::Sphere) {
            plan.kind = ObjectKind::ExactSphere;
        } else if (object.shape == Shape::Teapot) {
            plan.kind = ObjectKind::ExactPatches;
            variant.exactPatches = true;
            variant.twoSided = false; // the ray decides which side it sees (exact_patch.frag.glsl)
            layout = MeshLayout::PatchUv;
        } else {
            // A model has no analytic surface: its reference is per-fragment lighting of its own normals,
            // quantized as toon's when the exact answer is toon's (DESIGN §1 "Meshes from files").
            variant.shading = variant.exactToon ? ShadingMode::Toon : ShadingMode::Phong;
            variant.exactToon = false;
            variant.objectIdAlpha = true;
        }
    }
    // One program for all objects alike, or (values compiled in) one per material.
    plan.program = specialization == Specialization::Values
                       ? &program(variant.withValues(sized, object.material))
                       : &program(variant);
    if (plan.kind != ObjectKind::ExactSphere) plan.mesh = &mesh(sized, object, layout);
    return plan;
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
        const SurfaceProgram* program = plan_.objects[index].program; // drawPlan sets one for every object
        if (!program) throw RuntimeError("scene draw: object " + std::to_string(index) + " has no program");
        const SurfaceProgram& surface = *program;
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
    for (std::size_t index = 0; index < sized.objects.size(); ++index) {
        const ObjectPlan& object = plan.objects[index];
        switch (object.kind) {
        case ObjectKind::Mesh:
            drawMesh(sized, view, variant, object, index, bind, options);
            break;
        case ObjectKind::ExactSphere:
            drawExactSphere(sized, view, index, bind(index), x, options);
            break;
        case ObjectKind::ExactPatches:
            drawExactPatches(sized, view, object, index, bind(index), x, options);
            break;
        }
    }
    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_CULL_FACE);
    if (scene.overlay == Overlay::Wireframe || scene.overlay == Overlay::Normals)
        drawOverlay(sized, view, options);
    if (scene.overlay == Overlay::Lights && !ndcView) drawWorld(sized, lightMarkers(sized), {}, 1, viewport);
    checkGlError("rendering the scene");
}

void SceneDraw::drawMesh(const Scene& sized, const SceneView& view, const ProgramVariant& variant,
                         const ObjectPlan& plan, std::size_t index, ObjectBinder& bind,
                         const DrawOptions& options) {
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
        setFrontFace(viewFromObject, true);
    } else {
        setTransforms(at, view.clipFromView, viewFromObject, sized.normalMatrix);
        cullBackFaces(object, viewFromObject, view.volume.near, plan.closed, plan.mesh->boundRadiusObject);
    }
    if (variant.flatGeometryShader)
        glUniform1f(at.handedness, glm::determinant(glm::dmat3(viewFromObject)) < 0 ? -1.0f : 1.0f);
    glUniform1f(at.alpha, options.exactObjectIds ? float(index + 1) : 1.0f); // OBJECT_ID_ALPHA only
    plan.mesh->mesh->draw();
}

} // namespace shadelab::gl
