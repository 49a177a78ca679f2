// The demo's words: the window title, what a key changed, the panel's status and probe tables, and the
// presentation label.
#include "app/demo/demo_state.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/demo/demo_format.h"
#include "shadelab/diagram/overlay.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/auto_level.h"

namespace shadelab::app {

std::string formatVector(const glm::dvec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.2f, %.2f, %.2f)", v.x, v.y, v.z);
    return text;
}

namespace {

// With the unnegated perspective matrix, what it does: the picture is empty, and why.
std::string unnegated(const Scene& scene) {
    if (scene.perspectiveMatrix == PerspectiveMatrix::WebGl) return "";
    return leavesOutTheMinusOne(scene) ? ", unnegated perspective matrix: w < 0 in front, all clipped"
                                       : ", unnegated matrix (orthographic: no -1 to leave out)";
}

// "phong shading, blinn-phong lighting", with one term drawn ", specular term only", with normals by M
// ", normals by M".
std::string modes(const Scene& scene) {
    return std::string(toString(scene.shading)) + " shading, " + std::string(toString(scene.lighting)) +
           " lighting" +
           (scene.term == LightingTerm::All ? "" : ", " + std::string(toString(scene.term)) + " term only") +
           (scene.normalMatrix == NormalMatrixRule::Model ? ", normals by M" : "") + unnegated(scene);
}

// What is drawn: the mesh's level (and "(auto)"), or for exact shading, which draws no mesh, the ray cast;
// after the shape when it is not the sphere (the title) or always (the status line).
std::string geometry(const DemoState& state, const Scene& drawn, bool sphereNamed = false) {
    const std::string shape =
        sphereNamed || state.shape() != Shape::Sphere ? std::string(toString(state.shape())) + ", " : "";
    if (state.shape() == Shape::Mesh) return shape + "its file's triangles, no levels";
    if (drawn.shading == ShadingMode::Exact) return shape + "ray-cast per pixel, no mesh";
    return shape + "level " + std::to_string(state.level()) + (state.autoLevel() ? " (auto)" : "");
}

// The normals overlay past kNormalsOverlayLevel draws a thinned set (overlay.h): said, so that nobody reads
// the missing normals as missing faces.
std::string normalsOverlayNote(const Scene& drawn) {
    if (drawn.overlay != Overlay::Normals || drawn.shading == ShadingMode::Exact) return "";
    int finest = 0;
    for (const SceneObject& object : drawn.objects)
        finest = std::max(finest, subdivisionLevel(drawn, object));
    const NormalsShown shown = normalsShown(finest);
    if (shown.faceStride == 1) return "";
    return "\nnormals shown: level " + std::to_string(shown.level) + "'s vertices and 1 face in " +
           std::to_string(shown.faceStride) + " (of level " + std::to_string(finest) + ")";
}

} // namespace

std::string windowTitle(const DemoState& state, double frameMs) {
    char timing[32];
    std::snprintf(timing, sizeof timing, "%.2f ms", frameMs);
    const Scene& drawn = state.drawn();
    const std::string triangles =
        drawn.shading == ShadingMode::Exact ? "" : std::to_string(state.triangleCount()) + " triangles | ";
    const std::string step = state.lesson() == nullptr
                                 ? ""
                                 : "step " + std::to_string(state.step() + 1) + " of " +
                                       std::to_string(state.lesson()->steps.size()) + " | ";
    return "shadelab — " + step + modes(drawn) + " | " + geometry(state, drawn) + " | " + triangles + timing +
           (state.viewReport().empty() ? "" : " | " + state.viewReport()) + " | H: keys" +
           (state.lastChange().empty() ? "" : " | " + state.lastChange());
}

std::string statusText(const DemoState& state) {
    const Scene& scene = state.drawn();
    return modes(scene) + "\n" + geometry(state, scene, true) + ", " +
           (state.orthographic() ? "orthographic" : "perspective") + ", " +
           (scene.vertexNormals == VertexNormals::Averaged ? "averaged" : "exact") +
           " normals\nmaterial: " + state.materialName() + ", lights: " + state.lightsName() +
           "\npanel edits: " + state.editedObjectName() + normalsOverlayNote(scene) +
           (state.viewReport().empty() ? "" : "\n" + state.viewReport()) +
           (state.levelRefusal().empty() ? "" : "\n" + state.levelRefusal());
}

double probeError255(const ProbeReport& probe) {
    const glm::dvec3 d = glm::abs(probe.mode.color - probe.exact.color);
    return 255 * std::max({d.x, d.y, d.z});
}

bool probeFacesAway(const ProbeReport& probe) {
    const SurfacePoint& p = probe.exact.pointView;
    return glm::dot(p.normal, p.toViewer) < 0;
}

std::string presentationLabel(const DemoState& state) {
    return presentationLabel(presentationFacts(state.drawn()));
}

// What a key changed, in words: on a sphere orthographic and perspective, or exact and averaged normals,
// look alike, so the title says it.
std::string DemoState::describeChange(Command command) const {
    const Scene& scene = drawn();
    switch (command) {
    case Command::Flat:
    case Command::Gouraud:
    case Command::Phong:
    case Command::Toon:
    case Command::Exact:
        if (scene.view.kind == ViewKind::Split)
            return "split: " + toString(scene.view.left) + " | " + toString(scene.view.right);
        return std::string(toString(scene.shading)) + " shading";
    case Command::ToggleErrorView:
    case Command::ToggleSplitView:
    case Command::ToggleProfileView:
    case Command::ToggleOutsideView:
    case Command::ToggleNdcView:
        return scene.view.kind == ViewKind::Scene ? "view: scene" : "view: " + toString(scene.view);
    case Command::ToggleLighting:
        return std::string(toString(scene.lighting)) + " lighting";
    case Command::NextTerm:
        return scene.term == LightingTerm::All ? "every term of the lighting sum"
                                               : "the " + std::string(toString(scene.term)) + " term alone";
    case Command::TogglePerspectiveMatrix:
        if (scene.perspectiveMatrix == PerspectiveMatrix::WebGl)
            return "the WebGL perspective matrix (times -1)";
        return leavesOutTheMinusOne(scene)
                   ? "the unnegated perspective matrix: w < 0 in front of the eye, everything clipped"
                   : "the unnegated perspective matrix: no effect on an orthographic projection";
    case Command::ToggleNormalMatrix:
        return scene.normalMatrix == NormalMatrixRule::Model
                   ? "normals transformed by M: wrong wherever M scales unevenly"
                   : "normals transformed by (M^-1)^T";
    case Command::LevelUp:
    case Command::LevelDown:
        return "level " + std::to_string(level());
    case Command::AutoLevel:
        return (autoLevel() ? "automatic level on: level " : "automatic level off: level ") +
               std::to_string(level());
    case Command::ToggleProjection:
        return orthographic_ ? "orthographic projection" : "perspective projection";
    case Command::ToggleNormals:
        return scene.vertexNormals == VertexNormals::Exact ? "exact vertex normals"
                                                           : "averaged vertex normals";
    case Command::ToggleOverlay:
        return scene.overlay == Overlay::None        ? "overlay off"
               : scene.overlay == Overlay::Wireframe ? "overlay: wireframe"
               : scene.overlay == Overlay::Normals
                   ? "overlay: wireframe, face normals (amber), vertex normals (cyan)"
                   : "overlay: the lights (point: sphere, directional: arrows, spot: cone)";
    case Command::ToggleShape:
        return "shape: " + std::string(toString(shape())) + " for " + editedObjectName();
    case Command::NextMaterial:
        return "material: " + materialName();
    case Command::NextLights:
        return "lights: " + lightsName();
    case Command::ResetView:
        return "view reset";
    default: // the panel and the help show themselves
        return lastChange_;
    }
}

} // namespace shadelab::app
