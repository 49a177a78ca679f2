// `review --junit FILE` (review.h; docs/ci-engineers.md "JUnit in GitLab and GitHub"): one <testsuite>,
// one <testcase> a case, in the shape Jenkins' xunit schema (tests/check/data/junit.xsd), GitLab and GitHub's
// reporters read. Case names and messages are untrusted text: everything is escaped, and what XML 1.0
// cannot hold (control characters, bytes that are not UTF-8) is replaced by U+FFFD.
#include <cstdint>
#include <string_view>

#include "app/check/review.h"

namespace shadelab::app {
namespace {

constexpr std::string_view kJunitReplacement = "\xEF\xBF\xBD"; // U+FFFD

// The length of the valid UTF-8 sequence at text[at] and its code point, or 0 when it is not one
// (overlong forms, surrogates and values past U+10FFFF included).
std::size_t junitSequence(std::string_view text, std::size_t at, char32_t& code) {
    const auto byte = [&](std::size_t i) { return static_cast<std::uint8_t>(text[i]); };
    const std::uint8_t lead = byte(at);
    std::size_t length = 0;
    if (lead < 0x80) {
        code = lead;
        return 1;
    }
    if (lead >= 0xC2 && lead <= 0xDF)
        length = 2, code = lead & 0x1Fu;
    else if (lead >= 0xE0 && lead <= 0xEF)
        length = 3, code = lead & 0x0Fu;
    else if (lead >= 0xF0 && lead <= 0xF4)
        length = 4, code = lead & 0x07u;
    else
        return 0;
    if (at + length > text.size()) return 0;
    for (std::size_t i = 1; i < length; ++i) {
        if ((byte(at + i) & 0xC0u) != 0x80u) return 0;
        code = (code << 6) | (byte(at + i) & 0x3Fu);
    }
    const char32_t minimum = length == 2 ? 0x80 : length == 3 ? 0x800 : 0x10000;
    if (code < minimum || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
    return length;
}

// XML 1.0's Char production: tab, line feed, carriage return, and U+20 on, less the surrogates and
// U+FFFE, U+FFFF.
bool junitAllowed(char32_t c) {
    return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c != 0xFFFE && c != 0xFFFF);
}

// `text` escaped for an attribute value (`attribute`: line breaks and tabs as character references, which
// an attribute would otherwise normalize to spaces) or for element content.
std::string junitEscape(std::string_view text, bool attribute) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t at = 0; at < text.size();) {
        char32_t code = 0;
        const std::size_t length = junitSequence(text, at, code);
        if (length == 0 || !junitAllowed(code)) {
            out += kJunitReplacement;
            at += length == 0 ? 1 : length;
            continue;
        }
        switch (code) {
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
            out += "&apos;";
            break;
        case '\n':
            out += attribute ? "&#10;" : "\n";
            break;
        case '\r':
            out += "&#13;";
            break;
        case '\t':
            out += attribute ? "&#9;" : "\t";
            break;
        default:
            out.append(text.substr(at, length));
        }
        at += length;
    }
    return out;
}

std::string junitAttribute(std::string_view name, std::string_view value) {
    return " " + std::string(name) + "=\"" + junitEscape(value, true) + "\"";
}

// Every approved image's figures, one a line: the text of a failure.
std::string junitFigures(const CaseResult& c) {
    std::string text = c.message + "\n";
    for (const ApprovedResult& a : c.approved) {
        text += a.expected.string() + ": ";
        text += a.judgement ? judgementFigures(*a.judgement) : (a.error.empty() ? "not read" : a.error);
        if (a.judgement) text += a.judgement->passed ? " (within the limits)" : " (beyond the limits)";
        text += "\n";
    }
    if (c.actual) text += "actual: " + c.actual->string() + "\n";
    return text;
}

std::string junitBug(const CaseResult& c) {
    if (!c.rule) return "";
    std::string text = " (expectations line " + std::to_string(c.rule->line);
    if (!c.rule->comment.empty()) text += ": " + c.rule->comment;
    return text + ")";
}

} // namespace

std::string junitXml(const ReviewReport& report) {
    const auto& cases = report.cases;
    int failures = 0, skipped = 0;
    for (const CaseResult& c : cases) {
        failures += failsRun(c.status) ? 1 : 0;
        skipped += c.status == CaseStatus::Skipped ? 1 : 0;
    }
    const std::string classname =
        report.options.driver.empty() ? std::string("screenshots") : "screenshots." + report.options.driver;
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuite";
    xml += junitAttribute("name", "shadelab review") + junitAttribute("tests", std::to_string(cases.size())) +
           junitAttribute("failures", std::to_string(failures)) + junitAttribute("errors", "0") +
           junitAttribute("skipped", std::to_string(skipped)) + junitAttribute("time", "0") + ">\n";
    for (const CaseResult& c : cases) {
        xml += "  <testcase" + junitAttribute("classname", classname) + junitAttribute("name", c.name) +
               junitAttribute("time", "0");
        const std::string status = statusName(c.status);
        switch (c.status) {
        case CaseStatus::Fail:
        case CaseStatus::New:
        case CaseStatus::Stale:
        case CaseStatus::UnexpectedPass: {
            std::string message = status + ": " + c.message;
            if (c.status == CaseStatus::UnexpectedPass) message += junitBug(c) + ": remove the FAIL rule";
            xml += ">\n    <failure" + junitAttribute("message", message) + junitAttribute("type", status) +
                   ">" + junitEscape(junitFigures(c), false) + "</failure>\n  </testcase>\n";
            break;
        }
        case CaseStatus::Skipped:
            xml += ">\n    <skipped" + junitAttribute("message", c.message + junitBug(c)) +
                   "/>\n  </testcase>\n";
            break;
        case CaseStatus::ExpectedFail:
        case CaseStatus::FlakyFail:
            xml += ">\n    <system-out>" + junitEscape(status + junitBug(c) + "\n" + junitFigures(c), false) +
                   "</system-out>\n  </testcase>\n";
            break;
        case CaseStatus::Pass:
            xml += "/>\n";
            break;
        }
    }
    xml += "</testsuite>\n";
    return xml;
}

} // namespace shadelab::app
