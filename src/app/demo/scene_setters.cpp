// The value setters' table (scene_setters.h): how each value is read and set, and through which check.
#include "app/demo/scene_setters.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "shadelab/errors.h"
#include "shadelab/io/text.h"
#include "shadelab/scene/scene_values.h"
#include "shadelab/vocabulary.h"

namespace shadelab::app {
namespace {

std::string trimmed(std::string_view text) {
    const std::size_t first = text.find_first_not_of(" \t\n");
    if (first == std::string_view::npos) return "";
    return std::string(text.substr(first, text.find_last_not_of(" \t\n") - first + 1));
}

[[noreturn]] void expected(std::string_view what, std::string_view field, std::string_view text) {
    throw InputError(std::string(field) + ": expected " + std::string(what) + ", got " + quotedValue(text));
}

// A decimal number as the scene file writes one; its range is the check's to refuse, not the door's.
double number(std::string_view text, std::string_view field) {
    const std::string s = trimmed(text);
    if (s.empty()) expected("a number", field, text);
    char* end = nullptr;
    const double value = std::strtod(s.c_str(), &end);
    if (*end != '\0' || std::isnan(value)) expected("a number", field, text);
    if (!std::isfinite(value)) failNotFinite(field, s); // "1e400", as the scene file refuses it
    return value;
}

int integer(std::string_view text, std::string_view field) {
    const double value = number(text, field);
    if (value != std::floor(value) || std::abs(value) > std::numeric_limits<int>::max())
        expected("a whole number", field, text);
    return int(value);
}

// "0.1 0.2 0.3", "0.1, 0.2, 0.3" or "[0.1, 0.2, 0.3]".
glm::dvec3 vec3(std::string_view text, std::string_view field) {
    std::string s = trimmed(text);
    for (char& c : s)
        if (c == ',' || c == '[' || c == ']') c = ' ';
    glm::dvec3 v{0};
    std::size_t at = 0;
    for (int i = 0; i < 3; ++i) {
        const std::size_t start = s.find_first_not_of(' ', at);
        if (start == std::string::npos) expected("three numbers", field, text);
        at = std::min(s.find(' ', start), s.size());
        v[i] = number(std::string_view(s).substr(start, at - start), field);
    }
    if (s.find_first_not_of(' ', at) != std::string::npos) expected("three numbers", field, text);
    return v;
}

bool boolean(std::string_view text, std::string_view field) {
    const std::string s = trimmed(text);
    if (s == "true" || s == "on" || s == "1") return true;
    if (s == "false" || s == "off" || s == "0") return false;
    expected("true or false", field, text);
}

std::string word(std::string_view name) {
    return std::string(name);
}

// The panel's shown material, or a refusal for a scene without objects.
std::size_t shown(const DemoState& state) {
    if (const auto object = state.shownObject()) return *object;
    throw InputError("the scene has no objects to edit");
}
const Material& shownMaterial(const DemoState& state) {
    return state.scene().objects[shown(state)].material;
}
template <class Change> void editMaterial(DemoState& state, Change change) {
    Material edited = shownMaterial(state);
    change(edited);
    state.editMaterial(edited);
}

const Light& lightAt(const Scene& scene, std::size_t light) {
    if (light >= scene.lights.size())
        throw InputError("lights[" + std::to_string(light) + "]: the scene has " +
                         std::to_string(scene.lights.size()) + " light(s)");
    return scene.lights[light];
}
template <class Change> void editLight(DemoState& state, std::size_t light, Change change) {
    (void)lightAt(state.scene(), light);
    state.editValues([&](Scene& scene) { change(scene.lights[light]); });
}

// The drawn view volume with one value changed (DemoState::editViewVolume).
template <class Change> void editVolume(DemoState& state, Change change) {
    Projection edited = state.drawn().projection;
    change(edited);
    state.editViewVolume(edited);
}

// The key (1-5) that sets `mode`, whose words the title takes.
Command shadingKey(ShadingMode mode) {
    switch (mode) {
    case ShadingMode::Flat:
        return Command::Flat;
    case ShadingMode::Gouraud:
        return Command::Gouraud;
    case ShadingMode::Phong:
        return Command::Phong;
    case ShadingMode::Toon:
        return Command::Toon;
    case ShadingMode::Exact:
        break;
    }
    return Command::Exact;
}

ViewKind viewKind(std::string_view text) {
    std::string names;
    for (const ViewName& view : kViewNames) {
        if (view.name == text) return view.kind;
        names += (names.empty() ? "" : ", ") + std::string(view.name);
    }
    throw InputError("view: unknown value " + quotedValue(text) + "; expected one of " + names);
}

// The rows of a kind: an enumerated value of the scene set as a whole (term, overlay, ...), whose change
// the title words as its key `described` does; a material's property; a light's; the view volume's.
template <auto Field, const auto& Values, Command described> ValueSetter wordRow(std::string_view name) {
    return {name, [](const DemoState& s, std::size_t) { return word(toString(s.drawn().*Field)); },
            [](DemoState& s, std::size_t, std::string_view field, std::string_view t) {
                const auto value = parseNameOrThrow(trimmed(t), field, Values);
                s.editValues([&](Scene& scene) { scene.*Field = value; });
                s.describe(described);
            }};
}

template <auto Field, auto Parse> ValueSetter materialRow(std::string_view name) {
    return {name, [](const DemoState& s, std::size_t) { return valueText(shownMaterial(s).*Field); },
            [](DemoState& s, std::size_t, std::string_view field, std::string_view t) {
                const auto value = Parse(t, field);
                editMaterial(s, [&](Material& m) { m.*Field = value; });
            }};
}

template <auto Field, auto Parse> ValueSetter lightRow(std::string_view name) {
    return {name, [](const DemoState& s, std::size_t i) { return valueText(lightAt(s.scene(), i).*Field); },
            [](DemoState& s, std::size_t i, std::string_view field, std::string_view t) {
                const auto value = Parse(t, field);
                editLight(s, i, [&](Light& l) { l.*Field = value; });
            }};
}

template <auto Field> ValueSetter volumeRow(std::string_view name) {
    return {name, [](const DemoState& s, std::size_t) { return valueText(s.drawn().projection.*Field); },
            [](DemoState& s, std::size_t, std::string_view field, std::string_view t) {
                const double value = number(t, field);
                editVolume(s, [&](Projection& p) { p.*Field = value; });
            }};
}

const ValueSetter kSetters[] = {
    {"shading", [](const DemoState& s, std::size_t) { return word(toString(s.drawn().shading)); },
     [](DemoState& s, std::size_t, std::string_view field, std::string_view t) {
         const ShadingMode mode = parseNameOrThrow(trimmed(t), field, kAllShadingModes);
         s.setShading(mode);
         s.describe(shadingKey(mode));
     }},
    {"lighting", [](const DemoState& s, std::size_t) { return word(toString(s.drawn().lighting)); },
     [](DemoState& s, std::size_t, std::string_view field, std::string_view t) {
         s.setLighting(parseNameOrThrow(trimmed(t), field, kLightingModels));
         s.describe(Command::ToggleLighting);
     }},
    {"match_highlight",
     [](const DemoState& s, std::size_t) { return word(s.matchHighlight() ? "true" : "false"); },
     [](DemoState& s, std::size_t, std::string_view field, std::string_view t) {
         s.setMatchHighlight(boolean(t, field));
     }},
    wordRow<&Scene::term, kLightingTerms, Command::NextTerm>("term"),
    wordRow<&Scene::perspectiveMatrix, kPerspectiveMatrices, Command::TogglePerspectiveMatrix>(
        "perspective_matrix"),
    wordRow<&Scene::normalMatrix, kNormalMatrixRules, Command::ToggleNormalMatrix>("normal_matrix"),
    wordRow<&Scene::vertexNormals, kVertexNormals, Command::ToggleNormals>("vertex_normals"),
    wordRow<&Scene::overlay, kOverlays, Command::ToggleOverlay>("overlay"),
    {"view", [](const DemoState& s, std::size_t) { return word(viewNamed(s.drawn().view.kind).name); },
     [](DemoState& s, std::size_t, std::string_view, std::string_view t) {
         s.setView(viewKind(trimmed(t)));
     }},
    {"level", [](const DemoState& s, std::size_t) { return std::to_string(s.level()); },
     [](DemoState& s, std::size_t, std::string_view field, std::string_view t) {
         if (!s.setLevel(integer(t, field))) throw InputError(s.levelRefusal());
         s.describe(Command::LevelUp);
     }},
    {"auto_level", [](const DemoState& s, std::size_t) { return word(s.autoLevel() ? "true" : "false"); },
     [](DemoState& s, std::size_t, std::string_view field, std::string_view t) {
         s.setAutoLevel(boolean(t, field));
         s.describe(Command::AutoLevel);
     }},
    {"projection",
     [](const DemoState& s, std::size_t) { return word(s.orthographic() ? "orthographic" : "perspective"); },
     [](DemoState& s, std::size_t, std::string_view, std::string_view t) {
         const std::string type = trimmed(t);
         if (type != "perspective" && type != "orthographic")
             throw InputError("projection: unknown value " + quotedValue(t) +
                              "; expected one of perspective, orthographic");
         s.setOrthographic(type == "orthographic");
         s.describe(Command::ToggleProjection);
     }},
    volumeRow<&Projection::fovyDeg>("projection.fovy_deg"),
    volumeRow<&Projection::left>("projection.left"),
    volumeRow<&Projection::right>("projection.right"),
    volumeRow<&Projection::bottom>("projection.bottom"),
    volumeRow<&Projection::top>("projection.top"),
    volumeRow<&Projection::near>("projection.near"),
    volumeRow<&Projection::far>("projection.far"),
    {"toon_bands", [](const DemoState& s, std::size_t) { return std::to_string(s.scene().toonBands); },
     [](DemoState& s, std::size_t, std::string_view field, std::string_view t) {
         const int bands = integer(t, field);
         s.editValues([&](Scene& scene) { scene.toonBands = bands; });
     }},
    {"object", [](const DemoState& s, std::size_t) { return std::to_string(s.editedObjectNumber()); },
     [](DemoState& s, std::size_t, std::string_view field, std::string_view t) {
         s.chooseEditedObject(integer(t, field));
     }},
    materialRow<&Material::ambient, vec3>("material.ambient"),
    materialRow<&Material::diffuse, vec3>("material.diffuse"),
    materialRow<&Material::specular, vec3>("material.specular"),
    materialRow<&Material::shininess, number>("material.shininess"),
    {"shape", [](const DemoState& s, std::size_t) { return word(toString(s.shape())); },
     [](DemoState& s, std::size_t, std::string_view field, std::string_view t) {
         s.setShape(parseNameOrThrow(trimmed(t), field, kShapes)); // a mesh comes from a file, not a word
         s.describe(Command::ToggleShape);
     }},
    {"scale", [](const DemoState& s, std::size_t) { return valueText(s.scene().objects[shown(s)].scale); },
     [](DemoState& s, std::size_t, std::string_view field, std::string_view t) {
         s.editScale(vec3(t, field));
     }},
    lightRow<&Light::position, vec3>("lights[].position"),
    lightRow<&Light::direction, vec3>("lights[].direction"),
    lightRow<&Light::ambient, vec3>("lights[].ambient"),
    lightRow<&Light::diffuse, vec3>("lights[].diffuse"),
    lightRow<&Light::specular, vec3>("lights[].specular"),
    lightRow<&Light::attenuation, vec3>("lights[].attenuation"),
    lightRow<&Light::cutoffDeg, number>("lights[].cutoff_deg"),
    lightRow<&Light::exponent, number>("lights[].exponent"),
};

// The row `name` names, and a light's index from "lights[3].cutoff_deg" (the row "lights[].cutoff_deg").
std::pair<const ValueSetter*, std::size_t> rowNamed(std::string_view name) {
    std::string key(name);
    std::size_t light = 0;
    if (name.starts_with("lights[")) {
        const std::size_t close = name.find(']');
        const std::string digits(name.substr(7, close == std::string_view::npos ? 0 : close - 7));
        if (close == std::string_view::npos || digits.empty() ||
            digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 6)
            throw InputError("unknown value " + quotedValue(name));
        light = std::stoul(digits);
        key = "lights[]" + std::string(name.substr(close + 1));
    }
    for (const ValueSetter& row : kSetters)
        if (row.name == key) return {&row, light};
    throw InputError("unknown value " + quotedValue(name));
}

} // namespace

std::span<const ValueSetter> valueSetters() {
    return kSetters;
}

std::string setValue(DemoState& state, std::string_view name, std::string_view text) {
    try {
        const auto [row, light] = rowNamed(name);
        row->set(state, light, name, text);
        return "";
    } catch (const InputError& e) {
        return e.what();
    }
}

std::string readValue(const DemoState& state, std::string_view name) {
    const auto [row, light] = rowNamed(name);
    return row->read(state, light);
}

std::string valueText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

std::string valueText(const glm::dvec3& value) {
    return valueText(value.x) + " " + valueText(value.y) + " " + valueText(value.z);
}

} // namespace shadelab::app
