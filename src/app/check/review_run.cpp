// `shadelab review` put together (review.h): the cases judged, then the page, the JSON and the JUnit
// written, one line a case and a summary printed, and the exit status (DESIGN §5: 0 pass, 1 a failure,
// 2 bad input, the last thrown as InputError before any output is written).
#include <algorithm>
#include <array>
#include <cstdio>

#include "app/check/review.h"
#include "app/check/review_files.h"
#include "shadelab/errors.h"
#include "shadelab/io/atomic_file.h"
#include "shadelab/io/text.h"

namespace shadelab::app {
namespace {

constexpr std::array kReviewStatuses{
    CaseStatus::Pass,           CaseStatus::Fail,     CaseStatus::New,
    CaseStatus::Stale,          CaseStatus::Skipped,  CaseStatus::ExpectedFail,
    CaseStatus::UnexpectedPass, CaseStatus::FlakyFail};

void writeReviewText(const std::filesystem::path& path, std::string_view what, const std::string& text,
                     OutputRule rule) {
    writeFileAtomically(
        path, what,
        [&](std::FILE* file) {
            if (std::fwrite(text.data(), 1, text.size(), file) != text.size())
                failWrite(what, path, "short write");
        },
        rule);
}

std::string reviewNumber(double value, const char* format) {
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

} // namespace

const char* statusName(CaseStatus status) {
    switch (status) {
    case CaseStatus::Pass:
        return "pass";
    case CaseStatus::Fail:
        return "FAIL";
    case CaseStatus::New:
        return "NEW";
    case CaseStatus::Stale:
        return "STALE";
    case CaseStatus::Skipped:
        return "skip";
    case CaseStatus::ExpectedFail:
        return "expected-fail";
    case CaseStatus::UnexpectedPass:
        return "unexpected-pass";
    case CaseStatus::FlakyFail:
        return "flaky-fail";
    }
    return "?";
}

bool failsRun(CaseStatus status) {
    return status == CaseStatus::Fail || status == CaseStatus::New || status == CaseStatus::Stale ||
           status == CaseStatus::UnexpectedPass;
}

int ReviewReport::count(CaseStatus status) const {
    return int(
        std::count_if(cases.begin(), cases.end(), [&](const CaseResult& c) { return c.status == status; }));
}

bool ReviewReport::failed() const {
    return std::any_of(cases.begin(), cases.end(), [](const CaseResult& c) { return failsRun(c.status); });
}

std::string judgementFigures(const Judgement& j) {
    const Comparison& c = j.comparison;
    if (!c.sizeMatches)
        return "size: actual " + std::to_string(c.actualWidth) + "x" + std::to_string(c.actualHeight) +
               ", approved " + std::to_string(c.expectedWidth) + "x" + std::to_string(c.expectedHeight);
    std::string text = "max " + std::to_string(c.maxDelta) + ", mean " + reviewNumber(c.meanDelta, "%.4f") +
                       ", outliers " + std::to_string(c.outliers) + "/" + std::to_string(c.comparedPixels);
    if (j.ssim) text += ", SSIM " + reviewNumber(j.ssim->mean, "%.5f");
    if (j.perceptual)
        text += ", perceptual " + std::to_string(j.perceptual->differingPixels) + " px (" +
                std::to_string(j.perceptual->antialiasedPixels) + " anti-aliased)";
    return text;
}

int runReview(const ReviewOptions& options) {
    const ReviewReport report = reviewFolders(options);
    const ReviewOptions& o = report.options;
    if (!o.out.empty())
        writeReviewText(o.out / "index.html", "--out", reviewPageHtml(report, o.out), OutputRule::InFolder);
    if (!o.json.empty()) writeReviewText(o.json, "--json", reviewJson(report), OutputRule::Anywhere);
    if (!o.junit.empty()) writeReviewText(o.junit, "--junit", junitXml(report), OutputRule::Anywhere);

    for (const CaseResult& c : report.cases) {
        if (o.quiet && !failsRun(c.status)) continue;
        std::printf("%-15s %s: %s\n", statusName(c.status), printable(c.name).c_str(),
                    printable(c.message).c_str());
    }
    for (const std::string& line : report.blessed) std::printf("blessed: %s\n", printable(line).c_str());
    for (const std::string& name : o.bless) {
        const auto c = std::find_if(report.cases.begin(), report.cases.end(),
                                    [&](const CaseResult& r) { return r.name == name; });
        if (c != report.cases.end() &&
            (c->status == CaseStatus::Pass || c->status == CaseStatus::UnexpectedPass))
            std::printf("not blessed: %s passes; a passing case's approved images stand\n",
                        printable(name).c_str());
    }
    std::string summary = "review: " + std::to_string(report.cases.size()) + " cases";
    for (CaseStatus status : kReviewStatuses)
        if (const int n = report.count(status); n > 0)
            summary += ", " + std::to_string(n) + " " + statusName(status);
    if (!o.out.empty()) summary += "; the page: " + printable((o.out / "index.html").string());
    std::printf("%s\n", summary.c_str());
    return report.failed() ? kExitRuntimeError : kExitOk;
}

} // namespace shadelab::app
