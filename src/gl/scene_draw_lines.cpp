// What a SceneDraw draws over a scene it drew: the overlay's edges, normals and lights, lines given in view
// space (the probe's vectors) and the outside view's world-space faces and lines, with the line program they
// share.
#include <array>
#include <span>

#include <glm/gtc/type_ptr.hpp>

#include <glad/gl.h>

#include "shadelab/diagram/mesh_overlay.h"
#include "shadelab/diagram/outside_view.h"
#include "shadelab/diagram/overlay.h"
#include "shadelab/errors.h"
#include "shadelab/gl/loader.h"
#include "shadelab/scene/auto_level.h"

#include "gl/scene_draw.h"

namespace shadelab::gl {

const SceneDraw::LineProgram& SceneDraw::lineProgram() {
    if (!lineProgram_) {
        Program program = buildLineProgram();
        const GLint clipFromSpace = glGetUniformLocation(program.get(), "uClipFromSpace");
        if (clipFromSpace < 0) throw RuntimeError("the line program has no uniform uClipFromSpace");
        const GLint translucency = glGetUniformLocation(program.get(), "uTranslucency");
        lineProgram_ =
            std::make_unique<LineProgram>(LineProgram{std::move(program), clipFromSpace, translucency});
    }
    return *lineProgram_;
}

namespace {

// The overlays kept on the GPU: a scene's objects and a few scales, levels or shapes tried in the panel.
constexpr std::size_t kMaxCachedOverlays = 64;

} // namespace

void SceneDraw::drawOverlay(const Scene& sized, const SceneView& view, const DrawOptions& options) {
    const LineProgram& lines = lineProgram();
    glUseProgram(lines.program.get());
    for (const SceneObject& object : sized.objects) {
        const int level = subdivisionLevel(sized, object); // 0 for a model
        const glm::dmat4 world = worldFromObject(object);
        // The edges alone are the same lines for every object of a shape; the normals follow its M and the
        // rule.
        const bool normals = sized.overlay == Overlay::Normals;
        const std::array<double, 3> scale =
            normals ? std::array{world[0][0], world[1][1], world[2][2]} : std::array{1.0, 1.0, 1.0};
        const NormalMatrixRule rule = normals ? sized.normalMatrix : NormalMatrixRule::InverseTranspose;
        const Model* model = object.shape == Shape::Mesh ? object.model.get() : nullptr;
        if (object.shape == Shape::Mesh && !model) continue; // SceneDraw::mesh refused to draw it already
        // Only the sphere's lines depend on its vertex normals.
        const VertexNormals vertexNormals =
            object.shape == Shape::Sphere ? sized.vertexNormals : VertexNormals::Averaged;
        if (overlays_.size() > kMaxCachedOverlays) overlays_.clear(); // a scale edited again and again
        CachedLines& cached =
            overlays_[{object.shape, model, level, vertexNormals, sized.overlay, scale, rule}];
        if (!cached.lines) {
            const glm::dmat3 m(world);
            cached.model = object.shape == Shape::Mesh ? object.model : nullptr;
            cached.lines = std::make_unique<GpuLines>(
                object.shape == Shape::Sphere
                    ? overlayLines(buildSphere(level, vertexNormals), sized.overlay, m, rule)
                : object.shape == Shape::Teapot
                    ? teapotOverlayLines(buildTeapot(level), sized.overlay, m, rule)
                    : modelOverlayLines(model->mesh, sized.overlay, m, rule));
        }
        const glm::mat4 clipFromObject(options.observerClipFromNdc.value_or(glm::dmat4(1)) *
                                       view.clipFromView * view.viewFromWorld * world);
        glUniformMatrix4fv(lines.clipFromSpace, 1, GL_FALSE, glm::value_ptr(clipFromObject));
        cached.lines->draw();
    }
    glUseProgram(0);
}

std::span<const LineVertex> SceneDraw::lightMarkers(const Scene& sized) {
    LightMarkers& m = lightMarkers_;
    if (!m.made || m.lights != sized.lights || m.eye != sized.eye || m.target != sized.target) {
        m.made = false;
        m.lines = shadelab::lightMarkers(sized); // outside_view.h: from the lights, the eye and the target
        m.lights = sized.lights;
        m.eye = sized.eye;
        m.target = sized.target;
        m.made = true;
    }
    return m.lines;
}

SceneView SceneDraw::viewportOver(const Scene& scene, const Viewport& viewport) {
    sizedOver_ = scene; // into the same storage every frame, as draw()'s
    sizedOver_.width = viewport.width;
    sizedOver_.height = viewport.height;
    const SceneView view = sceneView(sizedOver_);
    glViewport(viewport.x, 0, viewport.width, viewport.height);
    setClipDepthZeroToOne(view.depth != DepthMode::Standard, toString(view.depth));
    return view;
}

void SceneDraw::drawLinesOver(const Scene& scene, std::span<const LineVertex> linesView,
                              const Viewport& viewport) {
    if (viewport.width <= 0 || viewport.height <= 0 || linesView.empty()) return;
    const SceneView view = viewportOver(scene, viewport);
    glDisable(GL_DEPTH_TEST);
    if (!streamedLines_) streamedLines_ = std::make_unique<GpuLines>();
    streamedLines_->set(linesView);
    const LineProgram& lines = lineProgram();
    glUseProgram(lines.program.get());
    const glm::mat4 clipFromView(view.clipFromView);
    glUniformMatrix4fv(lines.clipFromSpace, 1, GL_FALSE, glm::value_ptr(clipFromView));
    streamedLines_->draw();
    glUseProgram(0);
    glEnable(GL_DEPTH_TEST);
    checkGlError("drawing lines over the scene");
}

void SceneDraw::drawWorld(const Scene& scene, std::span<const LineVertex> linesWorld,
                          std::span<const LineVertex> trianglesWorld, float faceAlpha,
                          const Viewport& viewport) {
    if (viewport.width <= 0 || viewport.height <= 0) return;
    const SceneView view = viewportOver(scene, viewport);
    glEnable(GL_DEPTH_TEST); // GL_GREATER, as draw() left it (DESIGN §2)
    const LineProgram& lines = lineProgram();
    glUseProgram(lines.program.get());
    const glm::mat4 clipFromWorld(view.clipFromView * view.viewFromWorld);
    glUniformMatrix4fv(lines.clipFromSpace, 1, GL_FALSE, glm::value_ptr(clipFromWorld));
    // The translucent faces first, without writing depth, so that every line is drawn whole over them.
    if (!trianglesWorld.empty()) {
        if (!streamedTriangles_) streamedTriangles_ = std::make_unique<GpuLines>();
        streamedTriangles_->set(trianglesWorld);
        glUniform1f(lines.translucency, 1.0f - faceAlpha);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        const GLboolean culling = glIsEnabled(GL_CULL_FACE); // a face is seen from either side
        glDisable(GL_CULL_FACE);
        streamedTriangles_->drawTriangles();
        if (culling) glEnable(GL_CULL_FACE);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
    glUniform1f(lines.translucency, 0.0f);
    if (!streamedLines_) streamedLines_ = std::make_unique<GpuLines>();
    streamedLines_->set(linesWorld);
    streamedLines_->draw();
    glUseProgram(0);
    checkGlError("drawing the outside view's lines");
}

} // namespace shadelab::gl
