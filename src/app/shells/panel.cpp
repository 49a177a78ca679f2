#include "app/shells/panel.h"

#include <algorithm>
#include <string_view>
#include <utility>
#include <vector>

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include "app/demo/matrices_text.h"
#include "app/demo/scene_setters.h"
#include "app/demo/view_explanations.h"
#include "app/shells/panel_font.h"
#include "shadelab/context/window.h"
#include "shadelab/errors.h"
#include "shadelab/gl/loader.h"

namespace shadelab::app {
namespace {

// The widest label drawn beside a field: the fields leave room for it, so no label runs past the column.
constexpr const char* kWidestLabel = "near (n = −near)";

// ImGui lays a widget's label on one line and clips it at the window's edge; in the panel's column (narrow
// beside a wide picture, with --present's large text) they wrap instead, as its text does.

// The next item, `width` wide, goes on the current line if it fits in the column, else on the next.
void sameLineIfFits(float width) {
    const float end = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width;
    if (end <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}

// A radio button after the one before it, on the same line while the row fits.
bool radio(const char* label, bool active) {
    sameLineIfFits(ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x +
                   ImGui::CalcTextSize(label).x);
    return ImGui::RadioButton(label, active);
}

// A checkbox whose label wraps in the column (its lines start where the first one does).
bool wrappedCheckbox(const char* id, const char* label, bool* value) {
    const bool changed = ImGui::Checkbox(id, value);
    ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(label);
    return changed;
}

// What the panel's controls set: a value by its name through the setters every panel shares
// (scene_setters.h), which check it as a scene file's value is checked. A refusal is kept with the name of
// the value it refused and shown under that value's section, in the check's words.
struct Controls {
    DemoState& state;
    std::string& refusal;
    std::string& refused; // the name of the value refused
    void set(std::string_view name, const std::string& text) {
        refusal = setValue(state, name, text);
        refused = refusal.empty() ? "" : std::string(name);
    }
    // The refusal, if one of the values whose names start with `prefix` was refused.
    void showRefusal(std::string_view prefix) const {
        if (!refusal.empty() && std::string_view(refused).starts_with(prefix))
            ImGui::TextColored({1.0f, 0.5f, 0.4f, 1.0f}, "%s", refusal.c_str());
    }
};

// ImGui edits floats; the scene is double.
void colorEdit(Controls& controls, const char* label, const glm::dvec3& color, const std::string& name) {
    float c[3] = {float(color.x), float(color.y), float(color.z)};
    if (ImGui::ColorEdit3(label, c, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR))
        controls.set(name, valueText(glm::dvec3(c[0], c[1], c[2])));
}

void dragVec3(Controls& controls, const char* label, const glm::dvec3& v, float speed,
              const std::string& name) {
    float f[3] = {float(v.x), float(v.y), float(v.z)};
    if (ImGui::DragFloat3(label, f, speed)) controls.set(name, valueText(glm::dvec3(f[0], f[1], f[2])));
}

void materialControls(Controls& controls, const Material& m) {
    colorEdit(controls, "k_a ambient", m.ambient, "material.ambient");
    colorEdit(controls, "k_d diffuse", m.diffuse, "material.diffuse");
    colorEdit(controls, "k_s specular", m.specular, "material.specular");
    float shininess = float(m.shininess);
    // A drag field, not a slider: a slider's handle covers its digits. Logarithmic: 1..1000 by feel.
    if (ImGui::DragFloat("shininess", &shininess, 0.5f, 1, 1000, "%.1f", ImGuiSliderFlags_Logarithmic))
        controls.set("material.shininess", valueText(shininess));
}

void lightControls(Controls& controls, const Light& light, int index) {
    ImGui::PushID(index);
    const std::string_view type = toString(light.type);
    const std::string name = "lights[" + std::to_string(index) + "].";
    if (ImGui::TreeNodeEx("light", ImGuiTreeNodeFlags_DefaultOpen, "light %d: %.*s", index + 1,
                          int(type.size()), type.data())) {
        if (light.type == LightType::Point || light.type == LightType::Spot)
            dragVec3(controls, "position", light.position, 0.05f, name + "position");
        if (light.type == LightType::Directional || light.type == LightType::Spot)
            dragVec3(controls, "direction", light.direction, 0.02f, name + "direction");
        colorEdit(controls, "I_a ambient", light.ambient, name + "ambient");
        if (light.type != LightType::Ambient) {
            colorEdit(controls, "I_d diffuse", light.diffuse, name + "diffuse");
            colorEdit(controls, "I_s specular", light.specular, name + "specular");
        }
        if (light.type == LightType::Point || light.type == LightType::Spot) {
            // The formula on a line of its own: beside the three fields the label wrapped.
            ImGui::TextUnformatted("attenuation 1/(a + b·t + c·t²): a b c");
            dragVec3(controls, "##attenuation", light.attenuation, 0.01f, name + "attenuation");
        }
        if (light.type == LightType::Spot) {
            float cutoff = float(light.cutoffDeg), exponent = float(light.exponent);
            if (ImGui::SliderFloat("cutoff (deg)", &cutoff, 0, 90))
                controls.set(name + "cutoff_deg", valueText(cutoff));
            if (ImGui::SliderFloat("exponent", &exponent, 0, 128))
                controls.set(name + "exponent", valueText(exponent));
        }
        controls.showRefusal(name);
        ImGui::TreePop();
    }
    ImGui::PopID();
}

// The drawn view volume (the lecture's "viewing and projection normalization"): the field of view or the
// window l, r, b, t, and near and far, as distances. An edit the scene could not hold (near past far) is
// refused with its message under the fields.
void viewVolumeControls(Controls& controls) {
    const Projection& p = controls.state.drawn().projection;
    // near and far drag by 1 % of their value a pixel (a near of 0.01 and of 10 both by feel); the window's
    // edges linearly.
    auto drag = [&](const char* label, const char* name, double value, float speed, float lowest,
                    float highest) {
        float f = float(value);
        if (ImGui::DragFloat(label, &f, speed, lowest, highest, "%.4g"))
            controls.set(std::string("projection.") + name, valueText(f));
    };
    if (p.type == ProjectionType::Perspective) {
        drag("fovy (deg)", "fovy_deg", p.fovyDeg, 0.2f, 1, 170);
    } else {
        drag("left l", "left", p.left, 0.01f, -100, 100);
        drag("right r", "right", p.right, 0.01f, -100, 100);
        drag("bottom b", "bottom", p.bottom, 0.01f, -100, 100);
        drag("top t", "top", p.top, 0.01f, -100, 100);
    }
    drag("near (n = −near)", "near", p.near, float(p.near) * 0.01f, 0.001f, 1000);
    drag("far (f = −far)", "far", p.far, float(p.far) * 0.01f, 0.001f, 10000);
    controls.showRefusal("projection.");
}

// A caption's lines are broken for the slide's band, wider than the panel's column: here they are one
// paragraph, wrapped to the column (a line break and the wrap would leave short ragged lines).
std::string reflowed(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text;
}

} // namespace

// A lesson (docs/lecturers.md "Lessons"): where it is, the step's title and caption, and the buttons that do
// what the step keys do.
void lessonControls(DemoState& state) {
    const Lesson& lesson = *state.lesson();
    ImGui::TextUnformatted(lesson.title.c_str());
    if (ImGui::ArrowButton("previous step (PgUp)", ImGuiDir_Left)) state.apply(Command::PreviousStep);
    ImGui::SameLine();
    ImGui::Text("step %zu of %zu", state.step() + 1, lesson.steps.size());
    ImGui::SameLine();
    if (ImGui::ArrowButton("next step (PgDn)", ImGuiDir_Right)) state.apply(Command::NextStep);
    const LessonStep& step = lesson.steps[state.step()];
    ImGui::TextUnformatted(step.title.c_str());
    if (!step.caption.empty()) ImGui::TextUnformatted(reflowed(step.caption).c_str());
    ImGui::Separator();
}

Panel::Panel(Window& window, double uiScale) : api_(window.api()) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // no imgui.ini left in the user's folder
    try {
        // The first font added is ImGui's default; rasterized at the scaled size (sharp), where
        // FontGlobalScale would magnify a small one.
        addPanelFont(*io.Fonts, uiScale);
    } catch (...) {
        ImGui::DestroyContext();
        throw;
    }
    ImGui::StyleColorsDark();
    ImGui::GetStyle().ScaleAllSizes(float(uiScale)); // padding, spacing and scroll bars grow with the text
    ImGui_ImplGlfw_InitForOpenGL(static_cast<GLFWwindow*>(window.nativeHandle()), true);
    ImGui_ImplOpenGL3_Init(window.api() == Api::Gl ? "#version 330 core" : "#version 300 es");
}

Panel::~Panel() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

bool Panel::wantsKeyboard() const {
    return ImGui::GetIO().WantCaptureKeyboard;
}
bool Panel::wantsMouse() const {
    return ImGui::GetIO().WantCaptureMouse;
}

namespace {

// The lecture's three switches: which term of the lighting sum is drawn (K cycles them), the perspective
// matrix (U: WebGL's, or the lecture's before its -1, everything clipped) and what transforms normals
// (J: the right matrix, or M itself, the lecture's wrong one).
void lectureSwitches(Controls& controls) {
    const Scene& scene = controls.state.drawn();
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("term (K):");
    for (const LightingTerm term : kLightingTerms)
        if (radio(std::string(toString(term)).c_str(), scene.term == term))
            controls.set("term", std::string(toString(term)));
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("perspective matrix (U):");
    for (const PerspectiveMatrix matrix : kPerspectiveMatrices) {
        const char* label = matrix == PerspectiveMatrix::Unnegated ? "unnegated" : "WebGL (−1)";
        if (radio(label, scene.perspectiveMatrix == matrix))
            controls.set("perspective_matrix", std::string(toString(matrix)));
    }
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("normals by (J):");
    for (const NormalMatrixRule rule : kNormalMatrixRules) {
        const char* label = rule == NormalMatrixRule::Model ? "M (wrong)" : "(M⁻¹)ᵀ";
        if (radio(label, scene.normalMatrix == rule))
            controls.set("normal_matrix", std::string(toString(rule)));
    }
}

// The shape, material and scale of the chosen object (a probe click picks one), or of all of them when "all
// objects" (0) is chosen. An uneven scale makes an ellipsoid, where normals by M (J) go wrong.
void materialSection(Controls& controls) {
    const DemoState& state = controls.state;
    const int count = int(state.scene().objects.size());
    if (count > 1) {
        int chosen = state.editedObjectNumber();
        if (ImGui::DragInt("object (0: all)", &chosen, 0.1f, 0, count,
                           chosen == 0 ? "all objects" : "object %d", ImGuiSliderFlags_AlwaysClamp))
            controls.set("object", std::to_string(chosen));
    }
    const SceneObject& shown = state.scene().objects[*state.shownObject()];
    if (shown.shape == Shape::Mesh) {
        ImGui::TextWrapped("shape: mesh %s", shown.mesh.c_str()); // a file's, not switched by D
    } else {
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted("shape (D):");
        for (const Shape shape : kShapes) {
            const std::string name(toString(shape));
            if (radio(name.c_str(), shown.shape == shape) && shown.shape != shape)
                controls.set("shape", name);
        }
    }
    materialControls(controls, shown.material);
    glm::vec3 scale(shown.scale);
    if (ImGui::DragFloat3("scale x y z", &scale.x, 0.01f, 0.1f, 4.0f, "%.2f"))
        controls.set("scale", valueText(glm::dvec3(scale)));
    controls.showRefusal("material.");
    controls.showRefusal("scale");
    controls.showRefusal("shape");
}

} // namespace

// e, u, v, w, M_cam, the projection matrix, and the shown object's M and normal matrix, live.
void Panel::matricesSection(const DemoState& state) {
    if (matricesFor_.changed({state.drawnVersion(), state.shownObject()}))
        matricesText_ = matricesPanelText(state.drawn(), state.shownObject());
    ImGui::TextUnformatted(matricesText_.c_str());
}

// The probe's table, or how to make one.
void Panel::probeSection(DemoState& state) {
    // The report is the drawn scene's (its version names it, the mode and the lighting model) at the point.
    const auto& probe = state.probe();
    if (probeFor_.changed({state.drawnVersion(), probe ? std::optional(probe->point) : std::nullopt}))
        probeText_ = probeText(state);
    if (!probeText_.empty()) {
        ImGui::TextUnformatted(probeText_.c_str());
        if (ImGui::Button("remove the probe")) state.clearProbe();
    } else {
        ImGui::TextUnformatted("Click a point of an object: its l, n, v and r or h are drawn there, and "
                               "the ambient, diffuse and specular terms of the current mode show here "
                               "beside the exact ones. Right-drag moves the light; W shows the mesh.");
    }
}

// Docked: the whole left column, beside the picture rather than over it.
void Panel::controlsWindow(DemoState& state, const std::string& status, int columnWidth) {
    Controls controls{state, refusal_, refused_};
    // Read, not edited (the non-const scene() is an edit, which would make the drawn scene again).
    const Scene& scene = std::as_const(state).scene();
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos({0, 0}, ImGuiCond_Always);
    ImGui::SetNextWindowSize({float(columnWidth), display.y}, ImGuiCond_Always);
    // No title bar (a bar cannot wrap): its words are the first line, which can.
    ImGui::Begin("controls", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoTitleBar);
    ImGui::PushTextWrapPos(0.0f);
    // Fields end where the widest label still fits beside them.
    ImGui::PushItemWidth(-(ImGui::CalcTextSize(kWidestLabel).x + ImGui::GetStyle().ItemInnerSpacing.x));
    ImGui::TextDisabled("C hides this panel, H shows the keys");
    if (state.lesson() != nullptr) lessonControls(state);
    ImGui::TextUnformatted(status.c_str());
    bool match = state.matchHighlight();
    if (wrappedCheckbox("##match highlight", "B keeps the highlight size (β = 4α)", &match))
        controls.set("match_highlight", match ? "true" : "false");
    lectureSwitches(controls);
    if (ImGui::CollapsingHeader("what you are seeing", ImGuiTreeNodeFlags_DefaultOpen))
        ImGui::TextUnformatted(whatYouAreSeeing(state.drawn()).c_str());
    if (!scene.objects.empty() && ImGui::CollapsingHeader("material", ImGuiTreeNodeFlags_DefaultOpen))
        materialSection(controls);
    if (ImGui::CollapsingHeader("view volume")) viewVolumeControls(controls);
    if (ImGui::CollapsingHeader("matrices")) matricesSection(state);
    if (ImGui::CollapsingHeader("lights"))
        for (std::size_t i = 0; i < scene.lights.size(); ++i)
            lightControls(controls, scene.lights[i], int(i));
    if (ImGui::CollapsingHeader("probe (click an object)", ImGuiTreeNodeFlags_DefaultOpen))
        probeSection(state);
    if (ImGui::CollapsingHeader("toon")) {
        int bands = scene.toonBands;
        if (ImGui::SliderInt("bands", &bands, kMinToonBands, kMaxToonBands))
            controls.set("toon_bands", std::to_string(bands));
        controls.showRefusal("toon_bands");
    }
    ImGui::PopItemWidth();
    ImGui::PopTextWrapPos();
    ImGui::End();
}

void Panel::draw(DemoState& state, const std::string& status, int columnWidth) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (state.showPanel()) controlsWindow(state, status, columnWidth);
    if (state.showHelp()) helpWindow();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    // Debian builds Dear ImGui's OpenGL 3 backend for desktop GL only (no IMGUI_IMPL_OPENGL_ES3): on an
    // OpenGL ES context its state save and restore asks for GL_POLYGON_MODE and GL_PRIMITIVE_RESTART and
    // calls glPolygonMode, which ES lacks. Each is a no-op that sets GL_INVALID_ENUM/OPERATION (seen with
    // --gl-debug); those flags are cleared here so the renderer's own error checks stay meaningful.
    if (api_ == Api::Gles) gl::discardErrors();
}

} // namespace shadelab::app
