// What the demo window shows and how keys and the mouse change it: plain data and pure functions, no GL
// and no GLFW, so the key set is tested on the CPU and the screenshot state is exactly what is drawn.
// Defined in demo_state.cpp (DemoState's commands), demo_camera.cpp (the mouse, current()), demo_edits.cpp
// (the panels' edits), demo_keys.cpp (the bindings) and demo_text.cpp (title, status, probe table, label);
// the rooms it holds have headers of their own (lesson_player.h, probe_cache.h, and the presets, camera
// and layout it is made of), and its values are set by name through scene_setters.h.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/demo/demo_presets.h"
#include "app/demo/lesson_player.h"
#include "app/demo/orbit_camera.h"
#include "app/demo/picture_layout.h"
#include "app/demo/presentation_images.h"
#include "app/demo/probe_cache.h"
#include "app/measure/shape_levels.h"
#include "shadelab/exact/probe.h"
#include "shadelab/geometry/sphere.h"
#include "shadelab/image/image.h"
#include "shadelab/scene/lesson.h"
#include "shadelab/scene/scene.h"

namespace shadelab::app {

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
    ToggleShape,
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

// The demo's state: the scene and how commands, the mouse and the panels change it (demo_state.cpp,
// demo_camera.cpp, demo_edits.cpp), with a lesson player, the probe and the scene it draws, each kept in a
// room of its own. Every change goes through a method, so the drawn scene is made again only when
// something changed it, and handed out by reference: a frame of an unchanged scene copies none.
class DemoState {
public:
    explicit DemoState(Scene scene);

    // The scene to draw: the edited scene with the orbit camera and the chosen projection, for a
    // framebuffer of width × height (0: the scene's own image size). Until the user orbits or zooms, the
    // camera is the scene's own, exactly as `shadelab render` sees it. A copy: for a capture at another
    // size; the frame's own is drawn().
    Scene current(int width = 0, int height = 0) const;
    // The size the window (or the page) last drew at, which "auto" levels and the title are computed for
    // (0 × 0 until set: the scene's own image size); drawn() is current() at that size.
    void setViewport(int width, int height);
    // current() at the viewport, kept: made again after a change (an edit, a command, the mouse, the
    // viewport, a lesson step), the same object otherwise. Valid until the next change.
    const Scene& drawn() const;
    // Counts the changes of drawn(): equal versions, equal scenes (what a cache of it keys on).
    std::uint64_t drawnVersion() const;
    // The edited scene (before the orbit camera and the projection).
    const Scene& scene() const { return scene_; }
    // The edited scene, to change in place, unchecked (tests that build a state by hand); drawn() is made
    // again at its next call. The panels use the setters (scene_setters.h), which check the value.
    Scene& editScene() {
        drawn_.stale = true;
        return scene_;
    }
    // The same, under the name of a read: a read through a non-const DemoState makes the drawn scene again.
    // Kept only for tests/gl/slide_layout_test.cpp until it says editScene().
    Scene& scene() { return editScene(); }
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
    void clearProbe() { probe_.clear(); }
    // The probe evaluated for the drawn scene (it follows orbits, level and mode changes); nullopt
    // without one. Kept until the drawn scene or the point changes (probe_cache.h).
    const std::optional<ProbeReport>& probe() const { return probe_.report(drawn(), drawnVersion()); }

    // Applies a command; returns false for the commands the window carries out itself (screenshot, quit).
    bool apply(Command command);
    // What the keys 1-5, B and E, V, I, Y, Q do, as values (the setters of scene_setters.h): a mode (in split
    // view the left side's), the lighting model (with B's rule), a view on, or back to the scene. setView
    // throws InputError with the scene check's message for a view the scene could not hold (NDC with exact
    // shading) and the limits' for a split too large.
    void setShading(ShadingMode mode);
    void setLighting(LightingModel model);
    void setView(ViewKind kind);
    // The title's last change as the key `command` words it: a panel's setter says what it did so too.
    void describe(Command command) { lastChange_ = describeChange(command); }

    // A lesson being stepped through (docs/lecturers.md "Lessons"): the state becomes `index`'s step as
    // written (its scene, the camera it names, no material or light preset, no probe), keeping what belongs
    // to the window rather than the step (panel, help, presentation, B's rule, the viewport). The step keys
    // move through it; R returns to the step as written; every other key works inside the step.
    void openLesson(std::shared_ptr<const Lesson> lesson, std::size_t index = 0);
    const Lesson* lesson() const { return player_.lesson(); }
    const std::shared_ptr<const Lesson>& sharedLesson() const { return player_.shared(); }
    std::size_t step() const { return player_.step(); }
    // "step 3 of 15: The view volume"; "" without a lesson.
    std::string stepName() const { return player_.stepName(); }

    // What belongs to the window rather than the scene: a lesson step keeps them.
    bool showHelp() const { return window_.showHelp; }
    bool showPanel() const { return window_.showPanel; }
    bool presenting() const { return window_.presenting; } // F2, --present: the large label for a class
    void setShowPanel(bool shown) { window_.showPanel = shown; }
    void setPresenting(bool on) { window_.presenting = on; }
    // B keeps the highlight size: β = 4α going to Blinn-Phong, α = β/4 back.
    bool matchHighlight() const { return window_.matchHighlight; }
    void setMatchHighlight(bool on) { window_.matchHighlight = on; }

    // Why the last level change (+, -, the page's level slider) or split view (V) was refused, or "".
    const std::string& levelRefusal() const { return levelRefusal_; }
    // The object the control panel's material edits apply to (an index into the scene's objects), or
    // kAllObjects, chosen explicitly. A probe click picks the object it hits.
    static constexpr int kAllObjects = -1;
    int editedObject() const { return editedObject_; }
    // "the object" (a scene of one), "object 3 of 12" or "all 12 objects": what the status line says.
    std::string editedObjectName() const;
    // The chooser as the window's panel and the page number it: 0 for all objects, i for object i.
    int editedObjectNumber() const { return editedObject_ == kAllObjects ? 0 : editedObject_ + 1; }
    void chooseEditedObject(int number); // clamped to the scene's objects
    // The object whose material the panel shows: the edited one (the first when all are edited); nullopt
    // for a scene without objects.
    std::optional<std::size_t> shownObject() const;
    // A panel edit of the shown material: `edited` becomes the edited object's material. With all objects
    // chosen, each property that differs from the shown material's is set on every object, so one slider
    // changes that property everywhere and each object keeps its others. materialName() then says so.
    // Throws InputError naming objects[N].material.<field> for a value a scene file could not hold.
    void editMaterial(const Material& edited);
    // A panel edit of the shown object's scale (the ellipsoid's axes, times its radius), for the
    // normal-matrix lesson (J): the edited object's; with all objects chosen, the component that differs
    // from the shown object's is set on every object, as editMaterial does. Throws InputError naming
    // objects[N].scale[i] for a component that is zero or not finite, in a scene file's words.
    void editScale(const glm::dvec3& scale);
    // A panel edit of the view volume (the lecture's "viewing and projection normalization"): `edited`
    // becomes the drawn projection, its type included (O then toggles from it, and zoom scales an
    // orthographic box from where it was edited). Throws InputError naming projection.<field> for a value
    // a scene file could not hold (near >= far, fovy outside (0, 180), left == right...).
    void editViewVolume(const Projection& edited);
    // A panel edit of the scene's values other than its objects and view (lights, toon bands, the
    // lecture's switches): `edit` changes a copy, which is checked as a scene file's values are and then
    // kept. Throws InputError (nothing changed) for a value a scene file could not hold.
    template <class Edit> void editValues(Edit&& edit) {
        Scene edited = valuesCopy(); // its objects are none: an edit of them is not kept
        edit(edited);
        keepValues(std::move(edited));
    }
    // What the last drawn view measured, in words ("error: interior mean 2.54/255, max 98.5/255"), set by
    // FramedPicture::draw (demo_draw.h); "" for the plain scene.
    const std::string& viewReport() const { return viewReport_; }
    void setViewReport(const std::string& report) {
        if (report != viewReport_) viewReport_ = report;
    }
    // The level drawn (of the first object): its own, or what "auto" chose for the drawn view.
    int level() const;
    bool autoLevel() const;
    // The level of every object (each its own level + or − steps, "auto" resolved first), as + and − do;
    // false with levelRefusal() saying why when the scene limits refuse it.
    bool setLevel(int level);
    void setAutoLevel(bool on);
    // The drawn projection orthographic or perspective (O).
    void setOrthographic(bool on);
    // The shown object's shape (DESIGN §1: the sphere or Newell's teapot), or every object's when all are
    // edited (D toggles it); a level beyond the teapot's 0..kMaxTeapotLevel becomes its finest. A mesh
    // object keeps its model. Throws InputError (nothing changed) when the scene limits refuse the result.
    void setShape(Shape shape);
    // The shown object's shape; Shape::Sphere for a scene without objects.
    Shape shape() const;
    std::string materialName() const;
    // What the last key changed, in words ("orthographic projection", "material: metal"); "" at first.
    const std::string& lastChange() const { return lastChange_; }
    std::string lightsName() const;
    std::size_t triangleCount() const;
    bool orthographic() const { return orthographic_; }

private:
    // The scene's values without its objects (what editValues changes), and keeping them, checked, with
    // the scene's objects.
    Scene valuesCopy();
    void keepValues(Scene edited);
    void changeLevels(int delta);
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

    LessonPlayer player_;
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
    struct WindowSettings {
        bool showHelp = false, showPanel = true, presenting = false, matchHighlight = true;
    } window_;
    std::string lastChange_, levelRefusal_, viewReport_;
    int editedObject_ = 0;
    // drawn(): made from the state above at its first call after a change (stale), kept until the next.
    struct Drawn {
        Scene scene;
        std::uint64_t version = 0;
        bool stale = true;
    };
    mutable Drawn drawn_;
    mutable ProbeCache probe_; // a cache of the drawn scene's probe, filled by probe() const
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
// Presentation mode's label for the drawn scene (presentation_images.h: presentationLabel).
std::string presentationLabel(const DemoState& state);
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
