// A slide's file name from its step's title: the lecture's symbols spelled out in words, so that
// "(M⁻¹)ᵀ" names "m-inverse-transpose" and not the "M" of the slide before it (lesson.h).
#include <algorithm>
#include <array>
#include <string>
#include <string_view>

#include "shadelab/scene/lesson.h"

namespace shadelab {
namespace {

struct Spelling {
    std::string_view symbol; // UTF-8
    std::string_view word;
};

// Longest first where one symbol starts another (⁻¹ before ⁻). Greek letters as the lecture reads them
// (α, β: the shininess exponents; ψ, φ: the angles), the exponents and operators of its formulas, and the
// accented Latin letters of a title in another language.
constexpr std::array kSpellings = {
    Spelling{"⁻¹", "inverse"}, Spelling{"ᵀ", "transpose"}, Spelling{"²", "squared"},
    Spelling{"³", "cubed"},    Spelling{"⁻", "minus"},     Spelling{"−", "minus"},
    Spelling{"×", "times"},    Spelling{"÷", "over"},      Spelling{"±", "plus-minus"},
    Spelling{"→", "to"},       Spelling{"≤", "le"},        Spelling{"≥", "ge"},
    Spelling{"≠", "ne"},       Spelling{"≈", "approx"},    Spelling{"∞", "infinity"},
    Spelling{"√", "sqrt"},     Spelling{"Σ", "sum"},       Spelling{"∑", "sum"},
    Spelling{"°", "deg"},      Spelling{"α", "alpha"},     Spelling{"β", "beta"},
    Spelling{"γ", "gamma"},    Spelling{"δ", "delta"},     Spelling{"ε", "epsilon"},
    Spelling{"θ", "theta"},    Spelling{"λ", "lambda"},    Spelling{"μ", "mu"},
    Spelling{"π", "pi"},       Spelling{"ρ", "rho"},       Spelling{"σ", "sigma"},
    Spelling{"τ", "tau"},      Spelling{"φ", "phi"},       Spelling{"ψ", "psi"},
    Spelling{"ω", "omega"},    Spelling{"Δ", "delta"},     Spelling{"Ω", "omega"},
    Spelling{"⁰", "0"},        Spelling{"¹", "1"},         Spelling{"⁴", "4"},
    Spelling{"⁵", "5"},        Spelling{"⁶", "6"},         Spelling{"⁷", "7"},
    Spelling{"⁸", "8"},        Spelling{"⁹", "9"},         Spelling{"ⁿ", "n"},
    Spelling{"₀", "0"},        Spelling{"₁", "1"},         Spelling{"₂", "2"},
    Spelling{"₃", "3"},        Spelling{"à", "a"},         Spelling{"á", "a"},
    Spelling{"â", "a"},        Spelling{"ä", "ae"},        Spelling{"ç", "c"},
    Spelling{"è", "e"},        Spelling{"é", "e"},         Spelling{"ê", "e"},
    Spelling{"ë", "e"},        Spelling{"í", "i"},         Spelling{"î", "i"},
    Spelling{"ï", "i"},        Spelling{"ñ", "n"},         Spelling{"ó", "o"},
    Spelling{"ô", "o"},        Spelling{"ö", "oe"},        Spelling{"ú", "u"},
    Spelling{"û", "u"},        Spelling{"ü", "ue"},        Spelling{"ß", "ss"},
    Spelling{"À", "a"},        Spelling{"Á", "a"},         Spelling{"Â", "a"},
    Spelling{"Ä", "ae"},       Spelling{"Ç", "c"},         Spelling{"È", "e"},
    Spelling{"É", "e"},        Spelling{"Ê", "e"},         Spelling{"Ë", "e"},
    Spelling{"Í", "i"},        Spelling{"Î", "i"},         Spelling{"Ï", "i"},
    Spelling{"Ñ", "n"},        Spelling{"Ó", "o"},         Spelling{"Ô", "o"},
    Spelling{"Ö", "oe"},       Spelling{"Ú", "u"},         Spelling{"Û", "u"},
    Spelling{"Ü", "ue"},
};

constexpr std::size_t kMaxTitleBytes = 64;

char lowerAscii(char c) {
    return (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
}
bool digit(char c) {
    return c >= '0' && c <= '9';
}
// A letter or digit once lower-cased.
bool plain(char c) {
    return (lowerAscii(c) >= 'a' && lowerAscii(c) <= 'z') || digit(c);
}

// The title in lower-case ASCII words joined by '-': a symbol of the table is its word, an ASCII '-' just
// before a digit where no word ends is a minus ("The WebGL -1" → "the-webgl-minus-1"), anything else
// separates words.
std::string spelledOut(std::string_view title) {
    std::string words;
    const auto separate = [&] {
        if (!words.empty() && words.back() != '-') words += '-';
    };
    for (std::size_t i = 0; i < title.size();) {
        const auto spelling = std::find_if(kSpellings.begin(), kSpellings.end(), [&](const Spelling& s) {
            return title.substr(i).starts_with(s.symbol);
        });
        if (spelling != kSpellings.end()) {
            // A one-character spelling (a digit or a letter) joins its neighbours ("p₀" is "p0"); a word
            // stands apart ("t²" is "t-squared").
            const bool joined = spelling->word.size() == 1;
            if (!joined) separate();
            words += spelling->word;
            if (!joined) separate();
            i += spelling->symbol.size();
            continue;
        }
        const char c = title[i];
        const bool minusSign =
            c == '-' && i + 1 < title.size() && digit(title[i + 1]) && (i == 0 || !plain(title[i - 1]));
        if (minusSign) {
            separate();
            words += "minus-";
        } else if (plain(c)) {
            words += lowerAscii(c);
        } else {
            separate();
        }
        ++i;
    }
    while (!words.empty() && words.back() == '-') words.pop_back();
    while (!words.empty() && words.front() == '-') words.erase(words.begin());
    return words;
}

// At most kMaxTitleBytes, cut at a word's end where one is near (a word cut in half can read as another).
std::string shortened(std::string words) {
    if (words.size() <= kMaxTitleBytes) return words;
    const std::size_t cut = words.rfind('-', kMaxTitleBytes);
    words.resize(cut != std::string::npos && cut >= kMaxTitleBytes / 2 ? cut : kMaxTitleBytes);
    while (!words.empty() && words.back() == '-') words.pop_back();
    return words;
}

} // namespace

std::string slideFileName(std::size_t index, std::size_t count, std::string_view title) {
    const std::size_t digits = std::max<std::size_t>(2, std::to_string(count).size());
    std::string number = std::to_string(index + 1);
    number.insert(0, digits - std::min(digits, number.size()), '0');
    const std::string words = shortened(spelledOut(title));
    return number + "-" + (words.empty() ? "step" : words) + ".png";
}

} // namespace shadelab
