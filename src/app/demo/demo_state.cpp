// DemoState: what the demo shows and how commands and the mouse change it. The camera and the scene it
// draws are demo_camera.cpp's, the keys demo_keys.cpp's, the words (title, status, probe table)
// demo_text.cpp's (what a key changed among them), the presets M and L cycle through demo_presets.cpp's,
// the panel's edits demo_edits.cpp's.
#include "app/demo/demo_state.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "shadelab/errors.h"
#include "shadelab/scene/auto_level.h"

namespace shadelab::app {
namespace {

// "" or why `scene` asks for more than the scene limits allow (checkSceneLimits' message).
std::string overLimits(const Scene& scene) {
    try {
        checkSceneLimits(scene);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

DemoState::DemoState(Scene scene)
    : initial_(scene), scene_(std::move(scene)),
      initialCamera_(OrbitCamera::looking(scene_.eye, scene_.target)), camera_(initialCamera_),
      volumeDistance_(initialCamera_.distance),
      orthographic_(scene_.projection.type == ProjectionType::Orthographic) {
    for (const SceneObject& o : scene_.objects) exponents_.push_back(o.material.shininess);
}

void DemoState::setViewport(int width, int height) {
    if (width == viewportWidth_ && height == viewportHeight_) return; // every frame sets it
    viewportWidth_ = width;
    viewportHeight_ = height;
    drawn_.stale = true;
}

const Scene& DemoState::drawn() const {
    if (drawn_.stale) {
        // Versions are unique across states (a lesson step is a new one), so a cache keyed by a version
        // never mistakes another state's scene for this one's. A change that leaves the scene as it was
        // (a click on the background, a zero drag) keeps the version, and what is cached by it.
        static std::uint64_t lastVersion = 0;
        Scene fresh = current(viewportWidth_, viewportHeight_);
        if (drawn_.version == 0 || fresh != drawn_.scene) {
            drawn_.scene = std::move(fresh);
            drawn_.version = ++lastVersion;
        }
        drawn_.stale = false;
    }
    return drawn_.scene;
}

std::uint64_t DemoState::drawnVersion() const {
    (void)drawn(); // made if stale
    return drawn_.version;
}

void DemoState::openLesson(std::shared_ptr<const Lesson> lesson, std::size_t index) {
    player_.open(std::move(lesson), index);
    goToStep(player_.step());
    lastChange_ = stepName();
}

void DemoState::goToStep(std::size_t index) {
    LessonPlayer player = player_;
    player.open(player_.shared(), index);
    DemoState step(player.current().scene);
    step.player_ = std::move(player);
    step.window_ = window_;
    step.viewportWidth_ = viewportWidth_;
    step.viewportHeight_ = viewportHeight_;
    *this = std::move(step);
}

// In split view the mode keys change the left side (which the split names); a side never equals the other,
// so a mode the right side shows swaps the two.
void DemoState::setShading(ShadingMode mode) {
    View& view = scene_.view;
    if (view.kind == ViewKind::Split && view.left.shading) {
        const ShadingMode previous = *view.left.shading;
        view.left.shading = mode;
        if (view.left == view.right) view.right.shading = previous;
    }
    scene_.shading = mode;
    drawn_.stale = true;
    // The NDC view transforms the mesh; exact shading has none (the scene check refuses the pair).
    if (mode == ShadingMode::Exact && view.kind == ViewKind::Ndc) view.kind = ViewKind::Scene;
}

void DemoState::pointer(double x, double y, bool leftHeld) {
    const int width = drawn().width, height = drawn().height;
    const View& view = scene_.view;
    // Only a change makes the drawn scene again: the pointer moves far more often than the divider.
    const auto moveTo = [&](double at) {
        if (scene_.view.at == at) return;
        scene_.view.at = at;
        drawn_.stale = true;
    };
    if (view.kind == ViewKind::Profile && height > 0) moveTo(std::clamp(y / height, 0.0, 1.0));
    if (view.kind == ViewKind::Split && width > 0) {
        const double divider = view.at.value_or(0.5) * width;
        if (leftHeld && !leftWasHeld_) holdingDivider_ = std::abs(x - divider) <= 8;
        if (!leftHeld) holdingDivider_ = false;
        if (holdingDivider_) moveTo(std::clamp(x / width, 0.0, 1.0));
    } else {
        holdingDivider_ = false;
    }
    leftWasHeld_ = leftHeld;
}

void DemoState::setLighting(LightingModel model) {
    if (model != scene_.lighting) toggleLighting();
}

void DemoState::setView(ViewKind kind) {
    const ViewKind shown = scene_.view.kind;
    if (kind == shown) return;
    if (kind == ViewKind::Ndc && scene_.shading == ShadingMode::Exact) { // the scene check's own words
        Scene check = valuesCopy();
        check.view = View{};
        check.view.kind = ViewKind::Ndc;
        validateSceneValues(check);
    }
    const auto toggleOf = [](ViewKind k) {
        return k == ViewKind::Error     ? Command::ToggleErrorView
               : k == ViewKind::Split   ? Command::ToggleSplitView
               : k == ViewKind::Profile ? Command::ToggleProfileView
               : k == ViewKind::Outside ? Command::ToggleOutsideView
                                        : Command::ToggleNdcView;
    };
    const ViewKind toggled = kind == ViewKind::Scene ? shown : kind; // off: the shown view's toggle
    if (toggled == ViewKind::Split) {
        const View before = scene_.view;
        if (shown != ViewKind::Split) scene_.view = View{}; // a split is built from the scene's own view
        levelRefusal_.clear();
        toggleSplitView();
        if (!levelRefusal_.empty()) {
            scene_.view = before;
            throw InputError(levelRefusal_);
        }
    } else {
        toggleView(toggleOf(toggled));
    }
    drawn_.stale = true; // after the change: toggleSplitView reads drawn() on the way
    describe(toggleOf(toggled));
}

// E, V, I, Y, Q: the view on, or back to the scene; false (with lastChange_ saying why) when refused.
bool DemoState::toggleView(Command command) {
    const ViewKind kind = command == Command::ToggleErrorView     ? ViewKind::Error
                          : command == Command::ToggleProfileView ? ViewKind::Profile
                          : command == Command::ToggleOutsideView ? ViewKind::Outside
                                                                  : ViewKind::Ndc;
    if (kind == ViewKind::Ndc && scene_.view.kind != kind && scene_.shading == ShadingMode::Exact) {
        lastChange_ = "the NDC view transforms the mesh; exact shading has none: press 1-4 first";
        return false;
    }
    const bool on = scene_.view.kind != kind;
    const Observer observer = scene_.view.observer; // where it was left
    scene_.view = View{};
    scene_.view.kind = on ? kind : ViewKind::Scene;
    scene_.view.observer = observer;
    return true;
}

// The mode (which 1-5 then change) beside exact; beside exact itself, Gouraud and Phong. A split draws
// every object twice: refused (levelRefusal says why) beyond the limits.
void DemoState::toggleSplitView() {
    drawn_.stale = true;
    if (scene_.view.kind == ViewKind::Split) {
        scene_.view = View{};
        return;
    }
    View split;
    split.kind = ViewKind::Split;
    const bool exact = scene_.shading == ShadingMode::Exact;
    split.left.shading = exact ? ShadingMode::Gouraud : scene_.shading;
    split.right.shading = exact ? ShadingMode::Phong : ShadingMode::Exact;
    Scene candidate = drawn();
    candidate.view = split;
    if (const std::string why = overLimits(candidate); !why.empty()) {
        levelRefusal_ = "split view refused: " + why;
        return;
    }
    scene_.view = split;
    drawn_.stale = true; // drawn() above made it for the candidate
}

// M: the next material preset on every object, then the scene's own again.
void DemoState::nextMaterial() {
    material_ = (material_ + 1) % int(materialPresets().size() + 1);
    materialEdited_ = false;
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
        const Material own = initial_.objects[i].material;
        scene_.objects[i].material =
            material_ == 0 ? own : materialPresets()[std::size_t(material_ - 1)].material;
        // Presets are given as α; the scene's own exponent belongs to the scene's lighting model.
        double exponent = presetExponent(scene_.objects[i].material.shininess);
        if (material_ == 0)
            exponent = !window_.matchHighlight || initial_.lighting == scene_.lighting ? own.shininess
                       : scene_.lighting == LightingModel::BlinnPhong                  ? own.shininess * 4
                                                                                       : own.shininess / 4;
        setShininess(i, exponent);
    }
}

// PgDn, PgUp, Home, End; lastChange_ says where it went, or why it did not.
void DemoState::moveThroughLesson(Command command) {
    const StepMove move = command == Command::FirstStep  ? StepMove::First
                          : command == Command::LastStep ? StepMove::Last
                          : command == Command::NextStep ? StepMove::Next
                                                         : StepMove::Previous;
    if (std::string refused = player_.move(move); !refused.empty()) {
        lastChange_ = std::move(refused);
        return;
    }
    goToStep(player_.step());
    lastChange_ = stepName();
}

bool DemoState::apply(Command command) {
    drawn_.stale = true; // most commands change the drawn scene; drawn() keeps it when none did
    switch (command) {
    case Command::Flat:
        setShading(ShadingMode::Flat);
        break;
    case Command::Gouraud:
        setShading(ShadingMode::Gouraud);
        break;
    case Command::Phong:
        setShading(ShadingMode::Phong);
        break;
    case Command::Toon:
        setShading(ShadingMode::Toon);
        break;
    case Command::Exact:
        setShading(ShadingMode::Exact);
        break;
    case Command::ToggleErrorView:
    case Command::ToggleProfileView:
    case Command::ToggleOutsideView:
    case Command::ToggleNdcView:
        if (!toggleView(command)) return true;
        break;
    case Command::ToggleSplitView:
        toggleSplitView();
        break;
    case Command::ToggleLighting:
        toggleLighting();
        break;
    case Command::NextTerm: // all, ambient, diffuse, specular, all
        scene_.term = kLightingTerms[(std::size_t(scene_.term) + 1) % kLightingTerms.size()];
        break;
    case Command::TogglePerspectiveMatrix:
        scene_.perspectiveMatrix = scene_.perspectiveMatrix == PerspectiveMatrix::Unnegated
                                       ? PerspectiveMatrix::WebGl
                                       : PerspectiveMatrix::Unnegated;
        break;
    case Command::ToggleNormalMatrix:
        scene_.normalMatrix = scene_.normalMatrix == NormalMatrixRule::Model
                                  ? NormalMatrixRule::InverseTranspose
                                  : NormalMatrixRule::Model;
        break;
    case Command::LevelUp:
        changeLevels(+1);
        break;
    case Command::LevelDown:
        changeLevels(-1);
        break;
    case Command::AutoLevel: // A again leaves auto at the level it shows
        setAutoLevel(!autoLevel());
        break;
    case Command::ToggleProjection:
        setOrthographic(!orthographic_);
        break;
    case Command::ToggleNormals:
        scene_.vertexNormals =
            scene_.vertexNormals == VertexNormals::Averaged ? VertexNormals::Exact : VertexNormals::Averaged;
        break;
    case Command::ToggleOverlay:
        scene_.overlay = scene_.overlay == Overlay::None        ? Overlay::Wireframe
                         : scene_.overlay == Overlay::Wireframe ? Overlay::Normals
                         : scene_.overlay == Overlay::Normals   ? Overlay::Lights
                                                                : Overlay::None;
        break;
    case Command::ToggleShape:
        try {
            setShape(shape() == Shape::Sphere ? Shape::Teapot : Shape::Sphere);
            levelRefusal_.clear();
        } catch (const InputError& e) {
            levelRefusal_ = std::string("shape refused: ") + e.what();
        }
        break;
    case Command::NextMaterial:
        nextMaterial();
        break;
    case Command::NextLights:
        lights_ = (lights_ + 1) % int(lightPresets().size() + 1);
        scene_.lights = lights_ == 0 ? initial_.lights : lightPresets()[std::size_t(lights_ - 1)].lights;
        break;
    case Command::ResetView:
        if (lesson()) {
            goToStep(step()); // the step as written, not only its camera
            lastChange_ = stepName() + " (as written)";
            return true;
        }
        camera_ = initialCamera_;
        cameraMoved_ = false;
        break;
    case Command::NextStep:
    case Command::PreviousStep:
    case Command::FirstStep:
    case Command::LastStep:
        moveThroughLesson(command);
        return true;
    case Command::TogglePanel:
        window_.showPanel = !window_.showPanel;
        break;
    case Command::ToggleHelp:
        window_.showHelp = !window_.showHelp;
        break;
    case Command::TogglePresentation:
        window_.presenting = !window_.presenting;
        break;
    case Command::ToggleFullScreen:
    case Command::Screenshot:
    case Command::Quit:
        return false;
    }
    // Again after the change: a command that reads drawn() on its way (auto level, split) made it before.
    drawn_.stale = true;
    lastChange_ = describeChange(command);
    return true;
}

bool DemoState::probeAt(double x, double y) {
    const Scene& shown = drawn();
    if (observed(shown.view.kind)) return false; // the picture is the observer's, not the camera's
    const std::optional<ProbePoint> point = pickSurfacePoint(shown, x, y);
    if (!point) {
        probe_.clear();
        lastChange_ = "probe off";
        return false;
    }
    probe_.pin(*point);
    if (editedObject_ != kAllObjects) editedObject_ = int(point->object); // the panel edits what was picked
    if (const auto& report = probe()) {
        char text[160];
        std::snprintf(text, sizeof text, "probe: %s differs from exact by %.2f/255",
                      std::string(toString(shown.shading)).c_str(), probeError255(*report));
        lastChange_ = text;
    }
    return true;
}

// Each object one level up or down from the level it is drawn at ("auto" resolved first).
// A change that would draw more than the scene limits allow (docs/ci-engineers.md "Limits and memory": the
// triangles of every object, of both sides of a split) is refused, and levelRefusal says why.
void DemoState::changeLevels(int delta) {
    const Scene& scene = drawn();
    Scene changed = scene_;
    for (SceneObject& o : changed.objects)
        o.subdivisions = std::clamp(subdivisionLevel(scene, o) + delta, 0, finestLevel(o.shape));
    if (const std::string why = overLimits(changed); !why.empty()) {
        levelRefusal_ = "level " + std::to_string(level() + delta) + " refused: " + why;
        return;
    }
    levelRefusal_.clear();
    scene_.objects = std::move(changed.objects);
    drawn_.stale = true;
}

// β ≈ 4α keeps the highlight's size: the half-vector's angle is half the reflection's (DESIGN §3).
void DemoState::toggleLighting() {
    const bool toBlinn = scene_.lighting == LightingModel::Phong;
    scene_.lighting = toBlinn ? LightingModel::BlinnPhong : LightingModel::Phong;
    drawn_.stale = true;
    if (!window_.matchHighlight) return;
    for (std::size_t i = 0; i < scene_.objects.size(); ++i) {
        // A value edited in the panel since the last toggle replaces the remembered one.
        if (scene_.objects[i].material.shininess != std::max(1.0, exponents_[i]))
            exponents_[i] = scene_.objects[i].material.shininess;
        setShininess(i, toBlinn ? exponents_[i] * 4 : exponents_[i] / 4);
    }
}

} // namespace shadelab::app
