// `shadelab review ACTUAL_DIR EXPECTED_DIR`: the regression kit for anyone's PNGs (docs/ci-engineers.md).
// Pairs the two folders' PNGs by name, judges each pair (compare/judge.h) against the limits and the
// expectations file, and writes what a CI job reads: a summary, JSON, JUnit XML and one self-contained page.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "shadelab/compare/judge.h"

namespace shadelab::app {

// ---- the expectations file (src/app/check/expectations.cpp) ----
// One rule a line: `CASE  DRIVER-GLOB  PASS|FAIL|SKIP|FLAKY  # bug link or reason`; blank lines and lines
// starting with # are comments. CASE is a case name or a glob, DRIVER-GLOB a glob over the driver key
// (fnmatch, no flags). The first rule whose two globs match a case decides it; no rule means PASS.
enum class Expectation { Pass, Fail, Skip, Flaky };
struct ExpectationRule {
    std::string caseGlob, driverGlob;
    Expectation expectation = Expectation::Pass;
    std::string comment; // after '#', trimmed: the bug link
    int line = 0;        // 1-based, for messages
};
// Throws InputError "FILE:LINE: field: got 'value' (fix)" for a malformed line.
std::vector<ExpectationRule> parseExpectations(const std::string& text, const std::string& fileName);
// The first rule matching (name, driver), or nullptr.
const ExpectationRule* findExpectation(const std::vector<ExpectationRule>& rules, const std::string& name,
                                       const std::string& driver);

// ---- one case ----
enum class CaseStatus {
    Pass,    // within the limits of at least one approved image (and expected to pass)
    Fail,    // beyond the limits of every approved image (or a size mismatch, or unreadable)
    New,     // an actual image with no approved image: nothing to hold it to (fails; bless it)
    Stale,   // approved images with no actual image: the case is gone or the run did not write it (fails)
    Skipped, // SKIP in the expectations: not compared
    ExpectedFail,   // FAIL in the expectations and it fails: does not fail the run
    UnexpectedPass, // FAIL in the expectations but it passes: fails the run (remove the rule)
    FlakyFail,      // FLAKY in the expectations and it fails: reported, does not fail the run
};
const char* statusName(CaseStatus status); // "pass", "FAIL", "NEW", "STALE", "skip", "expected-fail", ...
bool failsRun(CaseStatus status);

struct ApprovedResult {                 // the case's actual image against one approved image
    std::filesystem::path expected;     // EXPECTED_DIR/NAME.png or an alternative NAME.N.png
    std::optional<Judgement> judgement; // nullopt: unreadable (error says why)
    std::string error;
};
struct CaseResult {
    std::string name; // the file name without .png: untrusted text
    CaseStatus status = CaseStatus::Pass;
    const ExpectationRule* rule = nullptr; // the expectation that decided it, if any
    std::optional<std::filesystem::path> actual;
    std::vector<ApprovedResult> approved; // every approved image, in name order
    int best = -1;                        // the index in `approved` that passed, else the closest one
    std::string message;                  // one line: the failed limits with figures, or why
    // Files written under --out (relative to the out folder), empty when not written.
    std::string actualFile, expectedFile, diffFile, heatmapFile;
};

struct ReviewOptions {
    std::filesystem::path actualDir, expectedDir;
    std::filesystem::path out;          // --out DIR: index.html and the cases' images; empty: no page
    std::filesystem::path json, junit;  // --json FILE, --junit FILE; empty: not written
    std::filesystem::path expectations; // --expectations FILE; empty: every case PASS
    std::filesystem::path masks;        // --masks DIR: DIR/NAME.png is case NAME's mask (black = left out)
    std::string driver;                 // --driver KEY, matched by the rules' driver globs ("" matches "*")
    CheckLimits limits;                 // the same flags as compare
    std::vector<std::string> bless;     // --bless NAME (repeatable): write these cases' actual images
    bool blessFailed = false;           // --bless-failed: write every FAIL and NEW case's actual image
    bool quiet = false;                 // --quiet: only failures on standard output
};

struct ReviewReport {
    ReviewOptions options;
    std::vector<CaseResult> cases;    // failures first, then by name
    std::vector<std::string> blessed; // what --bless wrote, as "NAME -> PATH"
    // The parsed expectations file that CaseResult::rule points into; shared, so a copied report's
    // pointers stay valid.
    std::shared_ptr<const std::vector<ExpectationRule>> rules;
    int count(CaseStatus status) const;
    bool failed() const; // any case whose status fails the run
};

// Judges every case (throws InputError for bad input: exit 2), blesses what was asked, writes --out,
// --json and --junit, and prints one line a case and a summary. Exit 0 all pass, 1 a failure.
int runReview(const ReviewOptions& options);

// A judgement's figures in one line ("max 3, mean 0.0120, outliers 0/40000, SSIM 0.99870, perceptual 0 px
// (2 anti-aliased)"): what the summary line, the JUnit failure and the page show (review_run.cpp).
std::string judgementFigures(const Judgement& judgement);

// The pieces runReview puts together, each testable alone:
ReviewReport reviewFolders(const ReviewOptions& options); // src/app/check/review.cpp
std::string reviewJson(const ReviewReport& report);       // src/app/check/review_json.cpp
std::string junitXml(const ReviewReport& report);         // src/app/check/junit.cpp
// The page: one HTML file with every image inlined as a data: URI, its script and style inlined, no
// network; every name and message HTML-escaped. Reads the images the report's *File fields name under `out`.
std::string reviewPageHtml(const ReviewReport& report, const std::filesystem::path& out); // review_page.cpp

} // namespace shadelab::app
