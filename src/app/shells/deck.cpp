#include "app/shells/deck.h"

#include <algorithm>
#include <cctype>

#include "shadelab/errors.h"
#include "shadelab/io/text.h"

namespace shadelab::app {
namespace {

namespace fs = std::filesystem;

std::string base64(std::string_view bytes) {
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        unsigned value = 0;
        for (std::size_t k = 0; k < 3; ++k)
            value = (value << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kDigits[(value >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

// Text as HTML text or attribute value: the lesson's words are data, never markup.
std::string escaped(std::string_view text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '\'':
            out += "&#39;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

// One slide at a time, as large as the window allows; ← → (PgUp PgDn, Space, Home, End) step, N shows the
// notes under the slide. Printed, each slide is a page with its notes below it.
constexpr const char* kStyle = R"(
html, body { margin: 0; background: #111; color: #eee; font: 18px/1.4 sans-serif; }
section { display: none; height: 100vh; box-sizing: border-box; padding: 1vh; flex-direction: column;
  align-items: center; justify-content: center; }
section.shown { display: flex; }
section img { width: 100%; height: 100%; min-height: 0; object-fit: contain; }
body.notes section img { height: 70%; }
aside { display: none; white-space: pre-wrap; max-width: 60em; margin-top: 1em; }
body.notes aside { display: block; }
footer { position: fixed; right: 1em; bottom: 0.5em; opacity: 0.6; font-size: 14px; }
@media print {
  html, body { background: #fff; color: #000; }
  section { display: flex; height: auto; page-break-after: always; break-after: page; }
  section img { height: auto; max-height: 70vh; }
  aside { display: block; }
  footer { display: none; }
}
)";

constexpr const char* kScript = R"(
const slides = document.querySelectorAll('section');
let shown = 0;
function show(i) {
  shown = Math.max(0, Math.min(slides.length - 1, i));
  slides.forEach((s, k) => s.classList.toggle('shown', k === shown));
  document.getElementById('where').textContent = (shown + 1) + ' / ' + slides.length + ' (N: notes)';
  history.replaceState(null, '', '#' + (shown + 1));
}
document.addEventListener('keydown', (e) => {
  const keys = {ArrowRight: 1, PageDown: 1, ' ': 1, ArrowLeft: -1, PageUp: -1, Backspace: -1};
  if (e.key in keys) show(shown + keys[e.key]);
  else if (e.key === 'Home') show(0);
  else if (e.key === 'End') show(slides.length - 1);
  else if (e.key === 'n' || e.key === 'N') document.body.classList.toggle('notes');
  else return;
  e.preventDefault();
});
document.addEventListener('click', (e) => show(shown + (e.clientX < innerWidth / 3 ? -1 : 1)));
show((parseInt(location.hash.slice(1), 10) || 1) - 1);
)";

bool htmlName(const fs::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension == ".html" || extension == ".htm";
}

} // namespace

std::string deckHtml(const Lesson& lesson, const std::vector<std::string>& pngs) {
    std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                       // Nothing is fetched: the pictures are in the file, the style and script inline.
                       "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src "
                       "data:; style-src 'unsafe-inline'; script-src 'unsafe-inline'\">\n"
                       "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
                       escaped(lesson.title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
    for (std::size_t i = 0; i < pngs.size() && i < lesson.steps.size(); ++i) {
        const LessonStep& step = lesson.steps[i];
        html += "<section id=\"slide-" + std::to_string(i + 1) + "\">\n<img alt=\"" + escaped(step.title) +
                "\" src=\"data:image/png;base64," + base64(pngs[i]) + "\">\n";
        html += "<aside class=\"notes\">" + escaped(step.notes) + "</aside>\n</section>\n";
    }
    html +=
        "<footer id=\"where\"></footer>\n<script>" + std::string(kScript) + "</script>\n</body>\n</html>\n";
    return html;
}

Deck::Deck(const fs::path& path, const std::vector<fs::path>& inputs) : path_(path) {
    // The slides' progress lines go to standard output: the deck cannot go there too.
    refuseStandardOutputAlias(path, "--deck", "the slides' progress lines", "deck.html");
    const OutputTarget target = resolveOutput(path, "--deck");
    if (target.kind == OutputTarget::Kind::Regular && !htmlName(path))
        throw InputError("--deck: \"" + printable(path.string()) +
                         "\" is not named .html; a deck is one HTML page (every slide, and the notes under "
                         "N): name it, for example, deck.html");
    for (const fs::path& input : inputs) refuseOverwritingInput(path, "--deck", input);
}

void Deck::add(std::string png) {
    pngs_.push_back(std::move(png));
}

void Deck::write(const Lesson& lesson) const {
    const std::string html = deckHtml(lesson, pngs_);
    writeFileAtomically(path_, "deck", [&](std::FILE* out) {
        if (std::fwrite(html.data(), 1, html.size(), out) != html.size())
            throw RuntimeError("cannot write the deck \"" + printable(path_.string()) + "\"");
    });
}

} // namespace shadelab::app
