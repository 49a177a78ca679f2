// Text taken from input (file names, scene strings, renderer strings) shown to a person or handed to a tool.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace shadelab {

// `text` with every byte that could act on a terminal or a script written as \xNN: control characters
// (0x00-0x1f, 0x7f, the C1 controls U+0080-009F), Unicode's format characters and line separators (the
// bidi overrides U+202A-202E and U+2066-2069 that reorder a line, U+200B and U+FEFF that are invisible,
// U+2028), and bytes that are not part of valid UTF-8. Printable ASCII and the other valid UTF-8 sequences
// pass unchanged. `keepNewlines` keeps \n and \t (for multi-line messages).
std::string printable(std::string_view text, bool keepNewlines = false);

// The first character printable() would escape, named for a message ("U+202E (an invisible format
// character, or one that reorders or breaks the line) at byte 4"), or "" when there is none.
std::string unprintableCharacter(std::string_view text, bool keepNewlines = false);

// User text quoted back in a message: in double quotes, JSON-escaped (so no control character reaches a
// terminal) and cut at kMaxQuotedChars with "..." (so a megabyte string cannot flood the message).
inline constexpr std::size_t kMaxQuotedChars = 40;
std::string quotedValue(std::string_view text);

// `text` as a whole number of 1 to `maxDigits` ASCII digits (no sign, no space), or nullopt: the flags'
// sizes and levels ("512", "4"), read without <regex> (half of a small file's compile time).
std::optional<int> digitsValue(std::string_view text, std::size_t maxDigits);

// ASCII letters upper-cased (labels drawn into pictures: "PHONG SHADING"); other bytes unchanged.
std::string upperAscii(std::string_view text);

} // namespace shadelab
