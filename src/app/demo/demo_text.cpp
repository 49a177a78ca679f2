// The demo's words: the window title, the panel's status and probe tables, and the presentation label.
#include "app/demo/demo_state.h"

#include <algorithm>
#include <cstdio>

#include "app/demo/demo_format.h"
#include "shadelab/text.h"

namespace shadelab::app {

std::string formatVector(const glm::dvec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.2f, %.2f, %.2f)", v.x, v.y, v.z);
    return text;
}

namespace {

std::string modes(const Scene& scene) {
    return std::string(toString(scene.shading)) + " shading, " + std::string(toString(scene.lighting)) +
           " lighting";
}

} // namespace

std::string windowTitle(const DemoState& state, double frameMs) {
    char timing[32];
    std::snprintf(timing, sizeof timing, "%.2f ms", frameMs);
    return "shadelab — " + modes(state.drawn()) + " | level " + std::to_string(state.level()) +
           (state.autoLevel() ? " (auto)" : "") + " | " + std::to_string(state.triangleCount()) +
           " triangles | " + timing + (state.viewReport.empty() ? "" : " | " + state.viewReport) +
           " | H: keys" + (state.lastChange().empty() ? "" : " | " + state.lastChange());
}

std::string statusText(const DemoState& state) {
    const Scene scene = state.drawn();
    return modes(scene) + "\nlevel " + std::to_string(state.level()) + ", " +
           (state.orthographic() ? "orthographic" : "perspective") + ", " +
           (scene.vertexNormals == VertexNormals::Averaged ? "averaged" : "exact") +
           " normals\nmaterial: " + state.materialName() + ", lights: " + state.lightsName() +
           "\npanel edits: " + state.editedObjectName() +
           (state.viewReport.empty() ? "" : "\n" + state.viewReport) +
           (state.levelRefusal.empty() ? "" : "\n" + state.levelRefusal);
}

double probeError255(const ProbeReport& probe) {
    const glm::dvec3 d = glm::abs(probe.mode.color - probe.exact.color);
    return 255 * std::max({d.x, d.y, d.z});
}

std::string probeText(const ProbeReport& probe, ShadingMode mode, LightingModel lighting) {
    char line[200];
    std::string text;
    auto row = [&](const char* name, const glm::dvec3& a, const glm::dvec3& b) {
        std::snprintf(line, sizeof line, "%-9s %6.3f %6.3f %6.3f | %6.3f %6.3f %6.3f\n", name, a.x, a.y, a.z,
                      b.x, b.y, b.z);
        text += line;
    };
    std::snprintf(line, sizeof line, "probe: object %zu, level %d, triangle %zu\n", probe.point.object + 1,
                  probe.level, probe.triangle);
    text += line;
    std::snprintf(line, sizeof line, "%-9s %-20s | %s\n", "RGB", std::string(toString(mode)).c_str(),
                  "exact");
    text += line;
    row("ambient", probe.mode.terms.ambient, probe.exact.terms.ambient);
    row("diffuse", probe.mode.terms.diffuse, probe.exact.terms.diffuse);
    row("specular", probe.mode.terms.specular, probe.exact.terms.specular);
    row("pixel", probe.mode.color, probe.exact.color);
    std::snprintf(line, sizeof line, "difference: %.2f/255 (largest of R, G, B)\n", probeError255(probe));
    text += line;
    const char* where = mode == ShadingMode::Flat ? "flat lights the triangle's centroid with its face normal"
                        : mode == ShadingMode::Gouraud ? "Gouraud interpolates the vertices' terms"
                        : mode == ShadingMode::Exact   ? "exact: the ray-cast sphere, its own normal"
                                                       : "lit at the mesh point, interpolated normal";
    text += std::string(where) + "\nview space, at the mode's point:\n";
    const SurfacePoint& p = probe.mode.pointView;
    text += "n (white)   " + formatVector(p.normal) + "\nv (green)   " + formatVector(p.toViewer) + "\n";
    if (probe.light >= 0) {
        text += "l (yellow)  " + formatVector(probe.mode.toLight) + ", light " +
                std::to_string(probe.light + 1) + "\n" +
                (lighting == LightingModel::Phong ? "r (magenta) " : "h (magenta) ") +
                formatVector(probe.mode.specularVector) + "\n";
    }
    return text;
}

std::string probeText(const DemoState& state) {
    const auto probe = state.probe();
    if (!probe) return "";
    const Scene shown = state.drawn();
    return probeText(*probe, shown.shading, shown.lighting);
}

std::string presentationLabel(const DemoState& state) {
    const Scene scene = state.drawn();
    std::string label = std::string(toString(scene.shading)) + " shading\n" +
                        std::string(toString(scene.lighting)) + " lighting | level " +
                        std::to_string(state.level());
    if (!scene.objects.empty()) {
        char exponent[48];
        std::snprintf(exponent, sizeof exponent, " | %s = %g",
                      scene.lighting == LightingModel::BlinnPhong ? "beta" : "alpha",
                      scene.objects[0].material.shininess);
        label += exponent;
    }
    return upperAscii(label);
}

} // namespace shadelab::app
