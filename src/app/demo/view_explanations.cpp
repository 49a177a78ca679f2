#include "app/demo/view_explanations.h"

#include <algorithm>
#include <array>

namespace shadelab::app {
namespace {

// The lecture's notation (../shared/lecture-notes.txt): α a point's world coordinates, β = M_cam·α its
// camera coordinates, M_proj the projection (M_orth, or M_per = M_orth·P times −1), n, l, v, r, h the unit
// vectors of the lighting equation.
constexpr std::array kViews = {
    ViewExplanation{"scene", "the objects as the camera sees them",
                    "camera space (β = M_cam·α), projected by M_proj to the window",
                    "I = k_a I_a + Σ att·(k_d I_d max(l·n, 0) + k_s I_s spec) per pixel"},
    ViewExplanation{"error", "|shaded − exact| per pixel as a heatmap, with its interior mean and max",
                    "window pixels, the mesh's picture against the ray-cast surface's",
                    "error = |I_mode − I_exact| on 0..255, the silhouette eroded by 2 px"},
    ViewExplanation{
        "split",
        "two settings of the same scene (shading, lighting, level, term, normal matrix, material) "
        "cut at a divider, or each whole in its half (side-by-side)",
        "window pixels, one camera for both sides", "left | right, each side's own I"},
    ViewExplanation{"profile",
                    "the intensity along one row: the mode's, the exact one, and mesh-edge crossings",
                    "one window row, x from left to right",
                    "I(x) of the mode and of the exact surface; a kink where an edge crosses"},
    ViewExplanation{
        "outside", "the camera itself from an observer: the eye e, u, v, w, the view volume, lights",
        "world space (α), seen by a second camera", "M_cam = [u v w e]⁻¹, the volume [l,r]×[b,t]×[f,n]"},
    ViewExplanation{"ndc", "the objects after M_proj·M_cam and the divide by w, in the cube [−1, 1]³",
                    "normalized device coordinates, seen by an observer",
                    "NDC = (x, y, z)/w of M_proj·β; near → z = +1, far → z = −1"},
};

constexpr std::array kShadings = {
    ViewExplanation{"flat", "each triangle lit once, at its centroid, with its face normal",
                    "camera space, one colour per triangle", "n = normalize((p₁ − p₀) × (p₂ − p₀))"},
    ViewExplanation{"gouraud", "lit at the vertices with the vertex normals, colours interpolated",
                    "camera space at the vertices, window space between them", "I(p) = Σ λᵢ I(vᵢ)"},
    ViewExplanation{"phong", "normals interpolated, lit at every pixel",
                    "camera space per pixel, n = (M⁻¹)ᵀ·n_object", "n(p) = normalize(Σ λᵢ nᵢ), then I(n(p))"},
    ViewExplanation{"toon", "the diffuse term quantized into bands, the highlight cut at a threshold",
                    "camera space per pixel", "bands of max(l·n, 0); spec on or off"},
    ViewExplanation{
        "exact",
        "the true surface ray-cast per pixel (a sphere, the teapot's patches; a model: its own mesh): the "
        "reference",
        "camera space per pixel, the exact normal",
        "n = (M⁻¹)ᵀ·n_object at the ray's hit (the sphere's n_object = p_object), then I(n)"},
};

// The row named `name` (every view and shading mode has one: view_explanations_test.cpp checks it).
const ViewExplanation& named(std::span<const ViewExplanation> rows, std::string_view name) {
    const auto row =
        std::find_if(rows.begin(), rows.end(), [&](const ViewExplanation& r) { return r.name == name; });
    return row != rows.end() ? *row : rows.front();
}

constexpr std::array<ViewExplanation, kViews.size() + kShadings.size()> all() {
    std::array<ViewExplanation, kViews.size() + kShadings.size()> rows{};
    std::size_t i = 0;
    for (const ViewExplanation& row : kViews) rows[i++] = row;
    for (const ViewExplanation& row : kShadings) rows[i++] = row;
    return rows;
}
constexpr auto kAll = all();

std::string line(const ViewExplanation& row) {
    return std::string(row.drawn) + "; in " + std::string(row.space) + "; " + std::string(row.formula);
}

} // namespace

std::span<const ViewExplanation> viewExplanations() {
    return kAll;
}

std::string whatYouAreSeeing(const Scene& scene) {
    const ViewExplanation& view = named(kViews, viewNamed(scene.view.kind).name);
    std::string text = std::string(view.name) + ": " + line(view);
    if (scene.view.kind == ViewKind::Scene || scene.view.kind == ViewKind::Split) {
        const ViewExplanation& shading = named(kShadings, toString(scene.shading));
        text += " — " + std::string(shading.name) + ": " + line(shading);
        text += scene.lighting == LightingModel::Phong ? "; spec = max(v·r, 0)^α, r = −l + 2(l·n)n"
                                                       : "; spec = max(n·h, 0)^β, h = normalize(v + l)";
    }
    return text;
}

std::string viewHelpText() {
    std::string text;
    for (const ViewExplanation& row : kAll) {
        std::string name(row.name);
        name.resize(std::max<std::size_t>(name.size(), 8), ' ');
        text.append(name).append(" ").append(line(row)).append("\n");
    }
    return text;
}

} // namespace shadelab::app
