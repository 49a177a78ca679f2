// Presentation mode's label and a lesson step's band as images (presentation_images.h).
#include "app/demo/presentation_images.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "shadelab/io/text.h"
#include "shadelab/scene/auto_level.h"

namespace shadelab::app {

PresentationFacts presentationFacts(const Scene& drawn) {
    PresentationFacts facts;
    facts.shading = drawn.shading;
    facts.normalsByM = drawn.normalMatrix == NormalMatrixRule::Model;
    facts.unnegated = leavesOutTheMinusOne(drawn);
    facts.lighting = drawn.lighting;
    facts.term = drawn.term;
    facts.level = drawn.shading == ShadingMode::Exact || drawn.objects.empty()
                      ? 0
                      : subdivisionLevel(drawn, drawn.objects[0]); // DemoState::level() of the drawn scene
    if (!drawn.objects.empty()) facts.shininess = drawn.objects[0].material.shininess;
    return facts;
}

std::string presentationLabel(const PresentationFacts& facts) {
    // Three short lines rather than two long ones: the label's letters can be larger in the same width.
    std::string label =
        std::string(toString(facts.shading)) + " shading" + (facts.normalsByM ? ", normals by M" : "") +
        (facts.unnegated ? ", unnegated: w < 0, all clipped" : "") + "\n" +
        std::string(toString(facts.lighting)) + " lighting" +
        (facts.term == LightingTerm::All ? "" : ", " + std::string(toString(facts.term))) + "\n" +
        (facts.shading == ShadingMode::Exact ? std::string("ray-cast")
                                             : "level " + std::to_string(facts.level));
    if (facts.shininess) {
        char exponent[48];
        std::snprintf(exponent, sizeof exponent, " | %s = %g",
                      facts.lighting == LightingModel::BlinnPhong ? "beta" : "alpha", *facts.shininess);
        label += exponent;
    }
    return upperAscii(label);
}

PresentationLabelImage presentationLabelImage(const std::string& label, int width, int height) {
    std::vector<std::string> lines;
    for (std::size_t start = 0; start <= label.size();) {
        const std::size_t end = std::min(label.find('\n', start), label.size());
        lines.push_back(label.substr(start, end - start));
        start = end + 1;
    }
    const int margin = std::max(4, height / 48);
    // The largest scale whose lines are at most a twelfth of the height and whose widest line, with the
    // box's padding, fits the width less the margins; at least 1 (a picture too small for that clips).
    int scale = std::clamp(height / 12 / textLineHeight(1), 1, kMaxTextScale);
    const auto pad = [](int s) { return textLineHeight(s) / 2; }; // half a line around the text
    const auto boxWidth = [&](int s) {
        int widest = 0;
        for (const std::string& line : lines) widest = std::max(widest, textWidth(line, s));
        return widest + 2 * pad(s);
    };
    while (scale > 1 && boxWidth(scale) > width - 2 * margin) --scale;
    Image image(boxWidth(scale), int(lines.size()) * textLineHeight(scale) + 2 * pad(scale));
    fillRect(image, 0, 0, image.width, image.height, {0, 0, 0, 153}); // 60 % black, as the page had
    for (std::size_t i = 0; i < lines.size(); ++i)
        drawText(image, pad(scale), pad(scale) + int(i) * textLineHeight(scale), lines[i], scale,
                 {255, 255, 255, 255});
    return {std::move(image), margin};
}

namespace {

// Where the UTF-8 character that starts at `at` ends.
std::size_t nextCharacter(const std::string& text, std::size_t at) {
    ++at;
    while (at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) ++at;
    return at;
}

// The lines `text` takes at `scale` in `width` pixels: its own lines, each wrapped at spaces; a word wider
// than a line is cut before the first character that would not fit (never inside a UTF-8 sequence).
std::vector<std::string> wrappedLines(const std::string& text, int scale, int width) {
    std::vector<std::string> lines;
    const auto fits = [&](const std::string& line) { return textWidth(line, scale) <= width; };
    for (std::size_t start = 0; start <= text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string paragraph = text.substr(start, end - start);
        start = end + 1;
        std::string line;
        std::size_t at = 0;
        while (at < paragraph.size()) {
            const std::size_t space = std::min(paragraph.find(' ', at), paragraph.size());
            std::string word = paragraph.substr(at, space - at);
            at = space + 1;
            std::string joined = line;
            if (!joined.empty()) joined += ' ';
            joined += word;
            if (fits(joined)) {
                line = joined;
                continue;
            }
            if (!line.empty()) lines.push_back(line);
            line.clear();
            while (!fits(word)) { // wider than a line on its own: cut after the last character that fits
                std::size_t cut = nextCharacter(word, 0);
                for (std::size_t next = nextCharacter(word, cut);
                     next <= word.size() && fits(word.substr(0, next)); next = nextCharacter(word, next))
                    cut = next;
                lines.push_back(word.substr(0, cut));
                word.erase(0, cut);
            }
            line = word;
        }
        lines.push_back(line);
    }
    return lines;
}

} // namespace

Image lessonBandImage(const std::string& title, const std::string& caption, int width, int height) {
    if (width < 1 || height < 1) return Image(0, 0);
    // The nearest whole scales (a scale is 11 px of line): a floor would leave a 700 px picture's caption
    // at 11 px.
    const auto nearestScale = [&](int parts) {
        return std::clamp(int(std::lround(double(height) / parts / textLineHeight(1))), 1, kMaxTextScale);
    };
    int titleScale = nearestScale(18), captionScale = nearestScale(30);
    const auto pad = [](int s) { return textLineHeight(s) / 2; };
    std::vector<std::string> titleLines, captionLines;
    int bandHeight = 0;
    for (;;) {
        const int inner = std::max(1, width - 2 * pad(titleScale));
        titleLines = wrappedLines(title, titleScale, inner);
        captionLines =
            caption.empty() ? std::vector<std::string>{} : wrappedLines(caption, captionScale, inner);
        bandHeight = 2 * pad(titleScale) + int(titleLines.size()) * textLineHeight(titleScale) +
                     int(captionLines.size()) * textLineHeight(captionScale);
        if (bandHeight <= height * 2 / 5 || (titleScale == 1 && captionScale == 1)) break;
        // The caption gives way first, down to two thirds of the title's size; then the title (to 1).
        const bool captionFirst = captionScale > 1 && (captionScale * 3 >= titleScale * 2 || titleScale == 1);
        if (captionFirst)
            --captionScale;
        else
            --titleScale;
    }
    Image image(width, std::min(bandHeight, height));
    fillRect(image, 0, 0, image.width, image.height, {0, 0, 0, 166}); // 65 % black
    int y = pad(titleScale);
    for (const std::string& line : titleLines) {
        drawText(image, pad(titleScale), y, line, titleScale, {255, 255, 255, 255});
        y += textLineHeight(titleScale);
    }
    for (const std::string& line : captionLines) {
        drawText(image, pad(titleScale), y, line, captionScale, {225, 225, 225, 255});
        y += textLineHeight(captionScale);
    }
    return image;
}

} // namespace shadelab::app
