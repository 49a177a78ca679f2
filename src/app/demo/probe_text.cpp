// The probe's text (demo_state.h: probeText): the probed point shaded by the mode and exactly, term by term,
// the vectors of the equation there, the normal matrix's argument, and the point through the pipeline.
#include <algorithm>
#include <cstdio>
#include <string>
#include <string_view>

#include "app/demo/demo_format.h"
#include "app/demo/demo_state.h"
#include "shadelab/diagram/point_stages.h"

namespace shadelab::app {

std::string probeText(const ProbeReport& probe, ShadingMode mode, LightingModel lighting) {
    char line[200];
    std::string text =
        probeFacesAway(probe) ? "probe hidden: behind the object (orbit back to see its vectors)\n" : "";
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
    if (const NormalMatrixArgument& a = probe.normalMatrix; a.unevenScale) {
        // The lecture's argument: n·t = 0 before M; after it only (M⁻¹)ᵀn stays perpendicular to M·t.
        std::snprintf(
            line, sizeof line, "normal matrix, M uneven: (M t).(M n) = %.3f, (M t).((M^-1)^T n) = %.3f\n",
            glm::dot(a.tangentByM, a.normalByM), glm::dot(a.tangentByM, a.normalByInverseTranspose));
        text += std::string("t (object)  ") + formatVector(a.tangentObject) + "\nM t (blue)  " +
                formatVector(a.tangentByM) + "\nM n (red)   " + formatVector(a.normalByM) +
                "\n(M^-1)^T n (cyan) " + formatVector(a.normalByInverseTranspose) + "\n" + line;
    }
    return text;
}

namespace {

// The point tracer: the probed point (the exact one) through each stage of the pipeline, in the lecture's
// letters (α world, β camera coordinates).
std::string pointStagesText(const PointStages& p) {
    char numbers[160];
    std::string text = "the exact point through the pipeline:\n";
    const auto row = [&](std::string_view stage, const glm::dvec3& v, const double* w = nullptr) {
        std::string label(stage);
        // Padded by characters, not bytes: α and β are two bytes each.
        const auto characters =
            std::count_if(label.begin(), label.end(), [](char c) { return (c & 0xC0) != 0x80; });
        label.append(std::size_t(std::max<std::ptrdiff_t>(0, 24 - characters)), ' ');
        std::snprintf(numbers, sizeof numbers, w ? "%9.4f %9.4f %9.4f %9.4f\n" : "%9.4f %9.4f %9.4f\n", v.x,
                      v.y, v.z, w ? *w : 0.0);
        text += label + numbers;
    };
    row("object p", p.object);
    row("world  α = M·p", p.world);
    row("camera β = M_cam·α", p.camera);
    row("clip   M_proj·β", glm::dvec3(p.clip), &p.clip.w);
    if (p.behindEye) return text + "w <= 0: clipped (no NDC, no pixel)\n";
    row("NDC    clip/w", p.ndc);
    row("window x, y (px), depth", p.window);
    if (!p.insideVolume) text += "outside the view volume: clipped\n";
    return text;
}

} // namespace

std::string probeText(const DemoState& state) {
    const auto& probe = state.probe();
    if (!probe) return "";
    const Scene& shown = state.drawn();
    return probeText(*probe, shown.shading, shown.lighting) +
           pointStagesText(tracePoint(shown, probe->point.object, probe->point.directionObject));
}

} // namespace shadelab::app
