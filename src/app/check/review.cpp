// `shadelab review`'s cases (review.h; docs/ci-engineers.md "review for anyone's PNGs"): the two folders'
// PNGs paired by name, each pair judged against every approved image, the expectations applied, the
// images a page shows written under --out, and what --bless asked for written into EXPECTED_DIR.
#include <algorithm>
#include <cstdio>
#include <map>
#include <utility>

#include "app/check/review.h"
#include "app/check/review_files.h"
#include "shadelab/errors.h"
#include "shadelab/image/image_file.h"
#include "shadelab/io/atomic_file.h"
#include "shadelab/io/text.h"

namespace shadelab::app {
namespace {

namespace fs = std::filesystem;

struct ReviewCaseFiles {
    std::optional<ReviewEntry> actual;
    std::vector<ReviewEntry> approved; // in name order
};

// Cases by name (std::map: sorted, so the index a case's files are named by follows the names). An approved
// NAME.N.png (N digits) is an alternative of case NAME, unless an actual image is called NAME.N itself.
std::map<std::string, ReviewCaseFiles> reviewPairCases(const ReviewOptions& o) {
    std::map<std::string, ReviewCaseFiles> cases;
    for (ReviewEntry& entry : listReviewPngs(o.actualDir, "ACTUAL_DIR"))
        cases[entry.stem].actual = std::move(entry);
    for (ReviewEntry& entry : listReviewPngs(o.expectedDir, "EXPECTED_DIR")) {
        std::string name = entry.stem;
        const auto dot = name.rfind('.');
        const bool numbered = dot != std::string::npos && dot > 0 && dot + 1 < name.size() &&
                              name.find_first_not_of("0123456789", dot + 1) == std::string::npos;
        const auto same = cases.find(name);
        if (numbered && (same == cases.end() || !same->second.actual)) name.resize(dot);
        cases[name].approved.push_back(std::move(entry));
    }
    for (auto& [name, files] : cases)
        std::sort(files.approved.begin(), files.approved.end(),
                  [](const ReviewEntry& a, const ReviewEntry& b) { return a.file < b.file; });
    return cases;
}

// Where the case's images go under --out: named by the case's index, so an untrusted name never becomes a
// path (docs/ci-engineers.md "Where outputs go").
struct ReviewOutFolder {
    fs::path cases; // OUT/cases, empty: no --out

    std::string copy(int index, std::string_view kind, const std::string& bytes) const {
        if (cases.empty()) return {};
        const std::string file = reviewIndexName(index) + "-" + std::string(kind) + ".png";
        writeReviewBytes(cases / file, "--out", bytes);
        return "cases/" + file;
    }
    std::string png(int index, std::string_view kind, const Image& image) const {
        if (cases.empty()) return {};
        const std::string file = reviewIndexName(index) + "-" + std::string(kind) + ".png";
        writePng(image, cases / file, /*inFolder=*/true);
        return "cases/" + file;
    }
};

// The heatmap of the map that says most about this judgement: 1 − SSIM when an SSIM limit is set, else the
// perceptual delta's map (1 anti-aliased, 2 differing).
Image reviewHeatmap(const Judgement& j, const CheckLimits& limits, const PixelSelection* selection) {
    if (limits.ssimMin && j.ssim) {
        MetricMap dissimilarity = j.ssim->map;
        for (float& v : dissimilarity.values) v = 1.0f - v;
        return heatmap(dissimilarity, 0.0f, 1.0f, "1 - SSIM", selection);
    }
    return heatmap(j.perceptual->map, 0.0f, 2.0f, "perceptual: 1 anti-aliased, 2 differing", selection);
}

// Lower is closer: a readable same-size image first, then the fewest failed limits, then the smallest mean.
std::tuple<int, std::size_t, double> reviewDistance(const ApprovedResult& a) {
    if (!a.judgement) return {2, 0, 0.0};
    if (!a.judgement->comparison.sizeMatches) return {1, 0, 0.0};
    return {0, a.judgement->failures.size(), a.judgement->comparison.meanDelta};
}

std::string reviewFailureLine(const CaseResult& c, const ApprovedResult& best) {
    std::string line;
    if (!best.judgement) {
        line = best.error;
    } else if (!best.judgement->comparison.sizeMatches) {
        const Comparison& s = best.judgement->comparison;
        line = "size: actual " + std::to_string(s.actualWidth) + "x" + std::to_string(s.actualHeight) +
               ", approved " + std::to_string(s.expectedWidth) + "x" + std::to_string(s.expectedHeight);
    } else {
        for (const std::string& failure : best.judgement->failures)
            line += (line.empty() ? "" : "; ") + failure;
    }
    if (c.approved.size() > 1)
        line += " (the closest of " + std::to_string(c.approved.size()) + " approved images, " +
                best.expected.filename().string() + ")";
    return line;
}

struct ReviewJudged {
    bool passed = false;
    std::string actualBytes; // kept for --bless; empty when the actual image was not read
};

// Judges one case with an actual image and approved ones; writes its images under --out.
ReviewJudged reviewJudgeCase(CaseResult& c, const ReviewCaseFiles& files, const ReviewOptions& o,
                             const ReviewOutFolder& out, int index) {
    ReviewJudged judged;
    ReviewRead actual = readReviewPng(*files.actual);
    std::optional<ReviewRead> mask;
    std::string maskError;
    if (!o.masks.empty() && actual.error.empty()) {
        const fs::path maskPath = o.masks / files.actual->path.filename();
        if (std::error_code e; fs::exists(fs::symlink_status(maskPath, e))) {
            mask = readReviewPng(reviewEntryAt(maskPath));
            if (!mask->error.empty()) maskError = "--masks: " + mask->error;
        }
    }
    if (!actual.error.empty() || !maskError.empty()) {
        c.message = actual.error.empty() ? maskError : actual.error;
        for (const ReviewEntry& entry : files.approved) c.approved.push_back({entry.path, std::nullopt, ""});
        return judged;
    }
    judged.actualBytes = actual.bytes;
    c.actualFile = out.copy(index, "actual", actual.bytes);
    const Image* maskImage = mask ? &mask->image : nullptr;
    std::vector<ReviewRead> approvedImages;
    std::string notRegular; // an approved entry that is no regular file fails the case whatever else passes
    for (const ReviewEntry& entry : files.approved) {
        ReviewRead read = readReviewPng(entry);
        ApprovedResult result{entry.path, std::nullopt, read.error};
        if (!entry.problem.empty() && notRegular.empty()) notRegular = read.error;
        if (read.error.empty()) {
            try {
                result.judgement = judgeImages(actual.image, read.image, o.limits, maskImage);
            } catch (const InputError& e) { // a mask or --ignore rectangle that does not fit this image
                result.error = e.what();
            }
        }
        c.approved.push_back(std::move(result));
        approvedImages.push_back(std::move(read));
    }
    c.best = 0;
    for (std::size_t i = 0; i < c.approved.size(); ++i) {
        const bool passed = c.approved[i].judgement && c.approved[i].judgement->passed;
        if (passed && !judged.passed) c.best = int(i);
        judged.passed = judged.passed || passed;
        if (!judged.passed && reviewDistance(c.approved[i]) < reviewDistance(c.approved[std::size_t(c.best)]))
            c.best = int(i);
    }
    const ApprovedResult& best = c.approved[std::size_t(c.best)];
    if (!notRegular.empty()) {
        judged.passed = false;
        c.message = notRegular;
    } else if (judged.passed) {
        c.message = judgementFigures(*best.judgement);
    } else {
        c.message = reviewFailureLine(c, best);
    }
    const ReviewRead& expected = approvedImages[std::size_t(c.best)];
    if (!expected.error.empty()) return judged;
    c.expectedFile = out.copy(index, "expected", expected.bytes);
    if (!best.judgement || !best.judgement->comparison.sizeMatches || out.cases.empty()) return judged;
    // The difference image leaves out what the mask and --ignore leave out, as the figures do.
    const std::optional<PixelSelection> selection =
        makeSelection(actual.image.width, actual.image.height, maskImage, o.limits.ignore);
    std::optional<Image> selectionMask;
    if (selection) {
        selectionMask = Image(selection->width, selection->height);
        for (int y = 0; y < selection->height; ++y)
            for (int x = 0; x < selection->width; ++x) {
                const std::uint8_t v = selection->isCounted(x, y) ? 255 : 0;
                std::uint8_t* p = selectionMask->pixel(x, y);
                p[0] = p[1] = p[2] = v;
                p[3] = 255;
            }
    }
    const Image diff = diffImage(actual.image, expected.image, selectionMask ? &*selectionMask : nullptr,
                                 !o.limits.ignoreAlpha);
    c.diffFile = out.png(index, "diff", diff);
    const PixelSelection* counted = selection ? &*selection : nullptr;
    c.heatmapFile = out.png(index, "heatmap", reviewHeatmap(*best.judgement, o.limits, counted));
    return judged;
}

CaseStatus reviewStatus(bool passed, const ExpectationRule* rule) {
    const Expectation expectation = rule ? rule->expectation : Expectation::Pass;
    if (passed) return expectation == Expectation::Fail ? CaseStatus::UnexpectedPass : CaseStatus::Pass;
    if (expectation == Expectation::Fail) return CaseStatus::ExpectedFail;
    if (expectation == Expectation::Flaky) return CaseStatus::FlakyFail;
    return CaseStatus::Fail;
}

} // namespace

ReviewReport reviewFolders(const ReviewOptions& options) {
    ReviewReport report;
    report.options = options;
    const ReviewOptions& o = report.options;
    checkReviewFolder(o.actualDir, "ACTUAL_DIR");
    checkReviewFolder(o.expectedDir, "EXPECTED_DIR");
    if (!o.masks.empty()) checkReviewFolder(o.masks, "--masks");
    auto rules = std::make_shared<std::vector<ExpectationRule>>();
    if (!o.expectations.empty()) *rules = parseExpectations(readReviewText(o.expectations), o.expectations);
    report.rules = rules;
    const std::map<std::string, ReviewCaseFiles> cases = reviewPairCases(o);

    std::vector<fs::path> inputs;
    for (const auto& [name, files] : cases) {
        if (files.actual) inputs.push_back(files.actual->path);
        for (const ReviewEntry& entry : files.approved) inputs.push_back(entry.path);
    }
    if (!o.expectations.empty()) inputs.push_back(o.expectations);
    const ReviewOutFolder out{prepareReviewOutputs(o, inputs)};

    // --bless is checked whole before anything is judged or written: a name that cannot be blessed is bad
    // input (exit 2), and then nothing is blessed.
    for (const std::string& name : o.bless) {
        const auto found = cases.find(name);
        if (found == cases.end())
            throw InputError("--bless: " + quotedValue(name) +
                             " is no case: ACTUAL_DIR has no such .png file");
        if (!found->second.actual)
            throw InputError("--bless: " + quotedValue(name) +
                             " is STALE: it has approved images but no actual image to bless");
        if (!found->second.actual->problem.empty())
            throw InputError("--bless: " + quotedValue(name) + ": ACTUAL_DIR's file is " +
                             found->second.actual->problem + ", not a regular file");
    }
    if (!o.bless.empty() || o.blessFailed) checkReviewBlessFolder(o.expectedDir);

    std::vector<std::pair<std::string, std::string>> toBless; // name, the actual image's bytes
    int index = 0;
    for (const auto& [name, files] : cases) {
        ++index;
        CaseResult c;
        c.name = name;
        if (files.actual) c.actual = files.actual->path;
        c.rule = findExpectation(*rules, name, o.driver);
        const bool blessNamed = std::find(o.bless.begin(), o.bless.end(), name) != o.bless.end();
        std::string bytes;
        if (c.rule && c.rule->expectation == Expectation::Skip) {
            c.status = CaseStatus::Skipped; // not compared: neither image is opened
            c.message = "skipped by " + printable(o.expectations.filename().string()) + ":" +
                        std::to_string(c.rule->line);
            for (const ReviewEntry& entry : files.approved)
                c.approved.push_back({entry.path, std::nullopt, ""});
            if (blessNamed) bytes = readReviewPng(*files.actual).bytes;
        } else if (!files.actual) {
            c.status = CaseStatus::Stale;
            c.message = "approved images but no actual image: the case is gone, or the run did not write it";
            for (const ReviewEntry& entry : files.approved)
                c.approved.push_back({entry.path, std::nullopt, ""});
            if (!out.cases.empty()) {
                const ReviewRead expected = readReviewPng(files.approved.front());
                if (expected.error.empty()) c.expectedFile = out.copy(index, "expected", expected.bytes);
            }
        } else if (files.approved.empty()) {
            const ReviewRead actual = readReviewPng(*files.actual);
            c.status = actual.error.empty() ? CaseStatus::New : CaseStatus::Fail;
            c.message = actual.error.empty() ? "no approved image: look at it, then bless it" : actual.error;
            if (actual.error.empty()) c.actualFile = out.copy(index, "actual", actual.bytes);
            bytes = actual.bytes;
        } else {
            const ReviewJudged judged = reviewJudgeCase(c, files, o, out, index);
            c.status = reviewStatus(judged.passed, c.rule);
            bytes = judged.actualBytes;
        }
        const bool failed = c.status == CaseStatus::Fail || c.status == CaseStatus::New;
        const bool passes = c.status == CaseStatus::Pass || c.status == CaseStatus::UnexpectedPass;
        if ((blessNamed && !passes) || (o.blessFailed && failed && !bytes.empty())) {
            if (bytes.empty())
                throw InputError("--bless: " + quotedValue(name) + ": " + readReviewPng(*files.actual).error);
            toBless.emplace_back(name, std::move(bytes));
        }
        report.cases.push_back(std::move(c));
    }
    // Every target first: a link, FIFO or folder planted at EXPECTED_DIR/NAME.png is refused (exit 2) before
    // any approved image is written, and a bless never writes through a link.
    for (const auto& [name, bytes] : toBless)
        (void)resolveFolderEntry(o.expectedDir, name + ".png", "--bless");
    for (const auto& [name, bytes] : toBless) {
        const fs::path path = o.expectedDir / (name + ".png");
        writeReviewBytes(path, "--bless", bytes);
        report.blessed.push_back(name + " -> " + path.string());
    }
    std::stable_sort(report.cases.begin(), report.cases.end(), [](const CaseResult& a, const CaseResult& b) {
        if (failsRun(a.status) != failsRun(b.status)) return failsRun(a.status);
        return a.name < b.name;
    });
    return report;
}

} // namespace shadelab::app
