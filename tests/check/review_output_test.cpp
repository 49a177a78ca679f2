// What `shadelab review` writes: blessed images, the JSON, the JUnit XML (held to the Jenkins xunit schema,
// tests/check/data/junit.xsd, by xmllint) and the lines it prints, with hostile case names.
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "check/review_fixture.h"
#include "shadelab/errors.h"

namespace shadelab::app {
namespace {

namespace fs = std::filesystem;

class ReviewOutput : public ReviewFixture {
protected:
    // A pass, a failure, a new and a stale case.
    void fourCases() {
        put(actual, "pass", grey(16, 16, 100));
        put(expected, "pass", grey(16, 16, 100));
        put(actual, "fail", grey(16, 16, 100, 200));
        put(expected, "fail", grey(16, 16, 100));
        put(actual, "new", grey(16, 16, 30));
        put(expected, "stale", grey(16, 16, 30));
    }
    static std::string inputErrorOf(const ReviewOptions& o) {
        try {
            (void)reviewFolders(o);
        } catch (const InputError& e) {
            return e.what();
        }
        return "(no error)";
    }
};

// Names no file should have but a file system allows: quotes, markup, an ampersand, a newline and bytes
// that are not UTF-8 (a file name cannot hold '/', so the script is not closed).
const std::string kHostile = "x\"'<script>alert(1)&amp;\n\xff\xfe";

TEST_F(ReviewOutput, BlessFailedWritesOnlyFailedAndNewCases) {
    fourCases();
    const std::string passBefore = bytesOf(expected / "pass.png");
    const auto passTime = fs::last_write_time(expected / "pass.png");
    ReviewOptions o = options();
    o.blessFailed = true;
    const ReviewReport report = reviewFolders(o);
    ASSERT_EQ(report.blessed.size(), 2u);
    EXPECT_EQ(report.blessed[0], "fail -> " + (expected / "fail.png").string());
    EXPECT_EQ(report.blessed[1], "new -> " + (expected / "new.png").string());
    EXPECT_EQ(bytesOf(expected / "fail.png"), bytesOf(actual / "fail.png"));
    EXPECT_EQ(bytesOf(expected / "new.png"), bytesOf(actual / "new.png"));
    EXPECT_EQ(bytesOf(expected / "pass.png"), passBefore);
    EXPECT_EQ(fs::last_write_time(expected / "pass.png"), passTime); // a passing case is never rewritten
    EXPECT_TRUE(fs::exists(expected / "stale.png"));
}

TEST_F(ReviewOutput, BlessByNameWritesThatCaseAndPrintsIt) {
    fourCases();
    ReviewOptions o = options();
    o.bless = {"fail", "pass"};
    ::testing::internal::CaptureStdout();
    const int status = runReview(o);
    const std::string printed = ::testing::internal::GetCapturedStdout();
    EXPECT_EQ(status, 1); // this run's failures stand
    EXPECT_NE(printed.find("blessed: fail -> " + (expected / "fail.png").string() + "\n"), std::string::npos)
        << printed;
    EXPECT_NE(printed.find("not blessed: pass passes"), std::string::npos) << printed;
    EXPECT_EQ(printed.find("blessed: new"), std::string::npos) << printed;
    EXPECT_EQ(bytesOf(expected / "fail.png"), bytesOf(actual / "fail.png"));
    EXPECT_FALSE(fs::exists(expected / "new.png"));
}

TEST_F(ReviewOutput, BlessingWhatHasNoActualImageIsBadInput) {
    fourCases();
    ReviewOptions o = options();
    o.bless = {"stale"};
    EXPECT_NE(inputErrorOf(o).find("\"stale\" is STALE"), std::string::npos) << inputErrorOf(o);
    o.bless = {"fail", "nothing"};
    EXPECT_NE(inputErrorOf(o).find("\"nothing\" is no case"), std::string::npos) << inputErrorOf(o);
    EXPECT_NE(bytesOf(expected / "fail.png"), bytesOf(actual / "fail.png")); // nothing was blessed
}

TEST_F(ReviewOutput, BlessNeverWritesThroughALink) {
    put(actual, "fail", grey(16, 16, 100, 200));
    put(root, "target", grey(16, 16, 100));
    fs::create_symlink(root / "target.png", expected / "fail.png");
    const std::string before = bytesOf(root / "target.png");
    ReviewOptions o = options();
    o.blessFailed = true;
    EXPECT_NE(inputErrorOf(o).find("symbolic link"), std::string::npos) << inputErrorOf(o);
    EXPECT_EQ(bytesOf(root / "target.png"), before);
    EXPECT_TRUE(fs::is_symlink(expected / "fail.png"));
}

TEST_F(ReviewOutput, TheJsonHoldsEveryCaseWithItsFiguresAndFiles) {
    fourCases();
    put(actual, kHostile, grey(16, 16, 100, 200));
    writeText(root / "exp.txt", "x* * FAIL # https://example.org/<1>\n");
    ReviewOptions o = options();
    o.out = root / "page";
    o.expectations = root / "exp.txt";
    o.driver = "llvmpipe";
    o.limits.ssimMin = 0.5;
    const nlohmann::json j = nlohmann::json::parse(reviewJson(reviewFolders(o)));
    EXPECT_EQ(j["driver"], "llvmpipe");
    EXPECT_EQ(j["passed"], false);
    EXPECT_EQ(j["limits"]["ssim_min"], 0.5);
    EXPECT_EQ(j["counts"]["FAIL"], 1);
    EXPECT_EQ(j["counts"]["NEW"],
              2); // "new" and the hostile name (no approved image: its rule does not apply)
    EXPECT_EQ(j["counts"]["STALE"], 1);
    EXPECT_EQ(j["counts"]["pass"], 1);
    ASSERT_EQ(j["cases"].size(), 5u);
    const nlohmann::json& fail = j["cases"][0];
    EXPECT_EQ(fail["name"], "fail");
    EXPECT_EQ(fail["status"], "FAIL");
    EXPECT_EQ(fail["expectation"], "PASS");
    EXPECT_EQ(fail["approved"][0]["max_delta"], 100);
    EXPECT_TRUE(fail["approved"][0].contains("ssim"));
    // The figures in compare --json's schema (app/check/figures_json.h).
    EXPECT_TRUE(fail["approved"][0]["perceptual"]["differing_pixels"].is_number_integer()) << fail.dump();
    EXPECT_EQ(fail["approved"][0]["perceptual"]["threshold"], 0.1);
    EXPECT_EQ(fail["approved"][0]["passed"], false);
    EXPECT_TRUE(fail["files"]["diff"].is_string());
    EXPECT_TRUE(fs::is_regular_file(o.out / fail["files"]["diff"].get<std::string>()));
    const nlohmann::json& stale = j["cases"][2];
    EXPECT_EQ(stale["name"], "stale");
    EXPECT_TRUE(stale["actual"].is_null());
    EXPECT_TRUE(stale["files"]["actual"].is_null());
    EXPECT_TRUE(stale["files"]["diff"].is_null());
    // The hostile name: valid characters kept, the bytes that are not UTF-8 replaced by U+FFFD.
    bool found = false;
    for (const auto& c : j["cases"])
        if (c["name"] == "x\"'<script>alert(1)&amp;\n\xEF\xBF\xBD\xEF\xBF\xBD") found = true;
    EXPECT_TRUE(found) << j.dump();
}

// xmllint from libxml2-utils (scripts/setup.sh's tests packages): in CI a missing one fails the test.
bool haveXmllint() {
    return std::system("command -v xmllint >/dev/null 2>&1") == 0;
}

TEST_F(ReviewOutput, TheJunitIsValidAgainstTheSchemaWithHostileNames) {
    if (!haveXmllint()) {
        if (std::getenv("CI")) FAIL() << "xmllint is missing (Debian: libxml2-utils), and CI is set";
        GTEST_SKIP() << "xmllint (Debian: libxml2-utils) is not installed: the schema check needs it";
    }
    fourCases();
    put(actual, kHostile, grey(16, 16, 100, 200));
    put(expected, kHostile, grey(16, 16, 100));
    put(actual, "flaky", grey(16, 16, 100, 200));
    put(expected, "flaky", grey(16, 16, 100));
    put(actual, "skipped", grey(16, 16, 1));
    put(actual, "known", grey(16, 16, 100, 200));
    put(expected, "known", grey(16, 16, 100));
    writeText(root / "exp.txt", "flaky * FLAKY # https://example.org/?a=1&b=<2>\nskipped * SKIP # \x01 why\n"
                                "known * FAIL # bug 7\n");
    ReviewOptions o = options();
    o.expectations = root / "exp.txt";
    o.driver = "llvm\"pipe";
    o.junit = root / "junit.xml";
    ::testing::internal::CaptureStdout();
    EXPECT_EQ(runReview(o), 1);
    (void)::testing::internal::GetCapturedStdout();
    const std::string xml = bytesOf(o.junit);
    const std::string command = "xmllint --noout --schema '" SHADELAB_TEST_DATA "/check/data/junit.xsd' '" +
                                o.junit.string() + "' 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << xml;
    EXPECT_NE(xml.find("<testsuite name=\"shadelab review\" tests=\"8\" failures=\"4\" errors=\"0\" "
                       "skipped=\"1\""),
              std::string::npos)
        << xml;
    EXPECT_NE(xml.find("classname=\"screenshots.llvm&quot;pipe\" name=\"x&quot;&apos;&lt;script&gt;alert(1)"
                       "&amp;amp;&#10;\xEF\xBF\xBD\xEF\xBF\xBD\""),
              std::string::npos)
        << xml;
    EXPECT_EQ(xml.find("<script>"), std::string::npos);
    EXPECT_NE(xml.find("<failure message=\"FAIL: "), std::string::npos) << xml;
    EXPECT_NE(xml.find("<skipped message="), std::string::npos) << xml;
    EXPECT_NE(
        xml.find("<system-out>flaky-fail (expectations line 1: https://example.org/?a=1&amp;b=&lt;2&gt;)\n"),
        std::string::npos)
        << xml;
    EXPECT_NE(xml.find("<system-out>expected-fail (expectations line 3: bug 7)\n"), std::string::npos) << xml;
    EXPECT_EQ(xml.find('\x01'), std::string::npos); // a control character XML 1.0 forbids is replaced
}

TEST_F(ReviewOutput, BadInputWritesNothing) {
    fourCases();
    writeText(root / "exp.txt", "fail * FAIL\nnew * MAYBE\n");
    ReviewOptions o = options();
    o.expectations = root / "exp.txt";
    o.json = root / "review.json";
    o.junit = root / "junit.xml";
    o.out = root / "page";
    o.blessFailed = true;
    const std::string failBefore = bytesOf(expected / "fail.png");
    try {
        (void)runReview(o);
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  (root / "exp.txt").string() +
                      ":2: expectation: got 'MAYBE' (one of PASS, FAIL, SKIP, FLAKY, in capitals)");
    }
    EXPECT_FALSE(fs::exists(o.json));
    EXPECT_FALSE(fs::exists(o.junit));
    EXPECT_FALSE(fs::exists(o.out));
    EXPECT_EQ(bytesOf(expected / "fail.png"), failBefore); // nothing blessed
}

TEST_F(ReviewOutput, RunReviewPrintsACaseALineAndWritesItsFiles) {
    fourCases();
    ReviewOptions o = options();
    o.json = root / "review.json";
    o.out = root / "page";
    o.quiet = true;
    ::testing::internal::CaptureStdout();
    EXPECT_EQ(runReview(o), 1);
    std::string printed = ::testing::internal::GetCapturedStdout();
    EXPECT_NE(printed.find("FAIL            fail: "), std::string::npos) << printed;
    EXPECT_EQ(printed.find("pass: "), std::string::npos) << printed; // --quiet: failures only
    EXPECT_NE(printed.find("review: 4 cases, 1 pass, 1 FAIL, 1 NEW, 1 STALE"), std::string::npos) << printed;
    EXPECT_TRUE(fs::is_regular_file(o.out / "index.html"));
    EXPECT_EQ(nlohmann::json::parse(bytesOf(o.json))["cases"].size(), 4u);
    // Everything passing: exit 0, and the passes printed without --quiet.
    fs::remove(actual / "fail.png");
    fs::remove(expected / "fail.png");
    fs::remove(actual / "new.png");
    fs::remove(expected / "stale.png");
    o.quiet = false;
    ::testing::internal::CaptureStdout();
    EXPECT_EQ(runReview(o), 0);
    printed = ::testing::internal::GetCapturedStdout();
    EXPECT_NE(printed.find("pass            pass: "), std::string::npos) << printed;
}

} // namespace
} // namespace shadelab::app
