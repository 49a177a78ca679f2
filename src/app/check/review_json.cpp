// `review --json FILE` (review.h): every case's status, figures and limits, and the paths of its
// images (relative to --out, null when not written), for a CI step or a dashboard to read.
#include <nlohmann/json.hpp>

#include "app/check/figures_json.h"
#include "app/check/review.h"

namespace shadelab::app {
namespace {

using ReviewJsonValue = nlohmann::json; // named apart: a unity build joins files' namespaces

ReviewJsonValue reviewPathOrNull(const std::string& file) {
    return file.empty() ? ReviewJsonValue(nullptr) : ReviewJsonValue(file);
}

ReviewJsonValue reviewLimitsJson(const CheckLimits& l) {
    ReviewJsonValue out = {
        {"max", l.tolerance.maxDelta},
        {"mean", l.tolerance.meanDelta},
        {"outliers", l.tolerance.outlierBudget},
        {"ignore_alpha", l.ignoreAlpha},
        {"ssim_min", l.ssimMin ? ReviewJsonValue(*l.ssimMin) : ReviewJsonValue(nullptr)},
        {"perceptual_max_pixels",
         l.perceptualMaxPixels ? ReviewJsonValue(*l.perceptualMaxPixels) : ReviewJsonValue(nullptr)},
        {"perceptual_threshold", l.perceptualThreshold},
    };
    ReviewJsonValue rects = ReviewJsonValue::array();
    for (const IgnoreRect& r : l.ignore)
        rects.push_back({{"x", r.x}, {"y", r.y}, {"width", r.width}, {"height", r.height}});
    out["ignore"] = rects;
    return out;
}

ReviewJsonValue reviewApprovedJson(const ApprovedResult& a, const CheckLimits& limits) {
    ReviewJsonValue out = {{"path", a.expected.string()}};
    if (!a.judgement) {
        out["passed"] = false;
        out["error"] = a.error.empty() ? ReviewJsonValue(nullptr)
                                       : ReviewJsonValue(a.error); // null: not read (skipped, stale)
        return out;
    }
    const Judgement& j = *a.judgement;
    const Comparison& c = j.comparison;
    out["passed"] = j.passed;
    out["failures"] = j.failures;
    out["size"] = {{"actual", {c.actualWidth, c.actualHeight}},
                   {"expected", {c.expectedWidth, c.expectedHeight}}};
    addFiguresJson(out, j, limits);
    return out;
}

const char* reviewExpectationName(Expectation e) {
    switch (e) {
    case Expectation::Pass:
        return "PASS";
    case Expectation::Fail:
        return "FAIL";
    case Expectation::Skip:
        return "SKIP";
    case Expectation::Flaky:
        return "FLAKY";
    }
    return "PASS";
}

} // namespace

std::string reviewJson(const ReviewReport& report) {
    const ReviewOptions& o = report.options;
    ReviewJsonValue counts = ReviewJsonValue::object();
    for (CaseStatus s :
         {CaseStatus::Pass, CaseStatus::Fail, CaseStatus::New, CaseStatus::Stale, CaseStatus::Skipped,
          CaseStatus::ExpectedFail, CaseStatus::UnexpectedPass, CaseStatus::FlakyFail})
        counts[statusName(s)] = report.count(s);
    ReviewJsonValue cases = ReviewJsonValue::array();
    for (const CaseResult& c : report.cases) {
        ReviewJsonValue approved = ReviewJsonValue::array();
        for (const ApprovedResult& a : c.approved) approved.push_back(reviewApprovedJson(a, o.limits));
        cases.push_back({
            {"name", c.name},
            {"status", statusName(c.status)},
            {"expectation", reviewExpectationName(c.rule ? c.rule->expectation : Expectation::Pass)},
            {"rule_line", c.rule ? ReviewJsonValue(c.rule->line) : ReviewJsonValue(nullptr)},
            {"bug", c.rule && !c.rule->comment.empty() ? ReviewJsonValue(c.rule->comment)
                                                       : ReviewJsonValue(nullptr)},
            {"message", c.message},
            {"actual", c.actual ? ReviewJsonValue(c.actual->string()) : ReviewJsonValue(nullptr)},
            {"approved", approved},
            {"best", c.best >= 0 ? ReviewJsonValue(c.best) : ReviewJsonValue(nullptr)},
            {"files",
             {{"actual", reviewPathOrNull(c.actualFile)},
              {"expected", reviewPathOrNull(c.expectedFile)},
              {"diff", reviewPathOrNull(c.diffFile)},
              {"heatmap", reviewPathOrNull(c.heatmapFile)}}},
        });
    }
    const ReviewJsonValue root = {
        {"driver", o.driver}, {"limits", reviewLimitsJson(o.limits)},
        {"counts", counts},   {"passed", !report.failed()},
        {"cases", cases},     {"blessed", report.blessed},
    };
    // A file name is untrusted bytes: what is not UTF-8 is replaced (U+FFFD) rather than refused, so the
    // summary is always written.
    return root.dump(2, ' ', false, ReviewJsonValue::error_handler_t::replace) + "\n";
}

} // namespace shadelab::app
