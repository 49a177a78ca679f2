// One way in for every named value: a vocabulary is an array of an enum's values, each with its
// toString() spelling (lighting.h: shading modes, lighting models, light types; scene.h: projections,
// vertex normals, depth modes, overlays). Every door — the scene's JSON, a command-line flag, the page's
// controls through them — finds a spelling with parseName and refuses one it lacks with the same message:
// "<field>: unknown value "<text>"; expected one of a, b, c".
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "shadelab/errors.h"
#include "shadelab/io/text.h"

namespace shadelab {

// "a, b, c" (or, with `last` " or ", "a, b or c"): the spellings of a vocabulary in its order, for the
// messages and help texts that list them, so that none is typed twice.
template <class Enum, std::size_t N>
std::string joinNames(const std::array<Enum, N>& values, std::string_view last = ", ") {
    std::string out;
    for (std::size_t i = 0; i < N; ++i)
        out.append(i == 0 ? "" : i + 1 == N ? last : ", ").append(toString(values[i]));
    return out;
}

template <class Enum, std::size_t N>
std::optional<Enum> parseName(std::string_view text, const std::array<Enum, N>& values) {
    for (Enum value : values)
        if (toString(value) == text) return value;
    return std::nullopt;
}

// `field` names where the text came from: a JSON path ("shading") or a flag ("--shading").
template <class Enum, std::size_t N>
Enum parseNameOrThrow(std::string_view text, std::string_view field, const std::array<Enum, N>& values) {
    if (const auto value = parseName(text, values)) return *value;
    throw InputError(std::string(field) + ": unknown value " + quotedValue(text) + "; expected one of " +
                     joinNames(values));
}

} // namespace shadelab
