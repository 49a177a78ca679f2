#include "app/shells/panel_font.h"

#include <stdexcept>

#include <imgui.h>

namespace shadelab::app {
namespace {

constexpr const char* kFontFile = "DejaVuSansMono.ttf";

// ImWchar is 16 bits in Debian's build (no IMGUI_USE_WCHAR32): the Basic Multilingual Plane only, which
// holds every block below. A block DejaVu Sans Mono has no glyph for costs nothing: ImGui skips it.
constexpr ImWchar kRanges[] = {
    0x0020, 0x017F, // Basic Latin, Latin-1 (· × ² ³ ½), Latin Extended-A
    0x0370, 0x03FF, // Greek (α β θ λ φ ψ Σ)
    0x1D00, 0x1DBF, // Phonetic Extensions: modifier and subscript letters (ᵀ ᵢ)
    0x2000, 0x206F, // General Punctuation (— ‖ …)
    0x2070, 0x209F, // Superscripts and Subscripts (⁻¹ ⁿ ⁺ ₀ ₁ ₂)
    0x2100, 0x214F, // Letterlike Symbols (ℓ ℝ)
    0x2190, 0x21FF, // Arrows (→)
    0x2200, 0x22FF, // Mathematical Operators (− ∝ ≈ ≤ ≥ ∞)
    0x2300, 0x23FF, // Miscellaneous Technical (⌈ ⌉ ⌊ ⌋)
    0x25A0, 0x25FF, // Geometric Shapes (■ ●)
    0xFFFD, 0xFFFD, // the replacement character: ImGui's fallback when present, not a '?' that reads as text
    0,
};

} // namespace

const unsigned short* panelGlyphRanges() {
    return kRanges;
}

ImFont* addPanelFont(ImFontAtlas& atlas, double uiScale) {
    const std::optional<std::string_view> ttf = embeddedPanelFont(kFontFile);
    if (!ttf) throw std::runtime_error(std::string("the panel's font ") + kFontFile + " is not embedded");
    ImFontConfig config;
    config.FontDataOwnedByAtlas = false; // the embedded bytes are static: the atlas must not free them
    // A monospaced face drawn at its own size: glyphs on whole pixels, no horizontal oversampling (which
    // would triple the atlas for sub-pixel positions a fixed advance does not need).
    config.OversampleH = 1;
    config.OversampleV = 1;
    config.PixelSnapH = true;
    // ImGui takes non-const data (it never writes it when it does not own it).
    void* data = const_cast<char*>(ttf->data());
    ImFont* font = atlas.AddFontFromMemoryTTF(data, int(ttf->size()), kPanelFontPixels * float(uiScale),
                                              &config, kRanges);
    if (font == nullptr) throw std::runtime_error(std::string("Dear ImGui could not load ") + kFontFile);
    return font;
}

} // namespace shadelab::app
