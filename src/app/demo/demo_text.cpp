// The demo's words: the window title, what a key changed, the panel's status and probe tables, and the
// presentation label.
#include "app/demo/demo_state.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/demo/demo_format.h"
#include "shadelab/geometry/overlay.h"
#include "shadelab/geometry/subdivision.h"
#include "shadelab/io/text.h"

namespace shadelab::app {

std::string formatVector(const glm::dvec3& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.2f, %.2f, %.2f)", v.x, v.y, v.z);
    return text;
}

namespace {

// With the unnegated perspective matrix, what it does: the picture is empty, and why.
std::string unnegated(const Scene& scene) {
    if (scene.perspectiveMatrix == PerspectiveMatrix::WebGl) return "";
    return leavesOutTheMinusOne(scene) ? ", unnegated perspective matrix: w < 0 in front, all clipped"
                                       : ", unnegated matrix (orthographic: no -1 to leave out)";
}

// "phong shading, blinn-phong lighting", with one term drawn ", specular term only", with normals by M
// ", normals by M".
std::string modes(const Scene& scene) {
    return std::string(toString(scene.shading)) + " shading, " + std::string(toString(scene.lighting)) +
           " lighting" +
           (scene.term == LightingTerm::All ? "" : ", " + std::string(toString(scene.term)) + " term only") +
           (scene.normalMatrix == NormalMatrixRule::Model ? ", normals by M" : "") + unnegated(scene);
}

// What is drawn: the mesh's level (and "(auto)"), or for exact shading, which draws no mesh, the ray cast.
std::string geometry(const DemoState& state, const Scene& drawn) {
    if (drawn.shading == ShadingMode::Exact) return "ray-cast per pixel, no mesh";
    return "level " + std::to_string(state.level()) + (state.autoLevel() ? " (auto)" : "");
}

// The normals overlay past kNormalsOverlayLevel draws a thinned set (overlay.h): said, so that nobody reads
// the missing normals as missing faces.
std::string normalsOverlayNote(const Scene& drawn) {
    if (drawn.overlay != Overlay::Normals || drawn.shading == ShadingMode::Exact) return "";
    int finest = 0;
    for (const SceneObject& object : drawn.objects)
        finest = std::max(finest, subdivisionLevel(drawn, object));
    const NormalsShown shown = normalsShown(finest);
    if (shown.faceStride == 1) return "";
    return "\nnormals shown: level " + std::to_string(shown.level) + "'s vertices and 1 face in " +
           std::to_string(shown.faceStride) + " (of level " + std::to_string(finest) + ")";
}

} // namespace

std::string windowTitle(const DemoState& state, double frameMs) {
    char timing[32];
    std::snprintf(timing, sizeof timing, "%.2f ms", frameMs);
    const Scene drawn = state.drawn();
    const std::string triangles =
        drawn.shading == ShadingMode::Exact ? "" : std::to_string(state.triangleCount()) + " triangles | ";
    const std::string step = state.lesson() == nullptr
                                 ? ""
                                 : "step " + std::to_string(state.step() + 1) + " of " +
                                       std::to_string(state.lesson()->steps.size()) + " | ";
    return "shadelab — " + step + modes(drawn) + " | " + geometry(state, drawn) + " | " + triangles + timing +
           (state.viewReport.empty() ? "" : " | " + state.viewReport) + " | H: keys" +
           (state.lastChange().empty() ? "" : " | " + state.lastChange());
}

std::string statusText(const DemoState& state) {
    const Scene scene = state.drawn();
    return modes(scene) + "\n" + geometry(state, scene) + ", " +
           (state.orthographic() ? "orthographic" : "perspective") + ", " +
           (scene.vertexNormals == VertexNormals::Averaged ? "averaged" : "exact") +
           " normals\nmaterial: " + state.materialName() + ", lights: " + state.lightsName() +
           "\npanel edits: " + state.editedObjectName() + normalsOverlayNote(scene) +
           (state.viewReport.empty() ? "" : "\n" + state.viewReport) +
           (state.levelRefusal.empty() ? "" : "\n" + state.levelRefusal);
}

double probeError255(const ProbeReport& probe) {
    const glm::dvec3 d = glm::abs(probe.mode.color - probe.exact.color);
    return 255 * std::max({d.x, d.y, d.z});
}

bool probeFacesAway(const ProbeReport& probe) {
    const SurfacePoint& p = probe.exact.pointView;
    return glm::dot(p.normal, p.toViewer) < 0;
}

PresentationFacts presentationFacts(const Scene& drawn) {
    PresentationFacts facts;
    facts.shading = drawn.shading;
    facts.normalsByM = drawn.normalMatrix == NormalMatrixRule::Model;
    facts.unnegated = leavesOutTheMinusOne(drawn);
    facts.lighting = drawn.lighting;
    facts.term = drawn.term;
    facts.level = drawn.shading == ShadingMode::Exact || drawn.objects.empty()
                      ? 0
                      : subdivisionLevel(drawn, drawn.objects[0]); // DemoState::level() of the drawn scene
    if (!drawn.objects.empty()) facts.shininess = drawn.objects[0].material.shininess;
    return facts;
}

std::string presentationLabel(const PresentationFacts& facts) {
    // Three short lines rather than two long ones: the label's letters can be larger in the same width.
    std::string label =
        std::string(toString(facts.shading)) + " shading" + (facts.normalsByM ? ", normals by M" : "") +
        (facts.unnegated ? ", unnegated: w < 0, all clipped" : "") + "\n" +
        std::string(toString(facts.lighting)) + " lighting" +
        (facts.term == LightingTerm::All ? "" : ", " + std::string(toString(facts.term))) + "\n" +
        (facts.shading == ShadingMode::Exact ? std::string("ray-cast")
                                             : "level " + std::to_string(facts.level));
    if (facts.shininess) {
        char exponent[48];
        std::snprintf(exponent, sizeof exponent, " | %s = %g",
                      facts.lighting == LightingModel::BlinnPhong ? "beta" : "alpha", *facts.shininess);
        label += exponent;
    }
    return upperAscii(label);
}

std::string presentationLabel(const DemoState& state) {
    return presentationLabel(presentationFacts(state.drawn()));
}

PresentationLabelImage presentationLabelImage(const std::string& label, int width, int height) {
    std::vector<std::string> lines;
    for (std::size_t start = 0; start <= label.size();) {
        const std::size_t end = std::min(label.find('\n', start), label.size());
        lines.push_back(label.substr(start, end - start));
        start = end + 1;
    }
    const int margin = std::max(4, height / 48);
    // The largest scale whose lines are at most a twelfth of the height and whose widest line, with the
    // box's padding, fits the width less the margins; at least 1 (a picture too small for that clips).
    int scale = std::clamp(height / 12 / textLineHeight(1), 1, kMaxTextScale);
    const auto pad = [](int s) { return textLineHeight(s) / 2; }; // half a line around the text
    const auto boxWidth = [&](int s) {
        int widest = 0;
        for (const std::string& line : lines) widest = std::max(widest, textWidth(line, s));
        return widest + 2 * pad(s);
    };
    while (scale > 1 && boxWidth(scale) > width - 2 * margin) --scale;
    Image image(boxWidth(scale), int(lines.size()) * textLineHeight(scale) + 2 * pad(scale));
    fillRect(image, 0, 0, image.width, image.height, {0, 0, 0, 153}); // 60 % black, as the page had
    for (std::size_t i = 0; i < lines.size(); ++i)
        drawText(image, pad(scale), pad(scale) + int(i) * textLineHeight(scale), lines[i], scale,
                 {255, 255, 255, 255});
    return {std::move(image), margin};
}

namespace {

// Where the UTF-8 character that starts at `at` ends.
std::size_t nextCharacter(const std::string& text, std::size_t at) {
    ++at;
    while (at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) ++at;
    return at;
}

// The lines `text` takes at `scale` in `width` pixels: its own lines, each wrapped at spaces; a word wider
// than a line is cut before the first character that would not fit (never inside a UTF-8 sequence).
std::vector<std::string> wrappedLines(const std::string& text, int scale, int width) {
    std::vector<std::string> lines;
    const auto fits = [&](const std::string& line) { return textWidth(line, scale) <= width; };
    for (std::size_t start = 0; start <= text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string paragraph = text.substr(start, end - start);
        start = end + 1;
        std::string line;
        std::size_t at = 0;
        while (at < paragraph.size()) {
            const std::size_t space = std::min(paragraph.find(' ', at), paragraph.size());
            std::string word = paragraph.substr(at, space - at);
            at = space + 1;
            std::string joined = line;
            if (!joined.empty()) joined += ' ';
            joined += word;
            if (fits(joined)) {
                line = joined;
                continue;
            }
            if (!line.empty()) lines.push_back(line);
            line.clear();
            while (!fits(word)) { // wider than a line on its own: cut after the last character that fits
                std::size_t cut = nextCharacter(word, 0);
                for (std::size_t next = nextCharacter(word, cut);
                     next <= word.size() && fits(word.substr(0, next)); next = nextCharacter(word, next))
                    cut = next;
                lines.push_back(word.substr(0, cut));
                word.erase(0, cut);
            }
            line = word;
        }
        lines.push_back(line);
    }
    return lines;
}

} // namespace

Image lessonBandImage(const std::string& title, const std::string& caption, int width, int height) {
    if (width < 1 || height < 1) return Image(0, 0);
    // The nearest whole scales (a scale is 11 px of line): a floor would leave a 700 px picture's caption
    // at 11 px.
    const auto nearestScale = [&](int parts) {
        return std::clamp(int(std::lround(double(height) / parts / textLineHeight(1))), 1, kMaxTextScale);
    };
    int titleScale = nearestScale(18), captionScale = nearestScale(30);
    const auto pad = [](int s) { return textLineHeight(s) / 2; };
    std::vector<std::string> titleLines, captionLines;
    int bandHeight = 0;
    for (;;) {
        const int inner = std::max(1, width - 2 * pad(titleScale));
        titleLines = wrappedLines(title, titleScale, inner);
        captionLines =
            caption.empty() ? std::vector<std::string>{} : wrappedLines(caption, captionScale, inner);
        bandHeight = 2 * pad(titleScale) + int(titleLines.size()) * textLineHeight(titleScale) +
                     int(captionLines.size()) * textLineHeight(captionScale);
        if (bandHeight <= height * 2 / 5 || (titleScale == 1 && captionScale == 1)) break;
        // The caption gives way first, down to two thirds of the title's size; then the title (to 1).
        const bool captionFirst = captionScale > 1 && (captionScale * 3 >= titleScale * 2 || titleScale == 1);
        if (captionFirst)
            --captionScale;
        else
            --titleScale;
    }
    Image image(width, std::min(bandHeight, height));
    fillRect(image, 0, 0, image.width, image.height, {0, 0, 0, 166}); // 65 % black
    int y = pad(titleScale);
    for (const std::string& line : titleLines) {
        drawText(image, pad(titleScale), y, line, titleScale, {255, 255, 255, 255});
        y += textLineHeight(titleScale);
    }
    for (const std::string& line : captionLines) {
        drawText(image, pad(titleScale), y, line, captionScale, {225, 225, 225, 255});
        y += textLineHeight(captionScale);
    }
    return image;
}

// What a key changed, in words: on a sphere orthographic and perspective, or exact and averaged normals,
// look alike, so the title says it.
std::string DemoState::describeChange(Command command) const {
    const Scene scene = drawn();
    switch (command) {
    case Command::Flat:
    case Command::Gouraud:
    case Command::Phong:
    case Command::Toon:
    case Command::Exact:
        if (scene.view.kind == ViewKind::Split)
            return "split: " + toString(scene.view.left) + " | " + toString(scene.view.right);
        return std::string(toString(scene.shading)) + " shading";
    case Command::ToggleErrorView:
    case Command::ToggleSplitView:
    case Command::ToggleProfileView:
    case Command::ToggleOutsideView:
    case Command::ToggleNdcView:
        return scene.view.kind == ViewKind::Scene ? "view: scene" : "view: " + toString(scene.view);
    case Command::ToggleLighting:
        return std::string(toString(scene.lighting)) + " lighting";
    case Command::NextTerm:
        return scene.term == LightingTerm::All ? "every term of the lighting sum"
                                               : "the " + std::string(toString(scene.term)) + " term alone";
    case Command::TogglePerspectiveMatrix:
        if (scene.perspectiveMatrix == PerspectiveMatrix::WebGl)
            return "the WebGL perspective matrix (times -1)";
        return leavesOutTheMinusOne(scene)
                   ? "the unnegated perspective matrix: w < 0 in front of the eye, everything clipped"
                   : "the unnegated perspective matrix: no effect on an orthographic projection";
    case Command::ToggleNormalMatrix:
        return scene.normalMatrix == NormalMatrixRule::Model
                   ? "normals transformed by M: wrong wherever M scales unevenly"
                   : "normals transformed by (M^-1)^T";
    case Command::LevelUp:
    case Command::LevelDown:
        return "level " + std::to_string(level());
    case Command::AutoLevel:
        return (autoLevel() ? "automatic level on: level " : "automatic level off: level ") +
               std::to_string(level());
    case Command::ToggleProjection:
        return orthographic_ ? "orthographic projection" : "perspective projection";
    case Command::ToggleNormals:
        return scene.vertexNormals == VertexNormals::Exact ? "exact vertex normals"
                                                           : "averaged vertex normals";
    case Command::ToggleOverlay:
        return scene.overlay == Overlay::None        ? "overlay off"
               : scene.overlay == Overlay::Wireframe ? "overlay: wireframe"
               : scene.overlay == Overlay::Normals
                   ? "overlay: wireframe, face normals (amber), vertex normals (cyan)"
                   : "overlay: the lights (point: sphere, directional: arrows, spot: cone)";
    case Command::NextMaterial:
        return "material: " + materialName();
    case Command::NextLights:
        return "lights: " + lightsName();
    case Command::ResetView:
        return "view reset";
    default: // the panel and the help show themselves
        return lastChange_;
    }
}

} // namespace shadelab::app
