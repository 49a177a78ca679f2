// The expectations file of `shadelab review` (review.h; docs/ci-engineers.md "Expectations"): one rule a
// line, CASE DRIVER-GLOB PASS|FAIL|SKIP|FLAKY # why, as Chromium's and ANGLE's TestExpectations.
#include <fnmatch.h>

#include <array>
#include <string_view>
#include <utility>

#include "app/check/review.h"
#include "shadelab/errors.h"
#include "shadelab/io/text.h"

namespace shadelab::app {
namespace {

constexpr std::array<std::pair<std::string_view, Expectation>, 4> kExpectationWords{{
    {"PASS", Expectation::Pass},
    {"FAIL", Expectation::Fail},
    {"SKIP", Expectation::Skip},
    {"FLAKY", Expectation::Flaky},
}};

constexpr std::string_view kExpectationRuleShape = "a rule is CASE DRIVER-GLOB PASS|FAIL|SKIP|FLAKY # why";

// The value quoted back: untrusted text, so escaped, and cut so that a long line cannot flood the message.
std::string expectationsShown(std::string_view value) {
    constexpr std::size_t kMaxShown = 60;
    if (value.size() > kMaxShown) return printable(value.substr(0, kMaxShown)) + "...";
    return printable(value);
}

[[noreturn]] void expectationsFail(const std::string& fileName, int line, std::string_view field,
                                   std::string_view value, std::string_view fix) {
    throw InputError(printable(fileName) + ":" + std::to_string(line) + ": " + std::string(field) +
                     ": got '" + expectationsShown(value) + "' (" + std::string(fix) + ")");
}

std::string_view expectationsTrim(std::string_view text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) return {};
    const auto last = text.find_last_not_of(" \t");
    return text.substr(first, last - first + 1);
}

std::vector<std::string_view> expectationsWords(std::string_view text) {
    std::vector<std::string_view> words;
    std::size_t at = 0;
    while (true) {
        at = text.find_first_not_of(" \t", at);
        if (at == std::string_view::npos) return words;
        const auto end = std::min(text.find_first_of(" \t", at), text.size());
        words.push_back(text.substr(at, end - at));
        at = end;
    }
}

} // namespace

std::vector<ExpectationRule> parseExpectations(const std::string& text, const std::string& fileName) {
    std::vector<ExpectationRule> rules;
    std::size_t start = 0;
    for (int lineNumber = 1; start <= text.size(); ++lineNumber) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string_view line(text.data() + start, end - start);
        start = end + 1;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1); // a file saved with CRLF
        const std::string_view trimmed = expectationsTrim(line);
        if (trimmed.empty() || trimmed.front() == '#') continue;
        const auto hash = trimmed.find('#');
        const std::string_view ruleText = trimmed.substr(0, hash);
        const std::vector<std::string_view> words = expectationsWords(ruleText);
        if (words.size() != 3)
            expectationsFail(fileName, lineNumber, "rule", expectationsTrim(ruleText), kExpectationRuleShape);
        ExpectationRule rule;
        rule.caseGlob = std::string(words[0]);
        rule.driverGlob = std::string(words[1]);
        rule.line = lineNumber;
        bool known = false;
        for (const auto& [word, expectation] : kExpectationWords) {
            if (words[2] != word) continue;
            rule.expectation = expectation;
            known = true;
        }
        if (!known)
            expectationsFail(fileName, lineNumber, "expectation", words[2],
                             "one of PASS, FAIL, SKIP, FLAKY, in capitals");
        if (hash != std::string_view::npos)
            rule.comment = std::string(expectationsTrim(trimmed.substr(hash + 1)));
        // Two rules for the same case and driver: only the first could ever apply, so the second is a
        // mistake the file's author should see (Chromium's expectations linter refuses them too).
        for (const ExpectationRule& earlier : rules) {
            if (earlier.caseGlob != rule.caseGlob || earlier.driverGlob != rule.driverGlob) continue;
            expectationsFail(fileName, lineNumber, "rule", rule.caseGlob + " " + rule.driverGlob,
                             "the same case and driver as line " + std::to_string(earlier.line) +
                                 ", which decides first: keep one");
        }
        rules.push_back(std::move(rule));
    }
    return rules;
}

const ExpectationRule* findExpectation(const std::vector<ExpectationRule>& rules, const std::string& name,
                                       const std::string& driver) {
    for (const ExpectationRule& rule : rules) {
        if (::fnmatch(rule.caseGlob.c_str(), name.c_str(), 0) == 0 &&
            ::fnmatch(rule.driverGlob.c_str(), driver.c_str(), 0) == 0)
            return &rule;
    }
    return nullptr;
}

} // namespace shadelab::app
