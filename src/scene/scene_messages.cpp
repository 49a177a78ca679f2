// The pieces of every scene message (scene_internal.h): numbers as the command line and the page both word
// them, JSON paths, the fail helpers that prefix a message with its path, and JSON values and key lists as
// messages name them.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <nlohmann/json.hpp>

#include "scene/scene_internal.h"
#include "shadelab/errors.h"
#include "shadelab/io/text.h"

namespace shadelab::detail {

// ---- message pieces ----

// What std::to_chars(value) gives: the fewest significant digits that read back as `value`, in fixed or
// scientific notation, whichever is shorter (fixed on a tie). Written out because the browser build's
// libc++ has no floating-point to_chars, and the page must word a message exactly as the command line does.
std::string formatNumber(double value) {
    if (!std::isfinite(value)) return std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf";
    std::array<char, 40> scientific{};
    int digits = 1;
    for (; digits < 17; ++digits) {
        std::snprintf(scientific.data(), scientific.size(), "%.*e", digits - 1, value);
        if (std::strtod(scientific.data(), nullptr) == value) break;
    }
    std::snprintf(scientific.data(), scientific.size(), "%.*e", digits - 1, value);
    const int exponent = std::atoi(std::strchr(scientific.data(), 'e') + 1);
    std::array<char, 400> fixed{}; // up to 309 integer digits
    std::snprintf(fixed.data(), fixed.size(), "%.*f", std::max(0, digits - 1 - exponent), value);
    const std::string a(fixed.data()), b(scientific.data());
    return a.size() <= b.size() ? a : b;
}

std::string formatVec(const glm::dvec3& v) {
    return "[" + formatNumber(v.x) + ", " + formatNumber(v.y) + ", " + formatNumber(v.z) + "]";
}

// ---- JSON paths: objects[0].material.diffuse[2] ----

namespace {

bool isPlainKey(std::string_view key) {
    if (key.empty() || key.size() > kMaxQuotedChars) return false; // a long key is quoted, and so truncated
    for (char c : key)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
    return true;
}

} // namespace

std::string keyPath(std::string_view parent, std::string_view key) {
    if (!isPlainKey(key)) return std::string(parent) + "[" + quotedValue(key) + "]";
    return parent.empty() ? std::string(key) : std::string(parent) + "." + std::string(key);
}

std::string indexPath(std::string_view parent, std::size_t index) {
    return std::string(parent) + "[" + std::to_string(index) + "]";
}

[[noreturn]] void fail(std::string_view path, std::string_view message) {
    throw InputError(path.empty() ? std::string(message) : std::string(path) + ": " + std::string(message));
}

// Errors from camera.h and sphere.h may already name the field; add the path only where they don't.
[[noreturn]] void failWithin(std::string_view path, const InputError& error) {
    std::string_view message = error.what();
    if (message.starts_with(path)) throw error;
    fail(path, message);
}

[[noreturn]] void failOutOfRange(IntRange range, std::string_view shown, std::string_view path) {
    fail(path, "must be between " + std::to_string(range.lo) + " and " + std::to_string(range.hi) + ", got " +
                   std::string(shown));
}

// ---- values as messages name them ----

std::string describe(const Json& value) {
    switch (value.type()) {
    case Json::value_t::null:
        return "null";
    case Json::value_t::boolean:
        return value.get<bool>() ? "true" : "false";
    case Json::value_t::string:
        return "string " + quotedValue(value.get_ref<const std::string&>());
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
        return "number " + formatNumber(value.get<double>());
    case Json::value_t::array:
        return "array of " + std::to_string(value.size()) + (value.size() == 1 ? " element" : " elements");
    case Json::value_t::object:
        return "object";
    default:
        return "unsupported value";
    }
}

std::string joinKeys(std::span<const std::string_view> keys) {
    std::string out;
    for (std::string_view key : keys) out += (out.empty() ? "" : ", ") + std::string(key);
    return out;
}

} // namespace shadelab::detail
