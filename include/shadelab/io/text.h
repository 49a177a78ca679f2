// Text taken from input (file names, scene strings, renderer strings) shown to a person or handed to a tool.
#pragma once

#include <string>
#include <string_view>

namespace shadelab {

// `text` with every byte that could act on a terminal or a script written as \xNN: control characters
// (0x00-0x1f, 0x7f) and bytes that are not part of valid UTF-8. Printable ASCII and valid UTF-8 sequences
// (other than C1 controls) pass unchanged. `keepNewlines` keeps \n and \t (for multi-line messages).
std::string printable(std::string_view text, bool keepNewlines = false);

// User text quoted back in a message: in double quotes, JSON-escaped (so no control character reaches a
// terminal) and cut at kMaxQuotedChars with "..." (so a megabyte string cannot flood the message).
inline constexpr std::size_t kMaxQuotedChars = 40;
std::string quotedValue(std::string_view text);

// ASCII letters upper-cased (labels drawn into pictures: "PHONG SHADING"); other bytes unchanged.
std::string upperAscii(std::string_view text);

} // namespace shadelab
