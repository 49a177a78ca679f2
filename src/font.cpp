// A built-in 5×7 bitmap font for labelling report and showcase images, so no font file or library is needed.
#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <string_view>

#include "shadelab/image.h"

namespace shadelab {

namespace {

constexpr int kGlyphWidth = 5, kGlyphHeight = 7;
constexpr int kAdvance = kGlyphWidth + 1; // one blank column between glyphs

// Rows top to bottom; bit 4 is the leftmost column.
struct Glyph {
    char32_t code;
    std::array<std::uint8_t, kGlyphHeight> rows;
};

constexpr char32_t kTimes = U'\u00D7';

constexpr Glyph kGlyphs[] = {
    {U'A', {0b01110, 0b10001, 0b10001, 0b10001, 0b11111, 0b10001, 0b10001}},
    {U'B', {0b11110, 0b10001, 0b10001, 0b11110, 0b10001, 0b10001, 0b11110}},
    {U'C', {0b01110, 0b10001, 0b10000, 0b10000, 0b10000, 0b10001, 0b01110}},
    {U'D', {0b11100, 0b10010, 0b10001, 0b10001, 0b10001, 0b10010, 0b11100}},
    {U'E', {0b11111, 0b10000, 0b10000, 0b11110, 0b10000, 0b10000, 0b11111}},
    {U'F', {0b11111, 0b10000, 0b10000, 0b11110, 0b10000, 0b10000, 0b10000}},
    {U'G', {0b01110, 0b10001, 0b10000, 0b10111, 0b10001, 0b10001, 0b01111}},
    {U'H', {0b10001, 0b10001, 0b10001, 0b11111, 0b10001, 0b10001, 0b10001}},
    {U'I', {0b01110, 0b00100, 0b00100, 0b00100, 0b00100, 0b00100, 0b01110}},
    {U'J', {0b00111, 0b00010, 0b00010, 0b00010, 0b00010, 0b10010, 0b01100}},
    {U'K', {0b10001, 0b10010, 0b10100, 0b11000, 0b10100, 0b10010, 0b10001}},
    {U'L', {0b10000, 0b10000, 0b10000, 0b10000, 0b10000, 0b10000, 0b11111}},
    {U'M', {0b10001, 0b11011, 0b10101, 0b10101, 0b10001, 0b10001, 0b10001}},
    {U'N', {0b10001, 0b10001, 0b11001, 0b10101, 0b10011, 0b10001, 0b10001}},
    {U'O', {0b01110, 0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b01110}},
    {U'P', {0b11110, 0b10001, 0b10001, 0b11110, 0b10000, 0b10000, 0b10000}},
    {U'Q', {0b01110, 0b10001, 0b10001, 0b10001, 0b10101, 0b10010, 0b01101}},
    {U'R', {0b11110, 0b10001, 0b10001, 0b11110, 0b10100, 0b10010, 0b10001}},
    {U'S', {0b01111, 0b10000, 0b10000, 0b01110, 0b00001, 0b00001, 0b11110}},
    {U'T', {0b11111, 0b00100, 0b00100, 0b00100, 0b00100, 0b00100, 0b00100}},
    {U'U', {0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b01110}},
    {U'V', {0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b01010, 0b00100}},
    {U'W', {0b10001, 0b10001, 0b10001, 0b10101, 0b10101, 0b10101, 0b01010}},
    {U'X', {0b10001, 0b10001, 0b01010, 0b00100, 0b01010, 0b10001, 0b10001}},
    {U'Y', {0b10001, 0b10001, 0b10001, 0b01010, 0b00100, 0b00100, 0b00100}},
    {U'Z', {0b11111, 0b00001, 0b00010, 0b00100, 0b01000, 0b10000, 0b11111}},
    {U'0', {0b01110, 0b10001, 0b10011, 0b10101, 0b11001, 0b10001, 0b01110}},
    {U'1', {0b00100, 0b01100, 0b00100, 0b00100, 0b00100, 0b00100, 0b01110}},
    {U'2', {0b01110, 0b10001, 0b00001, 0b00010, 0b00100, 0b01000, 0b11111}},
    {U'3', {0b11111, 0b00010, 0b00100, 0b00010, 0b00001, 0b10001, 0b01110}},
    {U'4', {0b00010, 0b00110, 0b01010, 0b10010, 0b11111, 0b00010, 0b00010}},
    {U'5', {0b11111, 0b10000, 0b11110, 0b00001, 0b00001, 0b10001, 0b01110}},
    {U'6', {0b00110, 0b01000, 0b10000, 0b11110, 0b10001, 0b10001, 0b01110}},
    {U'7', {0b11111, 0b00001, 0b00010, 0b00100, 0b01000, 0b01000, 0b01000}},
    {U'8', {0b01110, 0b10001, 0b10001, 0b01110, 0b10001, 0b10001, 0b01110}},
    {U'9', {0b01110, 0b10001, 0b10001, 0b01111, 0b00001, 0b00010, 0b01100}},
    {U' ', {0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b00000}},
    {U'-', {0b00000, 0b00000, 0b00000, 0b11111, 0b00000, 0b00000, 0b00000}},
    {U'+', {0b00000, 0b00100, 0b00100, 0b11111, 0b00100, 0b00100, 0b00000}},
    {U'/', {0b00000, 0b00001, 0b00010, 0b00100, 0b01000, 0b10000, 0b00000}},
    {U'.', {0b00000, 0b00000, 0b00000, 0b00000, 0b00000, 0b01100, 0b01100}},
    {U':', {0b00000, 0b01100, 0b01100, 0b00000, 0b01100, 0b01100, 0b00000}},
    {U'(', {0b00010, 0b00100, 0b01000, 0b01000, 0b01000, 0b00100, 0b00010}},
    {U')', {0b01000, 0b00100, 0b00010, 0b00010, 0b00010, 0b00100, 0b01000}},
    {kTimes, {0b00000, 0b10001, 0b01010, 0b00100, 0b01010, 0b10001, 0b00000}},
};

// Drawn for any character the table lacks, so a missing glyph is visible rather than silently blank.
constexpr Glyph kUnknown = {0, {0b11111, 0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b11111}};

const Glyph& findGlyph(char32_t code) {
    if (code >= U'a' && code <= U'z') code -= U'a' - U'A';
    const auto* glyph = std::find_if(std::begin(kGlyphs), std::end(kGlyphs),
                                     [code](const Glyph& g) { return g.code == code; });
    return glyph == std::end(kGlyphs) ? kUnknown : *glyph;
}

// Decodes the UTF-8 character at text[i] and advances i past it. A malformed sequence yields one
// unknown character, so a stray multi-byte character draws one box rather than one per byte.
char32_t nextChar(std::string_view text, std::size_t& i) {
    const auto lead = static_cast<unsigned char>(text[i++]);
    if (lead < 0x80) return lead;
    const int continuations = lead >= 0xF0 ? 3 : lead >= 0xE0 ? 2 : lead >= 0xC0 ? 1 : 0;
    if (continuations == 0) return kUnknown.code;
    char32_t code = lead & (0x3F >> continuations);
    for (int n = 0; n < continuations; ++n) {
        if (i == text.size() || (static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) return kUnknown.code;
        code = (code << 6) | (static_cast<unsigned char>(text[i++]) & 0x3F);
    }
    return code;
}

std::size_t countChars(std::string_view text) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < text.size(); ++count) nextChar(text, i);
    return count;
}

// Positions are 64-bit so a huge scale or a far-off origin cannot overflow; only font pixels that touch
// the canvas reach fillRect, which clips the rest.
void drawGlyph(Image& canvas, long long x, long long y, const Glyph& glyph, int scale, glm::u8vec4 color) {
    for (int row = 0; row < kGlyphHeight; ++row) {
        const long long top = y + (long long)row * scale;
        if (top >= canvas.height || top + scale <= 0) continue;
        for (int col = 0; col < kGlyphWidth; ++col) {
            const long long left = x + (long long)col * scale;
            if (!(glyph.rows[row] & (0x10 >> col)) || left >= canvas.width || left + scale <= 0) continue;
            fillRect(canvas, int(left), int(top), scale, scale, color); // in (−scale, size): fits an int
        }
    }
}

} // namespace

void drawText(Image& canvas, int x, int y, std::string_view text, int scale, glm::u8vec4 color) {
    if (scale < 1) return;
    long long penX = x;
    for (std::size_t i = 0; i < text.size() && penX < canvas.width;) {
        drawGlyph(canvas, penX, y, findGlyph(nextChar(text, i)), scale, color);
        penX += (long long)kAdvance * scale;
    }
}

// (6n − 1)·scale: the trailing gap after the last glyph is not part of the text.
int textWidth(std::string_view text, int scale) {
    const std::size_t count = countChars(text);
    if (count == 0 || scale < 1) return 0;
    const long long width = ((long long)kAdvance * (long long)count - 1) * scale;
    return int(std::min(width, (long long)INT_MAX));
}

} // namespace shadelab
