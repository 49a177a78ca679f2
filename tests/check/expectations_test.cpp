// The expectations file of `shadelab review` (app/check/review.h): what a line means, which rule decides,
// and each malformed line's message (FILE:LINE: field: got 'value' (fix)).
#include <gtest/gtest.h>

#include "app/check/review.h"
#include "shadelab/errors.h"

namespace shadelab::app {
namespace {

std::string messageOf(const std::string& text) {
    try {
        (void)parseExpectations(text, "exp.txt");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(Expectations, ReadsRulesCommentsAndBlankLines) {
    const std::string text = "# CASE DRIVER EXPECTATION\n"
                             "\n"
                             "toon-spot   softpipe  FAIL   # https://example.org/issues/12: bands\r\n"
                             "   toon-*\tswrast SKIP\n"
                             "phong  radeonsi*  FLAKY\n"
                             "sphere * PASS#no space before the hash";
    const auto rules = parseExpectations(text, "exp.txt");
    ASSERT_EQ(rules.size(), 4u);
    EXPECT_EQ(rules[0].caseGlob, "toon-spot");
    EXPECT_EQ(rules[0].driverGlob, "softpipe");
    EXPECT_EQ(rules[0].expectation, Expectation::Fail);
    EXPECT_EQ(rules[0].comment, "https://example.org/issues/12: bands"); // the CR of CRLF is not kept
    EXPECT_EQ(rules[0].line, 3);
    EXPECT_EQ(rules[1].expectation, Expectation::Skip);
    EXPECT_EQ(rules[1].line, 4);
    EXPECT_EQ(rules[2].expectation, Expectation::Flaky);
    EXPECT_EQ(rules[2].comment, "");
    EXPECT_EQ(rules[3].expectation, Expectation::Pass);
    EXPECT_EQ(rules[3].comment, "no space before the hash");
}

TEST(Expectations, EachMalformedLineIsNamedByFileLineAndField) {
    EXPECT_EQ(messageOf("a b\n"),
              "exp.txt:1: rule: got 'a b' (a rule is CASE DRIVER-GLOB PASS|FAIL|SKIP|FLAKY # why)");
    EXPECT_EQ(
        messageOf("# ok\na b FAIL extra # why\n"),
        "exp.txt:2: rule: got 'a b FAIL extra' (a rule is CASE DRIVER-GLOB PASS|FAIL|SKIP|FLAKY # why)");
    EXPECT_EQ(messageOf("a * fail\n"),
              "exp.txt:1: expectation: got 'fail' (one of PASS, FAIL, SKIP, FLAKY, in capitals)");
    EXPECT_EQ(
        messageOf("a * FAIL\nb * PASS\na * SKIP # again\n"),
        "exp.txt:3: rule: got 'a *' (the same case and driver as line 1, which decides first: keep one)");
    // Untrusted bytes are escaped in the message: an ESC cannot reach the terminal, nor a megabyte line.
    EXPECT_EQ(messageOf("a * \x1b[2J\n"),
              "exp.txt:1: expectation: got '\\x1b[2J' (one of PASS, FAIL, SKIP, FLAKY, in capitals)");
    const std::string message = messageOf("a * " + std::string(100000, 'X') + "\n");
    EXPECT_LT(message.size(), 200u) << message;
}

TEST(Expectations, TheFirstMatchingRuleDecides) {
    const auto rules = parseExpectations("toon-spot softpipe FAIL # 12\n"
                                         "toon-* * SKIP\n"
                                         "* llvm* FLAKY\n",
                                         "exp.txt");
    const ExpectationRule* spot = findExpectation(rules, "toon-spot", "softpipe");
    ASSERT_NE(spot, nullptr);
    EXPECT_EQ(spot->line, 1);
    const ExpectationRule* other = findExpectation(rules, "toon-spot", "llvmpipe");
    ASSERT_NE(other, nullptr);
    EXPECT_EQ(other->line, 2); // the driver glob of line 1 does not match: the next rule decides
    const ExpectationRule* any = findExpectation(rules, "sphere", "llvmpipe");
    ASSERT_NE(any, nullptr);
    EXPECT_EQ(any->expectation, Expectation::Flaky);
    EXPECT_EQ(findExpectation(rules, "sphere", "softpipe"), nullptr); // no rule: PASS
    EXPECT_EQ(findExpectation(rules, "sphere", ""), nullptr);
}

} // namespace
} // namespace shadelab::app
