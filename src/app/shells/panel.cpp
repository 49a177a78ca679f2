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

// ImGui edits floats; the scene is double. Edits a colour in place, clamped to >= 0 (DESIGN §4).
bool colorEdit(const char* label, glm::dvec3& color) {
    float c[3] = {float(color.x), float(color.y), float(color.z)};
    if (!ImGui::ColorEdit3(label, c, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR)) return false;
    color = glm::max(glm::dvec3(c[0], c[1], c[2]), glm::dvec3(0));
    return true;
}

bool dragVec3(const char* label, glm::dvec3& v, float speed) {
    float f[3] = {float(v.x), float(v.y), float(v.z)};
    if (!ImGui::DragFloat3(label, f, speed)) return false;
    v = glm::dvec3(f[0], f[1], f[2]);
    return true;
}

bool materialControls(Material& m) {
    bool changed = colorEdit("k_a ambient", m.ambient);
    changed |= colorEdit("k_d diffuse", m.diffuse);
    changed |= colorEdit("k_s specular", m.specular);
    float shininess = float(m.shininess);
    // A drag field, not a slider: a slider's handle covers its digits. Logarithmic: 1..1000 by feel.
    if (ImGui::DragFloat("shininess", &shininess, 0.5f, 1, 1000, "%.1f",
                         ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp)) {
        m.shininess = std::max(1.0f, shininess); // DESIGN §3: exponents >= 1
        changed = true;
    }
    return changed;
}

void lightControls(Light& light, int index) {
    ImGui::PushID(index);
    const std::string_view type = toString(light.type);
    if (ImGui::TreeNodeEx("light", ImGuiTreeNodeFlags_DefaultOpen, "light %d: %.*s", index + 1,
                          int(type.size()), type.data())) {
        if (light.type == LightType::Point || light.type == LightType::Spot)
            dragVec3("position", light.position, 0.05f);
        if (light.type == LightType::Directional || light.type == LightType::Spot) {
            glm::dvec3 direction = light.direction;
            if (dragVec3("direction", direction, 0.02f) && glm::length(direction) > 1e-6)
                light.direction = direction;
        }
        colorEdit("I_a ambient", light.ambient);
        if (light.type != LightType::Ambient) {
            colorEdit("I_d diffuse", light.diffuse);
            colorEdit("I_s specular", light.specular);
        }
        if (light.type == LightType::Point || light.type == LightType::Spot) {
            glm::dvec3 a = light.attenuation;
            // The formula on a line of its own: beside the three fields the label wrapped.
            ImGui::TextUnformatted("attenuation 1/(a + b·t + c·t²): a b c");
            if (dragVec3("##attenuation", a, 0.01f)) {
                a = glm::max(a, glm::dvec3(0)); // DESIGN §3: a, b, c >= 0 with a positive sum
                if (a.x + a.y + a.z > 0) light.attenuation = a;
            }
        }
        if (light.type == LightType::Spot) {
            float cutoff = float(light.cutoffDeg), exponent = float(light.exponent);
            if (ImGui::SliderFloat("cutoff (deg)", &cutoff, 0, 90))
                light.cutoffDeg = std::clamp(cutoff, 0.0f, 90.0f);
            if (ImGui::SliderFloat("exponent", &exponent, 0, 128)) light.exponent = std::max(exponent, 0.0f);
        }
        ImGui::TreePop();
    }
    ImGui::PopID();
}

// The drawn view volume (the lecture's "viewing and projection normalization"): the field of view or the
// window l, r, b, t, and near and far, as distances. An edit the scene could not hold (near past far) is
// refused with its message under the fields.
void viewVolumeControls(DemoState& state, std::string& refusal) {
    Projection p = state.drawn().projection;
    const Projection before = p;
    // near and far drag by 1 % of their value a pixel (a near of 0.01 and of 10 both by feel); the window's
    // edges linearly.
    auto drag = [](const char* label, double& value, float speed, float lowest, float highest,
                   ImGuiSliderFlags flags) {
        float f = float(value);
        if (ImGui::DragFloat(label, &f, speed, lowest, highest, "%.4g", flags)) value = double(f);
    };
    if (p.type == ProjectionType::Perspective) {
        drag("fovy (deg)", p.fovyDeg, 0.2f, 1, 170, ImGuiSliderFlags_None);
    } else {
        drag("left l", p.left, 0.01f, -100, 100, ImGuiSliderFlags_None);
        drag("right r", p.right, 0.01f, -100, 100, ImGuiSliderFlags_None);
        drag("bottom b", p.bottom, 0.01f, -100, 100, ImGuiSliderFlags_None);
        drag("top t", p.top, 0.01f, -100, 100, ImGuiSliderFlags_None);
    }
    drag("near (n = −near)", p.near, float(p.near) * 0.01f, 0.001f, 1000, ImGuiSliderFlags_None);
    drag("far (f = −far)", p.far, float(p.far) * 0.01f, 0.001f, 10000, ImGuiSliderFlags_None);
    if (p != before) {
        try {
            state.editViewVolume(p);
            refusal.clear();
        } catch (const InputError& e) {
            refusal = e.what();
        }
    }
    if (!refusal.empty()) ImGui::TextColored({1.0f, 0.5f, 0.4f, 1.0f}, "%s", refusal.c_str());
}

// A caption's lines are broken for the slide's band, wider than the panel's column: here they are one
// paragraph, wrapped to the column (a line break and the wrap would leave short ragged lines).
std::string reflowed(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text;
}

} // namespace

// A lesson (README "Lessons"): where it is, the step's title and caption, and the buttons that do what the
// step keys do.
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
void lectureSwitches(Scene& scene) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("term (K):");
    for (const LightingTerm term : kLightingTerms)
        if (radio(std::string(toString(term)).c_str(), scene.term == term)) scene.term = term;
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("perspective matrix (U):");
    for (const PerspectiveMatrix matrix : kPerspectiveMatrices) {
        const char* label = matrix == PerspectiveMatrix::Unnegated ? "unnegated" : "WebGL (−1)";
        if (radio(label, scene.perspectiveMatrix == matrix)) scene.perspectiveMatrix = matrix;
    }
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("normals by (J):");
    for (const NormalMatrixRule rule : kNormalMatrixRules) {
        const char* label = rule == NormalMatrixRule::Model ? "M (wrong)" : "(M⁻¹)ᵀ";
        if (radio(label, scene.normalMatrix == rule)) scene.normalMatrix = rule;
    }
}

// The material and scale of the chosen object (a probe click picks one), or of all of them when "all
// objects" (0) is chosen. An uneven scale makes an ellipsoid, where normals by M (J) go wrong.
void materialSection(DemoState& state) {
    const Scene& scene = state.scene();
    const int count = int(scene.objects.size());
    if (count > 1) {
        int chosen = state.editedObjectNumber();
        if (ImGui::DragInt("object (0: all)", &chosen, 0.1f, 0, count,
                           chosen == 0 ? "all objects" : "object %d", ImGuiSliderFlags_AlwaysClamp))
            state.chooseEditedObject(chosen);
    }
    Material edited = scene.objects[*state.shownObject()].material;
    if (materialControls(edited)) state.editMaterial(edited);
    glm::vec3 scale(state.scene().objects[*state.shownObject()].scale);
    if (ImGui::DragFloat3("scale x y z", &scale.x, 0.01f, 0.1f, 4.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp))
        state.editScale(glm::dvec3(scale));
}

} // namespace

// e, u, v, w, M_cam, the projection matrix, and the shown object's M and normal matrix, live.
void Panel::matricesSection(const DemoState& state) {
    if (matricesFor_.changed({state.drawn(), state.shownObject()}))
        matricesText_ = matricesPanelText(state.drawn(), state.shownObject());
    ImGui::TextUnformatted(matricesText_.c_str());
}

// The probe's table, or how to make one.
void Panel::probeSection(DemoState& state) {
    const Scene drawn = state.drawn();
    if (probeFor_.changed({state.probe(), drawn.shading, drawn.lighting})) probeText_ = probeText(state);
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
    Scene& scene = state.scene();
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
    wrappedCheckbox("##match highlight", "B keeps the highlight size (β = 4α)", &state.matchHighlight);
    lectureSwitches(scene);
    if (ImGui::CollapsingHeader("what you are seeing", ImGuiTreeNodeFlags_DefaultOpen))
        ImGui::TextUnformatted(whatYouAreSeeing(state.drawn()).c_str());
    if (!scene.objects.empty() && ImGui::CollapsingHeader("material", ImGuiTreeNodeFlags_DefaultOpen))
        materialSection(state);
    if (ImGui::CollapsingHeader("view volume")) viewVolumeControls(state, volumeRefusal_);
    if (ImGui::CollapsingHeader("matrices")) matricesSection(state);
    if (ImGui::CollapsingHeader("lights"))
        for (std::size_t i = 0; i < scene.lights.size(); ++i) lightControls(scene.lights[i], int(i));
    if (ImGui::CollapsingHeader("probe (click an object)", ImGuiTreeNodeFlags_DefaultOpen))
        probeSection(state);
    if (ImGui::CollapsingHeader("toon")) {
        int bands = scene.toonBands;
        if (ImGui::SliderInt("bands", &bands, kMinToonBands, kMaxToonBands))
            scene.toonBands = std::clamp(bands, kMinToonBands, kMaxToonBands);
    }
    ImGui::PopItemWidth();
    ImGui::PopTextWrapPos();
    ImGui::End();
}

void Panel::draw(DemoState& state, const std::string& status, int columnWidth) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (state.showPanel) controlsWindow(state, status, columnWidth);
    if (state.showHelp) helpWindow();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    // Debian builds Dear ImGui's OpenGL 3 backend for desktop GL only (no IMGUI_IMPL_OPENGL_ES3): on an
    // OpenGL ES context its state save and restore asks for GL_POLYGON_MODE and GL_PRIMITIVE_RESTART and
    // calls glPolygonMode, which ES lacks. Each is a no-op that sets GL_INVALID_ENUM/OPERATION (seen with
    // --gl-debug); those flags are cleared here so the renderer's own error checks stay meaningful.
    if (api_ == Api::Gles) gl::discardErrors();
}

} // namespace shadelab::app
