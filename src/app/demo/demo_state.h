// What the demo window shows and how keys and the mouse change it: plain data and pure functions, no GL
// and no GLFW, so the key set is tested on the CPU and the screenshot state is exactly what is drawn.
// Defined in demo_state.cpp (DemoState's commands and mouse, the presets), demo_camera.cpp (OrbitCamera,
// current()), demo_keys.cpp (the bindings) and demo_text.cpp (title, status, probe table, label).
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "shadelab/geometry/sphere.h"
#include "shadelab/image/image.h"
#include "shadelab/scene/lesson.h"
#include "shadelab/scene/scene.h"
#include "shadelab/shading/probe.h"

namespace shadelab::app {

// The width of the demo's control panel, docked as a left column beside the picture (0 when hidden): at
// most 420 px and at most half the window, so the picture always keeps at least half of it.
// `uiScale` (--ui-scale, --present) widens it with the text.
inline int panelColumnWidth(int windowWidth, bool panelShown, double uiScale = 1) {
    if (!panelShown || windowWidth <= 0) return 0;
    const int widest = int(420 * uiScale);
    return windowWidth / 2 < widest ? windowWidth / 2 : widest;
}

enum class Command {
    Flat,
    Gouraud,
    Phong,
    Toon,
    Exact,
    ToggleErrorView,
    ToggleSplitView,
    ToggleProfileView,
    ToggleOutsideView,
    ToggleNdcView,
    ToggleLighting,
    NextTerm,
    ToggleNormalMatrix,
    TogglePerspectiveMatrix,
    LevelUp,
    LevelDown,
    ToggleProjection,
    ToggleNormals,
    ToggleOverlay,
    AutoLevel,
    NextMaterial,
    NextLights,
    ResetView,
    Screenshot,
    ToggleHelp,
    TogglePanel,
    TogglePresentation,
    ToggleFullScreen,
    NextStep,
    PreviousStep,
    FirstStep,
    LastStep,
    Quit
};

// One spelling of every key, shared by the window, the help overlay, --help and the README table.
struct KeyBinding {
    std::vector<int> keys;  // GLFW key codes (printable keys: their upper-case ASCII code)
    std::string_view label; // how the help text spells the keys, e.g. "1 / F"
    std::string_view action;
    Command command;
};
std::span<const KeyBinding> keyBindings();
std::optional<Command> commandForKey(int key);
std::string keyHelpText(); // one line per binding
// The same as rows (keys, action): the window's help draws them as a table whose wrapped lines stay aligned.
std::vector<std::pair<std::string, std::string>> keyHelpRows();

// Orbits the target on a sphere: azimuth around +y, elevation clamped short of the poles so the camera
// frame (up = +y) is never degenerate.
struct OrbitCamera {
    glm::dvec3 target{0, 0, 0};
    double distance = 4;
    double azimuthRad = 0;   // 0: eye on +z of the target
    double elevationRad = 0; // 0: level with the target; ±kMaxElevation at most

    static constexpr double kMaxElevationRad = 1.5533430342749532; // 89°
    static OrbitCamera looking(const glm::dvec3& eye, const glm::dvec3& target);
    glm::dvec3 eye() const;
    void drag(double dxPixels, double dyPixels); // 0.5° per pixel
    void zoom(double wheelSteps);                // ×0.9 per step in, clamped to a sane range
};

struct MaterialPreset {
    std::string_view name;
    Material material;
};
struct LightPreset {
    std::string_view name;
    std::vector<Light> lights;
};
std::span<const MaterialPreset> materialPresets(); // matte (k_s = 0), plastic (α = 8), metal (α = 150)
std::span<const LightPreset> lightPresets();       // point, directional, spot, three coloured lights

// Where a picture goes in an area of the window (pixels, from the area's top left): the largest rectangle
// of the scene's own aspect that fits, centred, with bars above and below or at the sides. The window then
// frames the scene as `render` does at that size; a 0 × 0 rectangle for an empty area.
struct PictureRect {
    int x = 0, y = 0, width = 0, height = 0;
    bool contains(double px, double py) const {
        return px >= x && px < x + width && py >= y && py < y + height;
    }
};
PictureRect fitPicture(int sceneWidth, int sceneHeight, int areaWidth, int areaHeight);

class DemoState {
public:
    explicit DemoState(Scene scene);

    // The scene to draw: the edited scene with the orbit camera and the chosen projection, for a
    // framebuffer of width × height (0: the scene's own image size). Until the user orbits or zooms, the
    // camera is the scene's own, exactly as `shadelab render` sees it.
    Scene current(int width = 0, int height = 0) const;
    // The size the window (or the page) last drew at, which "auto" levels and the title are computed for
    // (0 × 0 until set: the scene's own image size); drawn() is current() at that size.
    void setViewport(int width, int height) {
        viewportWidth_ = width;
        viewportHeight_ = height;
    }
    Scene drawn() const { return current(viewportWidth_, viewportHeight_); }
    Scene& scene() { return scene_; } // for the control panel's live edits
    // The scene's own image size: the aspect the window fits the picture to (fitPicture).
    int sceneWidth() const { return scene_.width; }
    int sceneHeight() const { return scene_.height; }
    const OrbitCamera& camera() const { return camera_; }

    // Mouse input: orbit and zoom, kept outside every object (and inside the far plane where both fit).
    void drag(double dxPixels, double dyPixels);
    void zoom(double wheelSteps);
    // Right-button drag: orbits the first light that is not ambient around the camera target, 0.5° per
    // pixel as the camera does (a spot's direction turns with it; a directional light's direction turns).
    // An edit of the scene: S saves it and `shadelab render` draws it.
    void dragLight(double dxPixels, double dyPixels);
    // A click at (x, y) pixels of the drawn picture (top left origin) pins the probe to the surface point
    // there; a click on the background removes it. Returns whether a point was hit.
    bool probeAt(double x, double y);
    // The pointer at (x, y) pixels of the drawn picture, with the left button held or not, on every move
    // and button change. Profile view: the row under it is profiled. Split view: a press within 8 px of
    // the divider grabs it and the drag moves it (drag() then leaves the camera alone).
    void pointer(double x, double y, bool leftHeld);
    void clearProbe() { probePoint_.reset(); }
    // The probe evaluated for the drawn scene (it follows orbits, level and mode changes); nullopt
    // without one.
    std::optional<ProbeReport> probe() const;

    // Applies a command; returns false for the commands the window carries out itself (screenshot, quit).
    bool apply(Command command);

    // A lesson being stepped through (README "Lessons"): the state becomes `index`'s step as written (its
    // scene, the camera it names, no material or light preset, no probe), keeping what belongs to the
    // window rather than the step (panel, help, presentation, B's rule, the viewport). The step keys move
    // through it; R returns to the step as written; every other key works inside the step.
    void openLesson(std::shared_ptr<const Lesson> lesson, std::size_t index = 0);
    const Lesson* lesson() const { return lesson_.get(); }
    const std::shared_ptr<const Lesson>& sharedLesson() const { return lesson_; }
    std::size_t step() const { return step_; }
    // "step 3 of 15: The view volume"; "" without a lesson.
    std::string stepName() const;

    // Why the last level change (+, -, the page's level slider) or split view (V) was refused, or "".
    std::string levelRefusal;
    bool matchHighlight = true; // B keeps the highlight size: β = 4α going to Blinn-Phong, α = β/4 back
    bool showHelp = false;
    bool showPanel = true;
    bool presenting = false; // F2, --present: the large label for a class (presentationLabel)
    // The object the control panel's material edits apply to (an index into the scene's objects), or
    // kAllObjects, chosen explicitly. A probe click picks the object it hits.
    static constexpr int kAllObjects = -1;
    int editedObject = 0;
    // "the object" (a scene of one), "object 3 of 12" or "all 12 objects": what the status line says.
    std::string editedObjectName() const;
    // The chooser as the window's panel and the page number it: 0 for all objects, i for object i.
    int editedObjectNumber() const { return editedObject == kAllObjects ? 0 : editedObject + 1; }
    void chooseEditedObject(int number); // clamped to the scene's objects
    // The object whose material the panel shows: the edited one (the first when all are edited); nullopt
    // for a scene without objects.
    std::optional<std::size_t> shownObject() const;
    // A panel edit of the shown material: `edited` becomes the edited object's material. With all objects
    // chosen, each property that differs from the shown material's is set on every object, so one slider
    // changes that property everywhere and each object keeps its others. materialName() then says so.
    void editMaterial(const Material& edited);
    // A panel edit of the shown object's scale (the ellipsoid's axes, times its radius), for the
    // normal-matrix lesson (J): the edited object's; with all objects chosen, the component that differs
    // from the shown object's is set on every object, as editMaterial does. Throws InputError naming
    // objects[N].scale for a component that is zero or not finite, as a scene file would.
    void editScale(const glm::dvec3& scale);
    // A panel edit of the view volume (the lecture's "viewing and projection normalization"): `edited`
    // becomes the drawn projection, its type included (O then toggles from it, and zoom scales an
    // orthographic box from where it was edited). Throws InputError naming projection.<field> for a value
    // a scene file could not hold (near >= far, fovy outside (0, 180), left == right...).
    void editViewVolume(const Projection& edited);
    // What the last drawn view measured, in words ("error: interior mean 2.54/255, max 98.5/255"), set by
    // FramedPicture::draw (demo_draw.h); "" for the plain scene.
    std::string viewReport;
    // The level drawn (of the first object): its own, or what "auto" chose for the drawn view.
    int level() const;
    bool autoLevel() const;
    std::string materialName() const;
    // What the last key changed, in words ("orthographic projection", "material: metal"); "" at first.
    const std::string& lastChange() const { return lastChange_; }
    std::string lightsName() const;
    std::size_t triangleCount() const;
    bool orthographic() const { return orthographic_; }

private:
    void changeLevels(int delta);
    void setShading(ShadingMode mode);
    void toggleLighting();
    void setShininess(std::size_t object, double exponent);
    double presetExponent(double alpha) const;
    std::string describeChange(Command command) const;

    void goToStep(std::size_t index);
    // apply()'s longer commands.
    bool toggleView(Command command);
    void toggleSplitView();
    void nextMaterial();
    void moveThroughLesson(Command command);

    std::shared_ptr<const Lesson> lesson_; // null: a scene alone
    std::size_t step_ = 0;
    Scene initial_, scene_;
    OrbitCamera initialCamera_, camera_;
    bool cameraMoved_ = false;
    // The camera distance the scene's view volume (initial_.projection) belongs to: an orthographic box is
    // scaled by the distance over it, so zooming keeps the picture's scale as under perspective.
    double volumeDistance_ = 1;
    // The exponent each object's shininess stands for before the clamp to >= 1, so that B twice restores
    // a β below 4 exactly (β/4 < 1 would otherwise be lost to the clamp).
    std::vector<double> exponents_;
    bool orthographic_ = false;
    int viewportWidth_ = 0, viewportHeight_ = 0;
    std::string lastChange_;
    std::optional<ProbePoint> probePoint_;
    // The last probe evaluated and the scene it was evaluated for: a level-10 mesh takes ~0.1 s to build
    // and search, so the probe is recomputed only when the drawn scene or the point changes.
    mutable std::optional<Scene> probeScene_;
    mutable std::optional<ProbeReport> probeReport_;
    mutable std::optional<SphereMesh> probeMesh_;
    mutable VertexNormals probeMeshNormals_ = VertexNormals::Averaged;
    bool holdingDivider_ = false, leftWasHeld_ = false;
    int material_ = 0;            // 0: the scene's own, i: materialPresets()[i − 1]
    bool materialEdited_ = false; // by the panel since the last M
    int lights_ = 0;              // 0: the scene's own, i: lightPresets()[i − 1]
};

// "shadelab — phong shading, blinn-phong lighting | level 5 | 8192 triangles | 1.23 ms | H: keys": the
// window's title (the page's too), which the window tests wait for.
std::string windowTitle(const DemoState& state, double frameMs);
// The control panel's first lines: modes, level, projection, normals, material and lights.
std::string statusText(const DemoState& state);
// Presentation mode's label, large enough for the back of a classroom: "PHONG SHADING", "BLINN-PHONG
// LIGHTING" and "LEVEL 5 | BETA = 96" on three lines (ALPHA under Phong lighting; the first object's
// exponent; RAY-CAST instead of the level in exact mode). ASCII, upper case, as it has always read.
std::string presentationLabel(const DemoState& state);
// What the label says, as values: the window remakes its label only when these change.
struct PresentationFacts {
    ShadingMode shading = ShadingMode::Phong;
    bool normalsByM = false, unnegated = false;
    LightingModel lighting = LightingModel::BlinnPhong;
    LightingTerm term = LightingTerm::All;
    int level = 0;
    std::optional<double> shininess; // the first object's; none without objects
    bool operator==(const PresentationFacts&) const = default;
};
PresentationFacts presentationFacts(const Scene& drawn); // drawn: DemoState::drawn()
std::string presentationLabel(const PresentationFacts& facts);
// The label as the window and the page both draw it over the bottom left of a picture of width × height:
// DejaVu Sans Mono Bold on a translucent dark box, its lines as tall as a twelfth of the picture's height
// (55 px at 720) or smaller where the widest line would not fit the width, so it is never clipped; the
// same picture size always gives the same image. `margin` is the gap to the picture's left and bottom.
struct PresentationLabelImage {
    Image image;
    int margin = 0;
};
PresentationLabelImage presentationLabelImage(const std::string& label, int width, int height);
// A lesson step's title and caption as the window, the page and `shadelab slides` draw them across the bottom
// of a picture of width × height: a translucent dark band as wide as the picture, the title in lines an
// eighteenth of the height and the caption's a thirtieth, each to the nearest 11 px (55 and 33 px at 1080,
// 44 and 22 at 720), the caption's lines as written and wrapped at spaces to the width (a word too long for
// a line is cut between characters). Both sizes step down until the band is at most 40 % of the height; the
// same text and size give the same image.
// Drawn at (0, height − image.height); an empty image for a width or height under 1.
Image lessonBandImage(const std::string& title, const std::string& caption, int width, int height);
// The probe's table for the panel and the page: the ambient, diffuse and specular terms and the pixel for
// the current mode beside the exact ones, their difference in 1/255, and the vectors n, v, l, r or h.
std::string probeText(const ProbeReport& probe, ShadingMode mode, LightingModel lighting);
// The same for the state's probe in its drawn mode and lighting model; "" without a probe.
std::string probeText(const DemoState& state);
// The largest difference of the mode's pixel from the exact one over R, G, B, in units of 1/255.
double probeError255(const ProbeReport& probe);
// The probed point is on the far side of its object from the viewer (after an orbit): n · v < 0 at the
// exact surface point. Its vectors are then not drawn, and the table says so.
bool probeFacesAway(const ProbeReport& probe);

} // namespace shadelab::app
