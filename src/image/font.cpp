// Labels on the showcase and the teaching views, through a real font rasterizer: stb_truetype (Debian's
// libstb-dev) and DejaVu Sans Mono Bold (fonts-dejavu-core), embedded in the binary at build time
// (cmake/embed_files.cmake), so nothing depends on the working directory and the browser build has it too.
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#define STB_TRUETYPE_IMPLEMENTATION
#define STBTT_STATIC
#include <stb/stb_truetype.h>

#include "image/font_data.h"
#include "shadelab/errors.h"
#include "shadelab/image/image.h"

namespace shadelab {
namespace {

constexpr const char* kFontFile = "DejaVuSansMono-Bold.ttf";

// The font, parsed once. Throws if the embedded file is missing or unreadable (a build problem).
const stbtt_fontinfo& font() {
    static const stbtt_fontinfo info = [] {
        const auto data = embeddedFont(kFontFile);
        stbtt_fontinfo parsed{};
        if (!data || !stbtt_InitFont(&parsed, reinterpret_cast<const unsigned char*>(data->data()),
                                     stbtt_GetFontOffsetForIndex(
                                         reinterpret_cast<const unsigned char*>(data->data()), 0)))
            throw RuntimeError(std::string("the embedded font ") + kFontFile + " cannot be read");
        return parsed;
    }();
    return info;
}

float pixelScale(int scale) {
    return stbtt_ScaleForPixelHeight(&font(), float(textLineHeight(scale)));
}

// Decodes the UTF-8 character at text[i] and advances i past it; a malformed sequence is U+FFFD.
char32_t nextChar(std::string_view text, std::size_t& i) {
    const auto lead = static_cast<unsigned char>(text[i++]);
    if (lead < 0x80) return lead;
    const int continuations = lead >= 0xF0 ? 3 : lead >= 0xE0 ? 2 : lead >= 0xC0 ? 1 : 0;
    if (continuations == 0) return U'\uFFFD';
    char32_t code = lead & (0x3F >> continuations);
    for (int n = 0; n < continuations; ++n) {
        if (i == text.size() || (static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) return U'\uFFFD';
        code = (code << 6) | (static_cast<unsigned char>(text[i++]) & 0x3F);
    }
    return code;
}

// `color` over the canvas pixel with the glyph's coverage (0..255) as extra opacity.
void blend(std::uint8_t* pixel, glm::u8vec4 color, int coverage) {
    const int alpha = color.w * coverage / 255;
    for (int c = 0; c < 3; ++c) pixel[c] = std::uint8_t((color[c] * alpha + pixel[c] * (255 - alpha)) / 255);
    pixel[3] = std::uint8_t(alpha + pixel[3] * (255 - alpha) / 255);
}

} // namespace

int textLineHeight(int scale) {
    return 11 * std::clamp(scale, 1, kMaxTextScale);
}

void drawText(Image& canvas, int x, int y, std::string_view text, int scale, glm::u8vec4 color) {
    if (scale < 1 || text.empty()) return;
    const stbtt_fontinfo& info = font();
    const float s = pixelScale(scale);
    int ascent = 0, descent = 0, gap = 0;
    stbtt_GetFontVMetrics(&info, &ascent, &descent, &gap);
    const long long baseline = (long long)y + std::lround(float(ascent) * s);
    long long penX = x;
    std::vector<unsigned char> coverage;
    for (std::size_t i = 0; i < text.size() && penX < canvas.width;) {
        const int glyph = stbtt_FindGlyphIndex(&info, int(nextChar(text, i)));
        int advance = 0, bearing = 0;
        stbtt_GetGlyphHMetrics(&info, glyph, &advance, &bearing);
        int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        stbtt_GetGlyphBitmapBox(&info, glyph, s, s, &x0, &y0, &x1, &y1);
        const int w = x1 - x0, h = y1 - y0;
        const long long left = penX + x0, top = baseline + y0;
        if (w > 0 && h > 0 && left < canvas.width && left + w > 0 && top < canvas.height && top + h > 0) {
            coverage.assign(std::size_t(w) * std::size_t(h), 0);
            stbtt_MakeGlyphBitmap(&info, coverage.data(), w, h, w, s, s, glyph);
            for (int row = 0; row < h; ++row) {
                const long long cy = top + row;
                if (cy < 0 || cy >= canvas.height) continue;
                for (int col = 0; col < w; ++col) {
                    const long long cx = left + col;
                    const int c = coverage[std::size_t(row) * std::size_t(w) + std::size_t(col)];
                    if (c && cx >= 0 && cx < canvas.width) blend(canvas.pixel(int(cx), int(cy)), color, c);
                }
            }
        }
        penX += std::lround(float(advance) * s);
    }
}

std::vector<char32_t> missingGlyphs(std::string_view text) {
    std::vector<char32_t> missing;
    for (std::size_t i = 0; i < text.size();) {
        const char32_t c = nextChar(text, i);
        if (c == U'\n' || stbtt_FindGlyphIndex(&font(), int(c)) != 0) continue;
        if (std::find(missing.begin(), missing.end(), c) == missing.end()) missing.push_back(c);
    }
    return missing;
}

std::string fontName() {
    return "DejaVu Sans Mono Bold";
}

int textWidth(std::string_view text, int scale) {
    if (scale < 1) return 0;
    const stbtt_fontinfo& info = font();
    const float s = pixelScale(scale);
    long long width = 0;
    for (std::size_t i = 0; i < text.size();) {
        int advance = 0, bearing = 0;
        stbtt_GetGlyphHMetrics(&info, stbtt_FindGlyphIndex(&info, int(nextChar(text, i))), &advance,
                               &bearing);
        width += std::lround(float(advance) * s);
    }
    return int(std::min(width, (long long)INT_MAX));
}

} // namespace shadelab
