// What the picture shows of a scene: the scene itself, one of three teaching views that set the current
// shading against the exact ray-cast sphere or two settings beside each other (error, profile, split), the
// outside view of the camera and its view volume, or the NDC view of the objects in the cube. A scene value
// ("view", "view_at", "view_observer"), so the demo's S saves it and `shadelab render` draws the same
// picture; views, legends and plots are
// drawn into the GL picture itself (src/gl/views.cpp), so a headless render carries them.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "shadelab/scene/camera.h"
#include "shadelab/shading/lighting.h"

namespace shadelab {

struct Scene;

enum class ViewKind {
    Scene,   // "scene": the scene as it is
    Error,   // "error": |mode − exact| per pixel as a heatmap, with its legend and interior mean and max
    Split,   // "split:A,B": two configurations side by side under one camera, a divider between them
    Profile, // "profile": intensity along one row, the mode's and exact, mesh-edge crossings marked
    Outside, // "outside": the scene from an observer: the eye, u, v, w, the view volume, the lights
    Ndc, // "ndc": the objects after M_proj·M_cam and the divide, in the cube [−1, 1]³, from an observer
};
// Every view's one row, in the order the help lists them ("split" takes its sides: "split:A,B"): its
// spelling, the demo's key that switches it on and off (none for the scene itself), and what it shows, one
// line that the keys' help, --view's help and the page's view menu all print. A new view is a row here.
struct ViewName {
    ViewKind kind;
    std::string_view name;
    std::string_view key; // the key's label, one upper-case letter ("": no key)
    std::string_view help;
};
inline constexpr std::array<ViewName, 6> kViewNames = {{
    {ViewKind::Scene, "scene", "", "the scene as the camera sees it"},
    {ViewKind::Error, "error", "E", "error view: |mode - exact| heatmap with its mean and max"},
    {ViewKind::Profile, "profile", "I", "intensity profile along the row under the pointer"},
    {ViewKind::Outside, "outside", "Y",
     "outside view: the eye, u, v, w, the view volume and the lights; drag orbits the observer"},
    {ViewKind::Ndc, "ndc", "Q",
     "NDC view: the objects after M_proj M_cam and the divide, in the cube [-1, 1]^3"},
    {ViewKind::Split, "split", "V", "split view: the mode beside exact; drag the divider"},
}};
// The row of `kind`.
constexpr const ViewName& viewNamed(ViewKind kind) {
    for (const ViewName& view : kViewNames)
        if (view.kind == kind) return view;
    return kViewNames.front();
}
// The views that show the scene from an observer (view_observer), not from the camera.
inline bool observed(ViewKind kind) {
    return kind == ViewKind::Outside || kind == ViewKind::Ndc;
}

// Where the outside view's observer stands, in the viewing camera's frame (outside_view.h): azimuth about v
// from w (0: behind the eye, looking where the camera looks; 90: off to the side of u), elevation towards
// v, and a zoom that scales its distance (1: everything framed). "view_observer": [azimuth_deg,
// elevation_deg, zoom].
struct Observer {
    double azimuthDeg = 55, elevationDeg = 25, zoom = 1;
    bool operator==(const Observer&) const = default;
};
inline constexpr double kMaxObserverElevationDeg = 85; // short of the poles: the observer's up is v
inline constexpr double kMinObserverZoom = 0.05, kMaxObserverZoom = 20;

// One side of a split view: what it changes of the scene (unset = the scene's own).
struct SplitSide {
    std::optional<ShadingMode> shading;
    std::optional<LightingModel> lighting;
    std::optional<int> level; // subdivisions of every object, 0..kMaxSubdivisions
    // "outside" or "ndc": that view of the scene (from the scene's view_observer) instead of its picture,
    // so the camera's picture can stand beside it ("split:scene,outside").
    std::optional<ViewKind> view;
    // "{term=…, normal_matrix=…, ambient=…, diffuse=…, specular=…, shininess=…}": the term drawn, the rule
    // for normals and every object's material values, so "the same object with different parameters" is
    // one view: split:phong{shininess=8},phong{shininess=150}.
    std::optional<LightingTerm> term;
    std::optional<NormalMatrixRule> normalMatrix;
    std::optional<glm::dvec3> ambient, diffuse, specular; // k_a, k_d, k_s: linear RGB, >= 0
    std::optional<double> shininess;                      // α or β, >= 1
    bool operator==(const SplitSide&) const = default;
};

// How a split shows its two sides: cut at the divider, one picture whose left part is A and right part B
// ("split:A,B"), or each side whole in its own half, so that no object is cut in two
// ("side-by-side:A,B"; each half keeps the camera and a half-width picture's aspect).
enum class SplitLayout { Divider, SideBySide };

struct View {
    ViewKind kind = ViewKind::Scene;
    SplitSide left, right;                     // split only
    SplitLayout layout = SplitLayout::Divider; // split only
    // "view_at": split — the divider, as a fraction of the width from the left (default 0.5); profile — the
    // row, as a fraction of the height from the top (default: the row through the first object's centre).
    std::optional<double> at;
    Observer observer; // outside and ndc only
    bool operator==(const View&) const = default;
};

// "scene", "error", "profile", "outside", "ndc", or "split:A,B" (or "side-by-side:A,B") with each side
// written as shading[/lighting][@level][{settings}] (or the lighting model alone): "split:gouraud,phong",
// "split:phong@4,phong@6", "split:phong,blinn-phong", "side-by-side:phong{shininess=8},phong{shininess=150}",
// "split:phong{normal_matrix=model},phong".
std::string toString(const View& view);
std::string toString(const SplitSide& side);

// Parses the spelling above. A side is `name[/name][@level]`: one name is a shading mode, or a lighting
// model where it can only be one ("blinn-phong") — and then "phong" on the other side also means the
// lighting model, so "split:phong,blinn-phong" compares the two lighting models. Returns the reason on
// failure (for a message that names the field, the value and the fix).
struct ViewParse {
    std::optional<View> view;
    std::string error;
};
ViewParse parseView(std::string_view text);

// `scene` with what `side` changes of its values (shading, lighting, level, term, normal matrix, every
// object's material) applied; its view is left as it is.
void applySplitSideValues(Scene& scene, const SplitSide& side);

} // namespace shadelab
