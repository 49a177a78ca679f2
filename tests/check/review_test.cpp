// `shadelab review`'s cases end to end through reviewFolders (app/check/review.h): pairing by name, the
// statuses, several approved images, the expectations file's FAIL, SKIP and FLAKY, files that are not
// regular, the images written under --out, and what is refused as bad input.
#include <sys/stat.h>
#include <unistd.h>

#include "check/review_fixture.h"
#include "shadelab/errors.h"

namespace shadelab::app {
namespace {

namespace fs = std::filesystem;

class Review : public ReviewFixture {};

TEST_F(Review, PairsByNameAndPutsFailuresFirst) {
    put(actual, "a-same", grey(16, 16, 100));
    put(expected, "a-same", grey(16, 16, 100));
    put(actual, "b-differs", grey(16, 16, 100, 200));
    put(expected, "b-differs", grey(16, 16, 100));
    put(actual, "c-new", grey(16, 16, 100));
    put(expected, "d-stale", grey(16, 16, 100));
    writeText(actual / "notes.txt", "not a png"); // only *.png files are cases
    const ReviewReport report = reviewFolders(options());
    ASSERT_EQ(report.cases.size(), 4u);
    EXPECT_EQ(report.cases[0].name, "b-differs");
    EXPECT_EQ(report.cases[0].status, CaseStatus::Fail);
    EXPECT_EQ(report.cases[1].name, "c-new");
    EXPECT_EQ(report.cases[1].status, CaseStatus::New);
    EXPECT_EQ(report.cases[2].name, "d-stale");
    EXPECT_EQ(report.cases[2].status, CaseStatus::Stale);
    EXPECT_EQ(report.cases[3].name, "a-same");
    EXPECT_EQ(report.cases[3].status, CaseStatus::Pass);
    EXPECT_TRUE(report.failed());
    EXPECT_EQ(report.count(CaseStatus::Fail), 1);
    EXPECT_NE(report.cases[0].message.find("max"), std::string::npos) << report.cases[0].message;
}

TEST_F(Review, ASizeMismatchFailsWithBothSizes) {
    put(actual, "s", grey(17, 16, 100));
    put(expected, "s", grey(16, 16, 100));
    const ReviewReport report = reviewFolders(options());
    const CaseResult& c = caseNamed(report, "s");
    EXPECT_EQ(c.status, CaseStatus::Fail);
    EXPECT_NE(c.message.find("17x16"), std::string::npos) << c.message;
    EXPECT_NE(c.message.find("16x16"), std::string::npos) << c.message;
}

TEST_F(Review, AnyApprovedImagePassingPassesTheCase) {
    put(actual, "shot", grey(16, 16, 100));
    put(expected, "shot", grey(16, 16, 90));    // in name order: shot.1.png, shot.2.png, shot.png; the first
    put(expected, "shot.1", grey(16, 16, 80));  // and the last fail...
    put(expected, "shot.2", grey(16, 16, 100)); // ...the one between passes
    put(actual, "v1.5", grey(16, 16, 30));      // an actual image named like an alternative is its own case
    put(expected, "v1.5", grey(16, 16, 30));
    put(actual, "two", grey(16, 16, 50));
    put(expected, "two", grey(16, 16, 60));
    put(expected, "two.1", grey(16, 16, 52)); // neither passes: the failure names the closest
    ReviewOptions o = options();
    o.limits.tolerance.maxDelta = 0;
    const ReviewReport report = reviewFolders(o);
    const CaseResult& shot = caseNamed(report, "shot");
    EXPECT_EQ(shot.status, CaseStatus::Pass);
    ASSERT_EQ(shot.approved.size(), 3u);
    EXPECT_EQ(shot.approved[shot.best].expected.filename(), "shot.2.png");
    EXPECT_EQ(caseNamed(report, "v1.5").status, CaseStatus::Pass);
    EXPECT_EQ(caseNamed(report, "v1.5").approved.size(), 1u);
    const CaseResult& two = caseNamed(report, "two");
    EXPECT_EQ(two.status, CaseStatus::Fail);
    EXPECT_EQ(two.approved[two.best].expected.filename(), "two.1.png");
    EXPECT_NE(two.message.find("two.1.png"), std::string::npos) << two.message;
    EXPECT_EQ(report.cases.size(), 3u);
}

TEST_F(Review, AFailingFlakyCaseDoesNotFailTheRun) {
    put(actual, "flaky", grey(16, 16, 100, 200));
    put(expected, "flaky", grey(16, 16, 100));
    put(actual, "steady", grey(16, 16, 100));
    put(expected, "steady", grey(16, 16, 100));
    writeText(root / "exp.txt", "flaky llvm* FLAKY # https://example.org/34\nsteady * FLAKY\n");
    ReviewOptions o = options();
    o.expectations = root / "exp.txt";
    o.driver = "llvmpipe";
    ReviewReport report = reviewFolders(o);
    EXPECT_EQ(caseNamed(report, "flaky").status, CaseStatus::FlakyFail);
    ASSERT_NE(caseNamed(report, "flaky").rule, nullptr);
    EXPECT_EQ(caseNamed(report, "flaky").rule->comment, "https://example.org/34");
    EXPECT_EQ(caseNamed(report, "steady").status, CaseStatus::Pass);
    EXPECT_FALSE(report.failed());
    o.driver = "softpipe"; // the rule's driver glob does not match: a plain failure
    report = reviewFolders(o);
    EXPECT_EQ(caseNamed(report, "flaky").status, CaseStatus::Fail);
    EXPECT_TRUE(report.failed());
}

TEST_F(Review, ASkippedCaseIsNotCompared) {
    // Neither file could be compared: the actual is not a PNG, the approved image another size. Read, either
    // would fail the case; skipped, neither is opened.
    writeText(actual / "broken.png", "not a png at all");
    put(expected, "broken", grey(19, 19, 0));
    writeText(root / "exp.txt", "bro* * SKIP # no GL 3.3\n");
    ReviewOptions o = options();
    o.expectations = root / "exp.txt";
    const ReviewReport report = reviewFolders(o);
    const CaseResult& c = caseNamed(report, "broken");
    EXPECT_EQ(c.status, CaseStatus::Skipped);
    ASSERT_EQ(c.approved.size(), 1u);
    EXPECT_FALSE(c.approved[0].judgement.has_value());
    EXPECT_EQ(c.approved[0].error, "");
    EXPECT_FALSE(report.failed());
    o.expectations.clear(); // without the rule the same pair fails
    EXPECT_EQ(caseNamed(reviewFolders(o), "broken").status, CaseStatus::Fail);
}

TEST_F(Review, AFailRuleExpectsAFailureAndAPassFailsTheRun) {
    put(actual, "known-bug", grey(16, 16, 100, 200));
    put(expected, "known-bug", grey(16, 16, 100));
    writeText(root / "exp.txt", "known-bug * FAIL # https://example.org/12\nfixed * FAIL\n");
    ReviewOptions o = options();
    o.expectations = root / "exp.txt";
    ReviewReport report = reviewFolders(o);
    EXPECT_EQ(caseNamed(report, "known-bug").status, CaseStatus::ExpectedFail);
    EXPECT_FALSE(report.failed());
    put(actual, "fixed", grey(16, 16, 7));
    put(expected, "fixed", grey(16, 16, 7));
    report = reviewFolders(o);
    EXPECT_EQ(caseNamed(report, "fixed").status, CaseStatus::UnexpectedPass);
    EXPECT_TRUE(report.failed());
    EXPECT_EQ(report.cases.front().name, "fixed"); // a failure of the run: first
}

TEST_F(Review, FilesThatAreNotRegularAreFailedCasesNeverOpened) {
    put(root, "outside", grey(16, 16, 100));
    put(expected, "linked", grey(16, 16, 100));
    fs::create_symlink(root / "outside.png", actual / "linked.png");
    ASSERT_EQ(::mkfifo((actual / "fifo.png").c_str(), 0600), 0);
    put(expected, "fifo", grey(16, 16, 100));
    put(actual, "planted", grey(16, 16, 100));
    put(expected, "planted", grey(16, 16, 100));                          // passes...
    fs::create_symlink(root / "outside.png", expected / "planted.2.png"); // ...but a link sits beside it
    ::alarm(20); // a blocking open of the FIFO would hang: the alarm ends the test instead
    const ReviewReport report = reviewFolders(options());
    ::alarm(0);
    const CaseResult& linked = caseNamed(report, "linked");
    EXPECT_EQ(linked.status, CaseStatus::Fail);
    EXPECT_NE(linked.message.find("symbolic link"), std::string::npos) << linked.message;
    const CaseResult& fifo = caseNamed(report, "fifo");
    EXPECT_EQ(fifo.status, CaseStatus::Fail);
    EXPECT_NE(fifo.message.find("FIFO"), std::string::npos) << fifo.message;
    const CaseResult& planted = caseNamed(report, "planted");
    EXPECT_EQ(planted.status, CaseStatus::Fail);
    EXPECT_NE(planted.message.find("planted.2.png"), std::string::npos) << planted.message;
}

TEST_F(Review, OutHoldsEachCasesImagesNamedByIndex) {
    const std::string hostile = "a\"<script>&'";
    put(actual, hostile, grey(16, 16, 100, 250));
    put(expected, hostile, grey(16, 16, 100));
    put(actual, "masked", grey(16, 16, 100, 250));
    put(expected, "masked", grey(16, 16, 100));
    put(actual, "zz-new", grey(16, 16, 1));
    ReviewOptions o = options();
    o.out = root / "page";
    const ReviewReport report = reviewFolders(o);
    const CaseResult& h = caseNamed(report, hostile);
    EXPECT_EQ(h.actualFile, "cases/0001-actual.png");
    EXPECT_EQ(h.expectedFile, "cases/0001-expected.png");
    EXPECT_EQ(h.diffFile, "cases/0001-diff.png");
    EXPECT_EQ(h.heatmapFile, "cases/0001-heatmap.png");
    EXPECT_EQ(bytesOf(o.out / h.actualFile), bytesOf(actual / (hostile + ".png")));
    EXPECT_EQ(bytesOf(o.out / h.expectedFile), bytesOf(expected / (hostile + ".png")));
    const Image diff = readPng(o.out / h.diffFile);
    EXPECT_EQ(diff.pixel(1, 1)[0], 255); // |250 − 100|·8, clamped
    EXPECT_EQ(diff.pixel(0, 0)[0], 0);
    EXPECT_TRUE(fs::is_regular_file(o.out / h.heatmapFile));
    const CaseResult& n = caseNamed(report, "zz-new");
    EXPECT_EQ(n.actualFile, "cases/0003-actual.png");
    EXPECT_EQ(n.expectedFile, "");
    EXPECT_EQ(n.diffFile, "");
    // The difference image leaves out what --ignore leaves out, drawn as the left-out grey.
    o.limits.ignore = {IgnoreRect{1, 1, 1, 1}};
    const ReviewReport ignored = reviewFolders(o);
    const CaseResult& m = caseNamed(ignored, "masked");
    EXPECT_EQ(m.status, CaseStatus::Pass);
    if (!m.diffFile.empty()) {
        const Image leftOut = readPng(o.out / m.diffFile);
        EXPECT_EQ(leftOut.pixel(1, 1)[0], kDiffLeftOut.x);
    }
}

TEST_F(Review, TheDifferenceImageHonoursTheSelectionOfAFailingCase) {
    Image changed = grey(16, 16, 100, 250);
    changed.pixel(4, 4)[0] = 0; // a second difference, outside the ignored rectangle: the case still fails
    put(actual, "c", changed);
    put(expected, "c", grey(16, 16, 100));
    ReviewOptions o = options();
    o.out = root / "page";
    o.limits.ignore = {IgnoreRect{1, 1, 1, 1}};
    const ReviewReport report = reviewFolders(o);
    const CaseResult& c = caseNamed(report, "c");
    ASSERT_EQ(c.status, CaseStatus::Fail);
    ASSERT_FALSE(c.diffFile.empty());
    const Image diff = readPng(o.out / c.diffFile);
    EXPECT_EQ(diff.pixel(1, 1)[0], kDiffLeftOut.x); // left out, though it differs
    EXPECT_EQ(diff.pixel(4, 4)[0], 255);
}

TEST_F(Review, ACasesMaskLeavesItsBlackPixelsOut) {
    put(actual, "masked", grey(16, 16, 100, 250));
    put(expected, "masked", grey(16, 16, 100));
    put(actual, "unmasked", grey(16, 16, 100, 250)); // no mask of its own: every pixel counts
    put(expected, "unmasked", grey(16, 16, 100));
    fs::create_directories(root / "masks");
    put(root / "masks", "masked", grey(16, 16, 255, 0)); // black at the differing pixel (1, 1)
    ReviewOptions o = options();
    o.masks = root / "masks";
    const ReviewReport report = reviewFolders(o);
    EXPECT_EQ(caseNamed(report, "masked").status, CaseStatus::Pass);
    EXPECT_EQ(caseNamed(report, "unmasked").status, CaseStatus::Fail);
}

TEST_F(Review, AnOutputThatIsAnInputIsRefused) {
    put(actual, "a", grey(16, 16, 100));
    put(expected, "a", grey(16, 16, 100));
    ReviewOptions o = options();
    o.json = expected / "a.png";
    EXPECT_THROW((void)reviewFolders(o), InputError);
    EXPECT_EQ(bytesOf(expected / "a.png"), bytesOf(actual / "a.png"));
    o = options();
    o.out = actual;
    EXPECT_THROW((void)reviewFolders(o), InputError);
    o = options();
    o.expectedDir = root / "missing";
    EXPECT_THROW((void)reviewFolders(o), InputError);
}

} // namespace
} // namespace shadelab::app
