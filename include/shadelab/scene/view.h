// What the picture shows of a scene: the scene itself, one of three teaching views that set the current
// shading against the exact ray-cast sphere, or the outside view of the camera and its view volume. A scene
// value ("view", "view_at", "view_observer"),
// so the demo's S saves it and `shadelab render` draws the same picture; views, legends and plots are
// drawn into the GL picture itself (src/gl/views.cpp), so a headless render carries them.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "shadelab/shading/lighting.h"

namespace shadelab {

enum class ViewKind {
    Scene,   // "scene": the scene as it is
    Error,   // "error": |mode − exact| per pixel as a heatmap, with its legend and interior mean and max
    Split,   // "split:A,B": two configurations side by side under one camera, a divider between them
    Profile, // "profile": intensity along one row, the mode's and exact, mesh-edge crossings marked
    Outside, // "outside": the scene from an observer: the eye, u, v, w, the view volume, the lights
    Ndc, // "ndc": the objects after M_proj·M_cam and the divide, in the cube [−1, 1]³, from an observer
};
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
    bool operator==(const SplitSide&) const = default;
};

struct View {
    ViewKind kind = ViewKind::Scene;
    SplitSide left, right; // split only
    // "view_at": split — the divider, as a fraction of the width from the left (default 0.5); profile — the
    // row, as a fraction of the height from the top (default: the row through the first object's centre).
    std::optional<double> at;
    Observer observer; // outside and ndc only
    bool operator==(const View&) const = default;
};

// "scene", "error", "profile", "outside", "ndc", or "split:A,B" with each side written as
// shading[/lighting][@level] (or the lighting model alone): "split:gouraud,phong", "split:phong@4,phong@6",
// "split:phong,blinn-phong".
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

} // namespace shadelab
