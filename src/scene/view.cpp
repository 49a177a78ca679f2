#include "shadelab/scene/view.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "shadelab/scene/auto_level.h"
#include "shadelab/scene/scene.h"
#include "shadelab/vocabulary.h"

namespace shadelab {
namespace {

struct Token {
    std::string_view first, second; // names: shading[/lighting]
    std::optional<int> level;
    std::string_view settings; // between { and }, without them; empty for none
    bool braces = false;       // written with {…}, even empty
};

std::string_view trim(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    return s;
}

std::optional<Token> splitToken(std::string_view text, std::string& error) {
    Token token;
    text = trim(text);
    if (const std::size_t open = text.find('{'); open != std::string_view::npos) {
        if (text.back() != '}' || text.find('{', open + 1) != std::string_view::npos ||
            text.find('}') != text.size() - 1) {
            error = "a side's settings are one {…} at its end, e.g. phong{shininess=8}";
            return std::nullopt;
        }
        token.settings = text.substr(open + 1, text.size() - open - 2);
        token.braces = true;
        text = trim(text.substr(0, open));
    }
    if (const std::size_t at = text.find('@'); at != std::string_view::npos) {
        const std::string_view digits = text.substr(at + 1);
        int level = -1;
        const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), level);
        if (ec != std::errc() || end != digits.data() + digits.size() || level < 0 ||
            level > kMaxSubdivisions) {
            error = "level \"" + std::string(digits) + "\" after @ must be a whole number 0.." +
                    std::to_string(kMaxSubdivisions);
            return std::nullopt;
        }
        token.level = level;
        text = text.substr(0, at);
    }
    const std::size_t slash = text.find('/');
    token.first = text.substr(0, slash);
    if (slash != std::string_view::npos) token.second = text.substr(slash + 1);
    return token;
}

// A number as the scene file would take it back: the shortest text that reads as the same double. (Not
// std::to_chars: the browser build's libc++ has no floating-point to_chars or from_chars.)
std::string numberText(double value) {
    char text[32];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, value);
        if (std::strtod(text, nullptr) == value) break;
    }
    // A whole number in its digits: 150, not 1.5e+02.
    if (std::strchr(text, 'e') && value == std::floor(value) && std::abs(value) < 1e15)
        std::snprintf(text, sizeof text, "%.0f", value);
    return text;
}

// A decimal number, the whole of `text`, finite; the "C" locale's decimal point, as JSON's.
std::optional<double> readNumber(std::string_view text) {
    const std::string copy(trim(text));
    if (copy.empty() || copy.find_first_not_of("0123456789+-.eE") != std::string::npos) return std::nullopt;
    char* end = nullptr;
    const double value = std::strtod(copy.c_str(), &end);
    if (end != copy.c_str() + copy.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

// A colour: one number (a grey) or three separated by spaces, each 0..kMaxColorComponent.
std::optional<glm::dvec3> readColor(std::string_view text) {
    std::vector<double> values;
    text = trim(text);
    while (!text.empty()) {
        const std::size_t space = text.find(' ');
        const auto value = readNumber(text.substr(0, space));
        if (!value || *value < 0 || *value > kMaxColorComponent) return std::nullopt;
        values.push_back(*value);
        text = space == std::string_view::npos ? std::string_view{} : trim(text.substr(space));
    }
    if (values.size() == 1) return glm::dvec3(values[0]);
    if (values.size() == 3) return glm::dvec3(values[0], values[1], values[2]);
    return std::nullopt;
}

std::string settingsHelp() {
    std::string terms = joinNames(kLightingTerms), rules = joinNames(kNormalMatrixRules);
    std::replace(terms.begin(), terms.end(), ',', '|');
    std::replace(rules.begin(), rules.end(), ',', '|');
    std::erase(terms, ' ');
    std::erase(rules, ' ');
    return "term=" + terms + ", normal_matrix=" + rules +
           ", ambient=, diffuse=, specular= (a grey or three numbers >= 0: diffuse=0.7 0.2 0.2), shininess= "
           "(>= 1)";
}

// "term=specular, shininess=8": each setting once; returns the reason on failure.
std::string readSettings(std::string_view text, SplitSide& side) {
    for (std::string_view rest = text; !trim(rest).empty();) {
        const std::size_t comma = rest.find(',');
        const std::string_view setting = trim(rest.substr(0, comma));
        rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
        const std::size_t equals = setting.find('=');
        const std::string_view key = trim(setting.substr(0, equals));
        const std::string_view value =
            equals == std::string_view::npos ? "" : trim(setting.substr(equals + 1));
        const std::string shown = "\"" + std::string(setting) + "\"";
        if (equals == std::string_view::npos || value.empty())
            return "a side's setting " + shown + " is key=value; expected " + settingsHelp();
        const auto once = [&](bool set) {
            return set ? "\"" + std::string(key) + "\" is set twice in one side" : std::string();
        };
        if (key == "term") {
            if (auto error = once(side.term.has_value()); !error.empty()) return error;
            for (const LightingTerm term : kLightingTerms)
                if (value == toString(term)) side.term = term;
            if (!side.term) return "term in " + shown + " must be " + joinNames(kLightingTerms, " or ");
        } else if (key == "normal_matrix") {
            if (auto error = once(side.normalMatrix.has_value()); !error.empty()) return error;
            for (const NormalMatrixRule rule : kNormalMatrixRules)
                if (value == toString(rule)) side.normalMatrix = rule;
            if (!side.normalMatrix)
                return "normal_matrix in " + shown + " must be " + joinNames(kNormalMatrixRules, " or ");
        } else if (key == "shininess") {
            if (auto error = once(side.shininess.has_value()); !error.empty()) return error;
            side.shininess = readNumber(value);
            if (!side.shininess || *side.shininess < 1 || *side.shininess > kMaxColorComponent)
                return "shininess in " + shown + " must be a number >= 1 (pow(0, 0) is undefined, DESIGN §3)";
        } else if (key == "ambient" || key == "diffuse" || key == "specular") {
            std::optional<glm::dvec3>& color = key == "ambient"   ? side.ambient
                                               : key == "diffuse" ? side.diffuse
                                                                  : side.specular;
            if (auto error = once(color.has_value()); !error.empty()) return error;
            color = readColor(value);
            if (!color)
                return std::string(key) + " in " + shown +
                       " must be a grey or three numbers >= 0 separated by spaces, e.g. " + std::string(key) +
                       "=0.7 0.2 0.2";
        } else {
            return "unknown setting \"" + std::string(key) + "\" in a side; expected " + settingsHelp();
        }
    }
    return "";
}

std::string colorText(const glm::dvec3& c) {
    if (c.x == c.y && c.y == c.z) return numberText(c.x);
    return numberText(c.x) + " " + numberText(c.y) + " " + numberText(c.z);
}

std::string settingsText(const SplitSide& side) {
    std::vector<std::string> settings;
    if (side.term) settings.push_back("term=" + std::string(toString(*side.term)));
    if (side.normalMatrix) settings.push_back("normal_matrix=" + std::string(toString(*side.normalMatrix)));
    if (side.ambient) settings.push_back("ambient=" + colorText(*side.ambient));
    if (side.diffuse) settings.push_back("diffuse=" + colorText(*side.diffuse));
    if (side.specular) settings.push_back("specular=" + colorText(*side.specular));
    if (side.shininess) settings.push_back("shininess=" + numberText(*side.shininess));
    if (settings.empty()) return "";
    std::string text = "{";
    for (std::size_t i = 0; i < settings.size(); ++i) text += (i ? "," : "") + settings[i];
    return text + "}";
}

bool hasSettings(const SplitSide& side) {
    return side.term || side.normalMatrix || side.ambient || side.diffuse || side.specular || side.shininess;
}

// The comma between the two sides: the one outside any {…}.
std::optional<std::size_t> sidesComma(std::string_view sides) {
    std::optional<std::size_t> found;
    int depth = 0;
    for (std::size_t i = 0; i < sides.size(); ++i) {
        if (sides[i] == '{') ++depth;
        if (sides[i] == '}') --depth;
        if (sides[i] == ',' && depth == 0) {
            if (found) return std::nullopt;
            found = i;
        }
    }
    return found;
}

} // namespace

std::string toString(const SplitSide& side) {
    if (side.view) return std::string(viewNamed(*side.view).name);
    if (!side.shading && !side.lighting && !side.level && !hasSettings(side)) return "scene";
    std::string text;
    if (side.shading) text += toString(*side.shading);
    if (side.lighting) text += (side.shading ? "/" : "") + std::string(toString(*side.lighting));
    if (side.level) text += "@" + std::to_string(*side.level);
    return text + settingsText(side);
}

std::string toString(const View& view) {
    if (view.kind == ViewKind::Split)
        return std::string(view.layout == SplitLayout::SideBySide ? "side-by-side:" : "split:") +
               toString(view.left) + "," + toString(view.right);
    return std::string(viewNamed(view.kind).name);
}

static View viewOf(ViewKind kind) {
    View view;
    view.kind = kind;
    return view;
}

namespace {

// "scene, error, profile, outside, ndc" (`last` before the last): the views `named` picks, from their
// one table.
template <class Pick> std::string viewNames(Pick named, std::string_view last) {
    std::vector<std::string_view> names;
    for (const ViewName& view : kViewNames)
        if (named(view.kind)) names.push_back(view.name);
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i)
        out.append(i == 0 ? "" : i + 1 == names.size() ? last : ", ").append(names[i]);
    return out;
}

// A split's side that is a whole view: the scene as it is, or a view of it from an observer.
bool wholeSideView(ViewKind kind) {
    return kind == ViewKind::Scene || observed(kind);
}

} // namespace

ViewParse parseView(std::string_view text) {
    const std::string expected =
        "expected " + viewNames([](ViewKind kind) { return kind != ViewKind::Split; }, ", ") +
        ", split:A,B or side-by-side:A,B (A and B each shading[/lighting][@level][{settings}], e.g. "
        "split:gouraud,phong or side-by-side:phong{shininess=8},phong{shininess=150})";
    for (const ViewName& name : kViewNames)
        if (name.kind != ViewKind::Split && text == name.name) return {viewOf(name.kind), ""};
    const bool sideBySide = text.starts_with("side-by-side:");
    if (!text.starts_with("split:") && !sideBySide) return {std::nullopt, expected};
    const std::string_view sides = text.substr(sideBySide ? 13 : 6);
    const auto found = sidesComma(sides);
    if (!found)
        return {std::nullopt, "a split names two sides separated by one comma (outside their {…}), e.g. "
                              "split:gouraud,phong"};
    const std::size_t comma = *found;
    std::string error;
    const auto a = splitToken(sides.substr(0, comma), error);
    if (!a) return {std::nullopt, error};
    const auto b = splitToken(sides.substr(comma + 1), error);
    if (!b) return {std::nullopt, error};
    // One lone name that can only be a lighting model makes the other lone name a lighting model too.
    auto onlyLighting = [](const Token& t) {
        return t.second.empty() && !parseShadingMode(t.first) && parseLightingModel(t.first);
    };
    const bool lightingSplit = onlyLighting(*a) || onlyLighting(*b);
    View view = viewOf(ViewKind::Split);
    if (sideBySide) view.layout = SplitLayout::SideBySide;
    for (auto [token, side] : {std::pair{&*a, &view.left}, std::pair{&*b, &view.right}}) {
        if (const std::string settingsError = readSettings(token->settings, *side); !settingsError.empty())
            return {std::nullopt, settingsError};
        // A whole view for a side: the scene as it is, or the outside or NDC view of it.
        if (token->second.empty() && !token->level && !token->braces) {
            const auto whole =
                std::find_if(kViewNames.begin(), kViewNames.end(), [name = token->first](const ViewName& v) {
                    return v.name == name && wholeSideView(v.kind);
                });
            if (whole != kViewNames.end()) {
                if (whole->kind != ViewKind::Scene) side->view = whole->kind;
                continue;
            }
        }
        side->level = token->level;
        if (token->first.empty() && token->second.empty()) {
            if (!token->level && !hasSettings(*side))
                return {std::nullopt, "a split side is empty; " + expected};
            continue;
        }
        if (token->first == "scene" && token->second.empty()) continue; // "scene{shininess=8}"
        const bool loneLighting = token->second.empty() && lightingSplit && parseLightingModel(token->first);
        if (!loneLighting) {
            side->shading = parseShadingMode(token->first);
            if (!side->shading)
                return {std::nullopt, "unknown shading \"" + std::string(token->first) +
                                          "\" in a split side; expected " +
                                          joinNames(kAllShadingModes, " or ") + " (or " +
                                          viewNames(wholeSideView, " or ") + " alone)"};
        }
        if (loneLighting || !token->second.empty()) {
            const std::string_view lighting = loneLighting ? token->first : token->second;
            side->lighting = parseLightingModel(lighting);
            if (!side->lighting)
                return {std::nullopt, "unknown lighting \"" + std::string(lighting) +
                                          "\" in a split side; expected " +
                                          joinNames(kLightingModels, " or ")};
        }
    }
    if (view.left == view.right)
        return {std::nullopt, "both sides of the split are the same; name two different configurations"};
    return {view, ""};
}

void applySplitSideValues(Scene& scene, const SplitSide& side) {
    if (side.shading) scene.shading = *side.shading;
    if (side.lighting) scene.lighting = *side.lighting;
    if (side.term) scene.term = *side.term;
    if (side.normalMatrix) scene.normalMatrix = *side.normalMatrix;
    for (SceneObject& object : scene.objects) {
        if (side.level) object.subdivisions = *side.level;
        Material& m = object.material;
        if (side.ambient) m.ambient = *side.ambient;
        if (side.diffuse) m.diffuse = *side.diffuse;
        if (side.specular) m.specular = *side.specular;
        if (side.shininess) m.shininess = *side.shininess;
    }
}

} // namespace shadelab
