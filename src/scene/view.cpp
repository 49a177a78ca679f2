#include "shadelab/scene/view.h"

#include <charconv>
#include <vector>

#include "shadelab/geometry/subdivision.h"

namespace shadelab {
namespace {

struct Token {
    std::string_view first, second; // names: shading[/lighting]
    std::optional<int> level;
};

std::string_view trim(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    return s;
}

std::optional<Token> splitToken(std::string_view text, std::string& error) {
    Token token;
    text = trim(text);
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

} // namespace

std::string toString(const SplitSide& side) {
    if (side.view) return *side.view == ViewKind::Ndc ? "ndc" : "outside";
    if (!side.shading && !side.lighting && !side.level) return "scene";
    std::string text;
    if (side.shading) text += toString(*side.shading);
    if (side.lighting) text += (side.shading ? "/" : "") + std::string(toString(*side.lighting));
    if (side.level) text += "@" + std::to_string(*side.level);
    return text;
}

std::string toString(const View& view) {
    switch (view.kind) {
    case ViewKind::Scene:
        return "scene";
    case ViewKind::Error:
        return "error";
    case ViewKind::Profile:
        return "profile";
    case ViewKind::Outside:
        return "outside";
    case ViewKind::Ndc:
        return "ndc";
    case ViewKind::Split:
        return "split:" + toString(view.left) + "," + toString(view.right);
    }
    return "?";
}

static View viewOf(ViewKind kind) {
    View view;
    view.kind = kind;
    return view;
}

ViewParse parseView(std::string_view text) {
    constexpr const char* kExpected =
        "expected scene, error, profile, outside, ndc or split:A,B (A and B each "
        "shading[/lighting][@level], e.g. split:gouraud,phong)";
    if (text == "scene") return {View{}, ""};
    if (text == "error") return {viewOf(ViewKind::Error), ""};
    if (text == "profile") return {viewOf(ViewKind::Profile), ""};
    if (text == "outside") return {viewOf(ViewKind::Outside), ""};
    if (text == "ndc") return {viewOf(ViewKind::Ndc), ""};
    if (!text.starts_with("split:")) return {std::nullopt, kExpected};
    const std::string_view sides = text.substr(6);
    const std::size_t comma = sides.find(',');
    if (comma == std::string_view::npos || sides.find(',', comma + 1) != std::string_view::npos)
        return {std::nullopt, "a split names two sides separated by one comma, e.g. split:gouraud,phong"};
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
    for (auto [token, side] : {std::pair{&*a, &view.left}, std::pair{&*b, &view.right}}) {
        // A whole view for a side: the scene as it is, or the outside or NDC view of it.
        if (token->second.empty() && !token->level &&
            (token->first == "scene" || token->first == "outside" || token->first == "ndc")) {
            if (token->first != "scene")
                side->view = token->first == "outside" ? ViewKind::Outside : ViewKind::Ndc;
            continue;
        }
        side->level = token->level;
        if (token->first.empty() && token->second.empty()) {
            if (!token->level) return {std::nullopt, "a split side is empty; " + std::string(kExpected)};
            continue;
        }
        const bool loneLighting = token->second.empty() && lightingSplit && parseLightingModel(token->first);
        if (!loneLighting) {
            side->shading = parseShadingMode(token->first);
            if (!side->shading)
                return {std::nullopt, "unknown shading \"" + std::string(token->first) +
                                          "\" in a split side; expected flat, gouraud, phong, toon or exact "
                                          "(or scene, outside or ndc alone)"};
        }
        if (loneLighting || !token->second.empty()) {
            const std::string_view lighting = loneLighting ? token->first : token->second;
            side->lighting = parseLightingModel(lighting);
            if (!side->lighting)
                return {std::nullopt, "unknown lighting \"" + std::string(lighting) +
                                          "\" in a split side; expected phong or blinn-phong"};
        }
    }
    if (view.left == view.right)
        return {std::nullopt, "both sides of the split are the same; name two different configurations"};
    return {view, ""};
}

} // namespace shadelab
