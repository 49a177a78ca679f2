#include "shadelab/io/text.h"

#include <array>
#include <cctype>
#include <cstdio>
#include <utility>

#include <nlohmann/json.hpp>

namespace shadelab {

namespace {

// Unicode's format characters (general category Cf) and its line and paragraph separators (Zl, Zp):
// invisible (U+200B, U+FEFF), or acting on the text around them: U+202A-202E and U+2066-2069 reorder a
// terminal's line (the "Trojan Source" bidi overrides), U+2028 breaks it. Ranges from Unicode 15's
// UnicodeData.txt.
constexpr std::pair<char32_t, char32_t> kFormatCharacters[] = {
    {0x00AD, 0x00AD},   {0x0600, 0x0605},   {0x061C, 0x061C},   {0x06DD, 0x06DD},   {0x070F, 0x070F},
    {0x0890, 0x0891},   {0x08E2, 0x08E2},   {0x180E, 0x180E},   {0x200B, 0x200F},   {0x2028, 0x202E},
    {0x2060, 0x2064},   {0x2066, 0x206F},   {0xFEFF, 0xFEFF},   {0xFFF9, 0xFFFB},   {0x110BD, 0x110BD},
    {0x110CD, 0x110CD}, {0x13430, 0x1343F}, {0x1BCA0, 0x1BCA3}, {0x1D173, 0x1D17A}, {0xE0001, 0xE0001},
    {0xE0020, 0xE007F}};

bool isFormatCharacter(char32_t code) {
    for (const auto& [first, last] : kFormatCharacters)
        if (code >= first && code <= last) return true;
    return false;
}

// The code point of the valid UTF-8 sequence starting at text[i] and its length, or length 0.
struct Utf8Char {
    char32_t code = 0;
    std::size_t length = 0;
};

Utf8Char decodeUtf8(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(i);
    std::size_t length = 0;
    unsigned min = 0;
    unsigned code = 0;
    if (lead >= 0xc2 && lead <= 0xdf) {
        length = 2, min = 0x80, code = lead & 0x1fu;
    } else if (lead >= 0xe0 && lead <= 0xef) {
        length = 3, min = 0x800, code = lead & 0x0fu;
    } else if (lead >= 0xf0 && lead <= 0xf4) {
        length = 4, min = 0x10000, code = lead & 0x07u;
    } else {
        return {};
    }
    if (i + length > text.size()) return {};
    for (std::size_t k = 1; k < length; ++k) {
        if ((byte(i + k) & 0xc0u) != 0x80u) return {};
        code = (code << 6) | (byte(i + k) & 0x3fu);
    }
    const bool surrogate = code >= 0xd800 && code <= 0xdfff;
    if (code < min || code > 0x10ffff || surrogate) return {};
    return {code, length};
}

// The length of the valid UTF-8 sequence starting at text[i] that is neither a C1 control nor a format
// character, or 0.
std::size_t utf8Length(std::string_view text, std::size_t i) {
    const Utf8Char c = decodeUtf8(text, i);
    const bool c1 = c.code >= 0x80 && c.code <= 0x9f;
    return c1 || isFormatCharacter(c.code) ? 0 : c.length;
}

std::string codePointName(char32_t code) {
    std::array<char, 16> name{};
    std::snprintf(name.data(), name.size(), "U+%04X", unsigned(code));
    return name.data();
}

} // namespace

std::string printable(std::string_view text, bool keepNewlines) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
            ++i;
            continue;
        }
        if (keepNewlines && (c == '\n' || c == '\t')) {
            out += static_cast<char>(c);
            ++i;
            continue;
        }
        if (c >= 0x80) {
            if (const std::size_t length = utf8Length(text, i)) {
                out.append(text.substr(i, length));
                i += length;
                continue;
            }
        }
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
        out += escaped;
        ++i;
    }
    return out;
}

std::string unprintableCharacter(std::string_view text, bool keepNewlines) {
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        const bool plain = (c >= 0x20 && c < 0x7f) || (keepNewlines && (c == '\n' || c == '\t'));
        if (plain) {
            ++i;
            continue;
        }
        const std::string at = " at byte " + std::to_string(i);
        if (c < 0x80) return codePointName(c) + " (a control character)" + at;
        const Utf8Char decoded = decodeUtf8(text, i);
        if (decoded.length == 0) {
            std::array<char, 8> hex{};
            std::snprintf(hex.data(), hex.size(), "0x%02x", c);
            return std::string("the byte ") + hex.data() + " (not UTF-8)" + at;
        }
        if (decoded.code <= 0x9f) return codePointName(decoded.code) + " (a control character)" + at;
        if (isFormatCharacter(decoded.code))
            return codePointName(decoded.code) +
                   " (an invisible format character, or one that reorders or breaks the line)" + at;
        i += decoded.length;
    }
    return {};
}

// User text goes back out JSON-escaped and truncated, so a key full of control characters or a megabyte
// string cannot garble the terminal or the message.
std::string quotedValue(std::string_view text) {
    bool truncated = text.size() > kMaxQuotedChars;
    std::string shown(text.substr(0, kMaxQuotedChars));
    std::string out = nlohmann::json(shown).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    if (truncated) out.insert(out.size() - 1, "...");
    return out;
}

std::string upperAscii(std::string_view text) {
    std::string out(text);
    for (char& c : out)
        if (c >= 'a' && c <= 'z') c = char(c - 'a' + 'A');
    return out;
}

std::optional<int> digitsValue(std::string_view text, std::size_t maxDigits) {
    if (text.empty() || text.size() > maxDigits || maxDigits > 9) return std::nullopt;
    int value = 0;
    for (const char c : text) {
        if (c < '0' || c > '9') return std::nullopt;
        value = value * 10 + (c - '0');
    }
    return value;
}

} // namespace shadelab
