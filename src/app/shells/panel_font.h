// The panel's and the help's font: DejaVu Sans Mono (Debian's fonts-dejavu-core, embedded at build time
// by cmake/embed_files.cmake), with the glyphs of the lecture's notation — Dear ImGui's own font is ASCII
// only and draws α, ψ, ⁻¹ or ᵀ as '?'. A monospaced face, so the panel's matrix and probe tables keep their
// columns.
#pragma once

#include <optional>
#include <string_view>

struct ImFont;
struct ImFontAtlas;

namespace shadelab::app {

// The bytes of the embedded font file `name` ("DejaVuSansMono.ttf"); nullopt if it was not embedded.
std::optional<std::string_view> embeddedPanelFont(std::string_view name);

// The text height at --ui-scale 1, in pixels (ImGui's size: ascender to descender).
inline constexpr float kPanelFontPixels = 14;

// The Unicode blocks the panel's font holds (zero-terminated pairs of inclusive bounds, as ImGui takes
// them): Latin, Greek, the phonetic extensions (ᵀ, ᵢ), punctuation, super- and subscripts, letterlike
// symbols, arrows, mathematical operators and technical symbols (⌈ ⌉), and U+FFFD for anything else.
const unsigned short* panelGlyphRanges();

// Adds the panel's font at kPanelFontPixels × uiScale to `atlas` — rasterized at that size, not scaled up
// afterwards, so text stays sharp at any --ui-scale — and returns it. The atlas reads the embedded bytes
// in place (they live as long as the program). Throws std::runtime_error if the font is missing.
ImFont* addPanelFont(ImFontAtlas& atlas, double uiScale);

} // namespace shadelab::app
