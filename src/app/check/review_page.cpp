// The review page (review.h reviewPageHtml): one HTML file a person judges a run from in seconds
// (docs/ci-engineers.md "The review page"). Everything it shows is inlined — images as data: URIs, its
// script and style from review_page.js and .css — and its Content-Security-Policy forbids every load, so it
// opens from file:// with no server and reaches no network. Every name, message and path is untrusted
// text: it reaches the page through reviewPageText() only, and the script reads nothing but attributes.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string_view>
#include <utility>

#include "app/check/review.h"
#include "app/check/review_page_assets.h"
#include "shadelab/errors.h"
#include "shadelab/io/text.h"

namespace shadelab::app {
namespace {

// `text` as HTML text or a quoted attribute's value: control characters, bidi overrides and invalid UTF-8
// escaped by printable() (a file name's bytes are anybody's), then the five characters markup reads.
std::string reviewPageText(std::string_view text) {
    static constexpr std::pair<char, std::string_view> kEntities[] = {
        {'&', "&amp;"}, {'<', "&lt;"}, {'>', "&gt;"}, {'"', "&quot;"}, {'\'', "&#39;"}};
    std::string out;
    for (char c : printable(text)) {
        const auto* entity = std::find_if(std::begin(kEntities), std::end(kEntities),
                                          [c](const auto& e) { return e.first == c; });
        if (entity != std::end(kEntities))
            out += entity->second;
        else
            out += c;
    }
    return out;
}

std::string reviewPageBase64(const std::string& bytes) {
    static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t left = bytes.size() - i;
        const unsigned b0 = static_cast<unsigned char>(bytes[i]);
        const unsigned b1 = left > 1 ? static_cast<unsigned char>(bytes[i + 1]) : 0;
        const unsigned b2 = left > 2 ? static_cast<unsigned char>(bytes[i + 2]) : 0;
        const unsigned triple = (b0 << 16) | (b1 << 8) | b2;
        out += kAlphabet[(triple >> 18) & 63];
        out += kAlphabet[(triple >> 12) & 63];
        out += left > 1 ? kAlphabet[(triple >> 6) & 63] : '=';
        out += left > 2 ? kAlphabet[triple & 63] : '=';
    }
    return out;
}

std::string reviewPageNumber(double value, const char* format = "%.6g") {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// A PNG read for the page: its bytes, and its size from the IHDR chunk (the page sizes the picture in CSS
// pixels × zoom, so that scaling stays pixelated and every layer lines up).
struct PagePng {
    std::string bytes;
    unsigned width = 0, height = 0;
};
// The size in a PNG's first 24 bytes (signature, IHDR length and type, width, height), or false.
bool readIhdrSize(std::string_view head, unsigned& width, unsigned& height) {
    static constexpr std::string_view kSignature = "\x89PNG\r\n\x1a\n";
    if (head.size() < 24 || head.substr(0, 8) != kSignature || head.substr(12, 4) != "IHDR") return false;
    const auto be32 = [&](std::size_t at) {
        unsigned value = 0;
        for (std::size_t i = 0; i < 4; ++i) value = (value << 8) | static_cast<unsigned char>(head[at + i]);
        return value;
    };
    width = be32(16);
    height = be32(20);
    return width > 0 && height > 0;
}
std::optional<PagePng> readPagePng(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) return std::nullopt;
    PagePng png{std::string(std::istreambuf_iterator<char>(file), {}), 0, 0};
    if (!readIhdrSize(png.bytes, png.width, png.height)) return std::nullopt;
    return png;
}
// The zoom a case opens at: the largest of the menu's that shows its picture at most about 240 CSS pixels
// wide (an 80-pixel test image at 3×, a full-size render at 1×); the menu changes it.
constexpr unsigned kZooms[] = {1, 2, 3, 4, 6, 8, 12, 16};
unsigned openingZoom(const std::filesystem::path& picture) {
    std::ifstream file(picture, std::ios::binary);
    std::string head(24, '\0');
    unsigned width = 0, height = 0;
    if (!file.read(head.data(), 24) || !readIhdrSize(head, width, height)) return 1;
    unsigned zoom = 1;
    for (unsigned z : kZooms)
        if (z * width <= 240) zoom = z;
    return zoom;
}

// Where a case goes on the page: what fails the run first, then what was expected to fail or is flaky,
// then the passing (folded), then the skipped (listed).
enum class PageGroup { Failing, Expected, Passing, Skipped };
PageGroup pageGroup(CaseStatus status) {
    switch (status) {
    case CaseStatus::Fail:
    case CaseStatus::New:
    case CaseStatus::Stale:
    case CaseStatus::UnexpectedPass:
        return PageGroup::Failing;
    case CaseStatus::ExpectedFail:
    case CaseStatus::FlakyFail:
        return PageGroup::Expected;
    case CaseStatus::Pass:
        return PageGroup::Passing;
    case CaseStatus::Skipped:
        return PageGroup::Skipped;
    }
    return PageGroup::Failing;
}
constexpr const char* kGroupClasses[] = {"g-fail", "g-expected", "g-pass", "g-skip"}; // by PageGroup
// By Expectation: the expectations file's own spelling.
constexpr const char* kPageExpectationWords[] = {"PASS", "FAIL", "SKIP", "FLAKY"};

// A rule's comment as a link when it is one an engineer can follow (http or https, nothing a browser would
// run or resolve locally), otherwise as text.
std::string bugLink(const std::string& comment) {
    const bool web = comment.rfind("https://", 0) == 0 || comment.rfind("http://", 0) == 0;
    const bool plain = std::none_of(comment.begin(), comment.end(),
                                    [](char c) { return static_cast<unsigned char>(c) <= ' ' || c == '"'; });
    if (web && plain)
        return "<a href=\"" + reviewPageText(comment) + "\" rel=\"noreferrer noopener\" target=\"_blank\">" +
               reviewPageText(comment) + "</a>";
    return reviewPageText(comment);
}

struct FigureRow {
    std::string figure, value, limit;
    bool failed = false;
};
// Every figure of the closest approved image's judgement beside the limit it was held to.
std::vector<FigureRow> figureRows(const Judgement& judgement, const CheckLimits& limits) {
    std::vector<FigureRow> rows;
    const Comparison& c = judgement.comparison;
    if (!c.sizeMatches) {
        rows.push_back(
            {"size", std::to_string(c.actualWidth) + "×" + std::to_string(c.actualHeight),
             "the reference's " + std::to_string(c.expectedWidth) + "×" + std::to_string(c.expectedHeight),
             true});
        return rows;
    }
    const Tolerance& t = c.tolerance;
    const bool tooManyOutliers = c.outliers > t.outlierBudget;
    rows.push_back({"max channel difference", std::to_string(c.maxDelta),
                    "≤ " + std::to_string(t.maxDelta) + " but for the outlier budget", tooManyOutliers});
    rows.push_back({"pixels beyond max", std::to_string(c.outliers), "≤ " + std::to_string(t.outlierBudget),
                    tooManyOutliers});
    rows.push_back({"mean channel difference", reviewPageNumber(c.meanDelta, "%.4f"),
                    "≤ " + reviewPageNumber(t.meanDelta), c.meanDelta > t.meanDelta});
    if (judgement.ssim) {
        const double mean = judgement.ssim->mean;
        rows.push_back({"SSIM", reviewPageNumber(mean, "%.5f"),
                        limits.ssimMin ? "≥ " + reviewPageNumber(*limits.ssimMin) : "no limit",
                        limits.ssimMin && mean < *limits.ssimMin});
    }
    if (judgement.perceptual) {
        const PerceptualResult& p = *judgement.perceptual;
        rows.push_back(
            {"perceptual pixels (threshold " + reviewPageNumber(limits.perceptualThreshold) + ")",
             std::to_string(p.differingPixels) + " (+" + std::to_string(p.antialiasedPixels) + " AA)",
             limits.perceptualMaxPixels ? "≤ " + std::to_string(*limits.perceptualMaxPixels) : "no limit",
             limits.perceptualMaxPixels && p.differingPixels > *limits.perceptualMaxPixels});
    }

    return rows;
}

std::string limitsText(const CheckLimits& limits) {
    std::string text = "max " + std::to_string(limits.tolerance.maxDelta) + ", mean " +
                       reviewPageNumber(limits.tolerance.meanDelta) + ", outliers " +
                       std::to_string(limits.tolerance.outlierBudget);
    if (limits.ignoreAlpha) text += ", alpha ignored";
    if (limits.ssimMin) text += ", SSIM ≥ " + reviewPageNumber(*limits.ssimMin);
    if (limits.perceptualMaxPixels)
        text += ", perceptual pixels ≤ " + std::to_string(*limits.perceptualMaxPixels) + " at threshold " +
                reviewPageNumber(limits.perceptualThreshold);
    if (!limits.ignore.empty()) text += ", " + std::to_string(limits.ignore.size()) + " ignored rectangle(s)";
    return text;
}

// The page, written case by case.
class PageWriter {
public:
    PageWriter(const ReviewReport& report, std::filesystem::path out)
        : report_(report), out_(std::move(out)) {}

    std::string write();

private:
    // An <img> of the file `name` under the out folder, or a line saying why there is none.
    std::string image(const std::string& name, const char* role, const char* alt) {
        const std::optional<PagePng> png = name.empty() ? std::nullopt : readPagePng(out_ / name);
        if (!png)
            return std::string("<p class=\"missing\">") + alt + ": " +
                   (name.empty() ? std::string("none") : "unreadable " + reviewPageText(name)) + "</p>";
        return std::string("<img class=\"px ") + role + "\" alt=\"" + alt + "\" title=\"" +
               reviewPageText(name) + "\" style=\"--w:" + std::to_string(png->width) +
               ";--h:" + std::to_string(png->height) + "\" src=\"data:image/png;base64," +
               reviewPageBase64(png->bytes) + "\">";
    }
    void writeCase(const CaseResult& c, int index);
    void writeViewer(const CaseResult& c, int index, unsigned zoom);

    const ReviewReport& report_;
    std::filesystem::path out_;
    std::ostringstream html_;
};

void PageWriter::writeViewer(const CaseResult& c, int index, unsigned zoom) {
    const std::string mode = "mode-" + std::to_string(index);
    if (c.actualFile.empty() || c.expectedFile.empty()) { // NEW or STALE: one picture, nothing to compare
        html_ << "<div class=\"single\"><figure>"
              << image(c.actualFile.empty() ? c.expectedFile : c.actualFile, "one",
                       c.actualFile.empty() ? "reference" : "new")
              << "<figcaption>" << (c.actualFile.empty() ? "reference (no new image)" : "new (no reference)")
              << "</figcaption></figure></div>";
        return;
    }
    html_ << "<div class=\"viewer\" data-mode=\"flip\"><div class=\"controls\">";
    for (const auto& [value, label] :
         {std::pair{"flip", "hover-flip"}, {"slide", "slide"}, {"2up", "2-up"}, {"blend", "blend"}})
        html_ << "<label><input type=\"radio\" name=\"" << mode << "\" value=\"" << value << "\""
              << (std::string_view(value) == "flip" ? " checked" : "") << "> " << label << "</label>";
    html_ << "<input type=\"range\" class=\"split\" min=\"0\" max=\"100\" value=\"50\" aria-label=\"slide\">"
          << "<input type=\"range\" class=\"blend\" min=\"0\" max=\"100\" value=\"50\" aria-label=\"blend\">"
          << "<label>zoom <select class=\"zoom\">";
    for (unsigned z : kZooms)
        html_ << "<option value=\"" << z << "\"" << (z == zoom ? " selected" : "") << ">" << z
              << "×</option>";
    html_ << "</select></label></div><p class=\"legend\">"
          << "<span class=\"l-flip\">new; the reference while the pointer is over it</span>"
          << "<span class=\"l-slide\">new on the left, the reference right of the slider's position</span>"
          << "<span class=\"l-2up\">new, then the reference</span>"
          << "<span class=\"l-blend\">the reference over new at the slider's opacity</span></p>"
          << "<div class=\"frame\"><div class=\"stage\">" << image(c.actualFile, "new", "new")
          << image(c.expectedFile, "ref", "reference") << "</div></div></div>";
}

void PageWriter::writeCase(const CaseResult& c, int index) {
    const PageGroup group = pageGroup(c.status);
    const std::string& picture = c.actualFile.empty() ? c.expectedFile : c.actualFile;
    const unsigned zoom = picture.empty() ? 1 : openingZoom(out_ / picture);
    html_ << "<section class=\"case " << kGroupClasses[int(group)] << "\" id=\"case-" << index
          << "\" tabindex=\"-1\" data-status=\"" << reviewPageText(statusName(c.status))
          << "\" data-fails-run=\"" << (group == PageGroup::Failing ? 1 : 0) << "\" style=\"--zoom:" << zoom
          << "\">";
    html_ << "<h3><span class=\"badge\">" << reviewPageText(statusName(c.status))
          << "</span> <span class=\"case-name\">" << reviewPageText(c.name) << "</span></h3>";
    html_ << "<p class=\"expectation\">expected: ";
    if (c.rule != nullptr) {
        html_ << kPageExpectationWords[int(c.rule->expectation)] << " (expectations line " << c.rule->line
              << ")";
        if (!c.rule->comment.empty()) html_ << " · " << bugLink(c.rule->comment);
    } else {
        html_ << "PASS (no rule)";
    }
    html_ << "</p>";
    if (!c.message.empty()) html_ << "<p class=\"message\">" << reviewPageText(c.message) << "</p>";
    const ApprovedResult* held =
        c.best >= 0 && std::size_t(c.best) < c.approved.size() ? &c.approved[c.best] : nullptr;
    if (held != nullptr) {
        html_ << "<p class=\"approved\">held to " << reviewPageText(held->expected.filename().string());
        if (c.approved.size() > 1) html_ << " (the closest of " << c.approved.size() << " approved images)";
        if (!held->error.empty()) html_ << ": " << reviewPageText(held->error);
        html_ << "</p>";
    }
    html_ << "<div class=\"case-body\">";
    if (held != nullptr && held->judgement) {
        html_
            << "<table class=\"figures\"><thead><tr><th>figure</th><th>value</th><th>limit</th></tr></thead>"
            << "<tbody>";
        for (const FigureRow& row : figureRows(*held->judgement, report_.options.limits))
            html_ << "<tr" << (row.failed ? " class=\"failed\"" : "") << "><td>" << reviewPageText(row.figure)
                  << "</td><td>" << reviewPageText(row.value) << "</td><td>" << reviewPageText(row.limit)
                  << "</td></tr>";
        html_ << "</tbody></table>";
    }
    writeViewer(c, index, zoom);
    if (!c.diffFile.empty() || !c.heatmapFile.empty()) {
        html_ << "<div class=\"maps\">";
        if (!c.diffFile.empty())
            html_ << "<figure>" << image(c.diffFile, "diff", "difference")
                  << "<figcaption>difference</figcaption></figure>";
        if (!c.heatmapFile.empty())
            html_ << "<figure>" << image(c.heatmapFile, "heat", "heatmap")
                  << "<figcaption>heatmap</figcaption></figure>";
        html_ << "</div>";
    }
    html_ << "</div></section>\n";
}

std::string PageWriter::write() {
    const std::optional<std::string_view> script = reviewPageAsset("review_page.js");
    const std::optional<std::string_view> style = reviewPageAsset("review_page.css");
    if (!script || !style)
        throw RuntimeError("review page: the page's script or style was not embedded (a build problem)");
    // The report's order (failures first, then by name) kept within each of the page's groups.
    std::vector<const CaseResult*> order;
    for (const CaseResult& c : report_.cases) order.push_back(&c);
    int failing = 0;
    for (const CaseResult* c : order) failing += pageGroup(c->status) == PageGroup::Failing ? 1 : 0;
    // The page's one script runs by a nonce no file name can know, so that markup slipped past the escaping
    // could still run nothing: a nonce policy also blocks inline event handlers (onerror=...).
    std::random_device random;
    std::string nonceBytes;
    for (int i = 0; i < 16; ++i) nonceBytes += char(random() & 0xff);
    const std::string nonce = reviewPageBase64(nonceBytes);

    html_ << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
          << "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src data:; "
             "style-src 'unsafe-inline'; script-src 'nonce-"
          << nonce << "'; base-uri 'none'; form-action 'none'\">\n"
          << "<meta name=\"referrer\" content=\"no-referrer\">\n"
          << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
          << "<title>shadelab review: " << failing << " of " << order.size() << " failing</title>\n"
          << "<style>\n"
          << *style << "</style></head><body>\n<header class=\"summary\"><h1>shadelab review</h1>"
          << "<p class=\"verdict " << (failing > 0 ? "failed" : "passed") << "\">"
          << (failing > 0
                  ? std::to_string(failing) + " of " + std::to_string(order.size()) + " cases fail the run"
                  : "all " + std::to_string(order.size()) + " cases pass")
          << "</p><ul class=\"counts\">";
    for (CaseStatus s :
         {CaseStatus::Fail, CaseStatus::New, CaseStatus::Stale, CaseStatus::UnexpectedPass,
          CaseStatus::ExpectedFail, CaseStatus::FlakyFail, CaseStatus::Pass, CaseStatus::Skipped}) {
        const auto n =
            std::count_if(order.begin(), order.end(), [s](const CaseResult* c) { return c->status == s; });
        if (n > 0)
            html_ << "<li class=\"" << kGroupClasses[int(pageGroup(s))] << "\">"
                  << reviewPageText(statusName(s)) << " <b>" << n << "</b></li>";
    }
    html_ << "</ul><p class=\"run\"><span>driver: "
          << (report_.options.driver.empty() ? std::string("(none)") : reviewPageText(report_.options.driver))
          << "</span><span>limits: " << reviewPageText(limitsText(report_.options.limits)) << "</span></p>"
          << "<p class=\"keys\"><kbd>j</kbd> / <kbd>k</kbd> next / previous failing "
             "case</p></header>\n<main>\n";

    static constexpr const char* kHeadings[] = {"Failing", "Expected to fail or flaky", "Passing", "Skipped"};
    for (PageGroup group :
         {PageGroup::Failing, PageGroup::Expected, PageGroup::Passing, PageGroup::Skipped}) {
        std::vector<const CaseResult*> cases;
        std::copy_if(order.begin(), order.end(), std::back_inserter(cases),
                     [group](const CaseResult* c) { return pageGroup(c->status) == group; });
        if (cases.empty()) continue;
        const std::string heading =
            std::string(kHeadings[int(group)]) + " (" + std::to_string(cases.size()) + ")";
        if (group == PageGroup::Skipped) {
            html_ << "<h2>" << heading << "</h2><ul class=\"skipped\">";
            for (const CaseResult* c : cases)
                html_ << "<li><span class=\"case-name\">" << reviewPageText(c->name) << "</span>"
                      << (c->rule && !c->rule->comment.empty() ? " · " + bugLink(c->rule->comment) : "")
                      << "</li>";
            html_ << "</ul>\n";
            continue;
        }
        html_ << (group == PageGroup::Passing ? "<details class=\"passing\"><summary>" : "<h2>") << heading
              << (group == PageGroup::Passing ? "</summary>\n" : "</h2>\n");
        for (const CaseResult* c : cases) writeCase(*c, int(c - report_.cases.data()));
        if (group == PageGroup::Passing) html_ << "</details>\n";
    }
    html_ << "</main>\n<script nonce=\"" << nonce << "\">\n" << *script << "</script></body></html>\n";
    return html_.str();
}

} // namespace

std::string reviewPageHtml(const ReviewReport& report, const std::filesystem::path& out) {
    return PageWriter(report, out).write();
}

} // namespace shadelab::app
