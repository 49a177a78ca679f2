// The review page (app/check/review.h reviewPageHtml), built from a report made by hand — a failing, a
// passing and a hostile-named case with real PNGs — checked as text here and in headless Chromium through
// tests/check/page/review_page_driver.py: the failing case first, the slider moving the clip, hover-flip
// swapping the picture, the hostile name staying text, and nothing loaded from anywhere.
#include <netdb.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/check/review.h"
#include "cli/run_process.h"
#include "shadelab/image/image_file.h"

namespace shadelab::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Markup, quotes and an ampersand: a file name anybody could give a PNG.
const std::string kHostileName = "<img src=x onerror=alert(1)> \"q\" & 'a'";
const std::string kFailingName = "sphere-phong";
const std::string kPassingName = "a-passing"; // sorts first by name: the page must still put it after
const std::string kBugLink = "https://bugs.example.org/49";

// A lit sphere on a grey ground, lit from (lightX, -0.5, 1): the new and the reference images differ in the
// light's direction, as a shading change would make them.
Image sphere(int width, int height, float lightX) {
    Image image(width, height);
    const float ly = -0.5f, lz = 1.0f, length = std::sqrt(lightX * lightX + ly * ly + lz * lz);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float nx = (x + 0.5f - width / 2.0f) / (height * 0.4f);
            const float ny = (y + 0.5f - height / 2.0f) / (height * 0.4f);
            const float r2 = nx * nx + ny * ny;
            std::uint8_t* p = image.pixel(x, y);
            const float lambert =
                r2 > 1 ? 0.0f : std::max(0.0f, (nx * lightX + ny * ly + std::sqrt(1 - r2) * lz) / length);
            p[0] = r2 > 1 ? 60 : std::uint8_t(30 + 200 * lambert);
            p[1] = r2 > 1 ? 60 : std::uint8_t(20 + 120 * lambert);
            p[2] = r2 > 1 ? 60 : std::uint8_t(15 + 60 * lambert);
            p[3] = 255;
        }
    return image;
}

// The difference's magnitude from dark purple to yellow (viridis' ends): a picture shaped as a heatmap.
Image magnitude(const Image& difference) {
    Image image = difference;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        const float t = std::min(1.0f, float(image.rgba[i] + image.rgba[i + 1] + image.rgba[i + 2]) / 255.0f);
        image.rgba[i] = std::uint8_t(68 + 185 * t);
        image.rgba[i + 1] = std::uint8_t(1 + 230 * t);
        image.rgba[i + 2] = std::uint8_t(84 - 47 * t);
    }
    return image;
}

Judgement judgement(int maxDelta, double meanDelta, int outliers, double ssimMean,
                    const CheckLimits& limits) {
    Judgement j;
    j.comparison.actualWidth = j.comparison.expectedWidth = 80;
    j.comparison.actualHeight = j.comparison.expectedHeight = 60;
    j.comparison.maxDelta = maxDelta;
    j.comparison.meanDelta = meanDelta;
    j.comparison.outliers = outliers;
    j.comparison.tolerance = limits.tolerance;
    j.comparison.passed =
        outliers <= limits.tolerance.outlierBudget && meanDelta <= limits.tolerance.meanDelta;
    j.ssim = SsimResult{ssimMean, 0, {}};
    j.perceptual = PerceptualResult{outliers, 2, {}};
    j.passed = j.comparison.passed && ssimMean >= limits.ssimMin.value_or(0);
    return j;
}

// Writes the cases' PNGs under `out` and returns the report naming them (in the order the page must undo).
struct PageFixture {
    ReviewReport report;
    ExpectationRule failingRule, hostileRule;
};
void makeReport(const fs::path& out, PageFixture& f) {
    f.report.options.out = out;
    f.report.options.driver = "llvmpipe <gl 4.5>";
    f.report.options.limits.tolerance = {2, 0.5, 0};
    f.report.options.limits.ssimMin = 0.99;
    f.failingRule = {kFailingName, "*", Expectation::Pass, kBugLink, 3};
    f.hostileRule = {"*", "*", Expectation::Pass, "javascript:alert(3)", 4};
    const auto addCase = [&](const std::string& name, CaseStatus status, const ExpectationRule* rule,
                             const Judgement& judged, const std::string& message, float lightX, int width) {
        CaseResult c;
        c.name = name;
        c.status = status;
        c.rule = rule;
        c.message = message;
        c.actualFile = name + ".png";
        c.expectedFile = name + ".expected.png";
        c.diffFile = name + ".diff.png";
        c.heatmapFile = name + ".heatmap.png";
        const Image actual = sphere(width, width * 3 / 4, lightX),
                    expected = sphere(width, width * 3 / 4, -0.6f);
        writePng(actual, out / c.actualFile);
        writePng(expected, out / c.expectedFile);
        writePng(diffImage(actual, expected), out / c.diffFile);
        writePng(magnitude(diffImage(actual, expected)), out / c.heatmapFile);
        c.approved.push_back({out / c.expectedFile, judged, ""});
        c.best = 0;
        f.report.cases.push_back(c);
    };
    const CheckLimits& limits = f.report.options.limits;
    addCase(kPassingName, CaseStatus::Pass, nullptr, judgement(1, 0.1, 0, 0.999, limits), "", -0.6f, 80);
    addCase(kFailingName, CaseStatus::Fail, &f.failingRule, judgement(55, 3.5, 1200, 0.81, limits),
            "max 55 beyond 2 in 1200 pixels", 0.2f, 80);
    addCase(kHostileName, CaseStatus::Fail, &f.hostileRule, judgement(9, 0.2, 3, 0.995, limits),
            "</p><script>alert(2)</script>", -0.3f,
            700); // wider than a phone: its pictures scroll in their frame, the page does not
}

class ReviewPage : public testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("shadelab-review-page-" + std::to_string(::getpid()) + "-" +
                                            testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_ / "out");
        makeReport(dir_ / "out", fixture_);
        html_ = reviewPageHtml(fixture_.report, dir_ / "out");
        std::ofstream(dir_ / "out" / "index.html", std::ios::binary) << html_;
    }
    void TearDown() override {
        if (!HasFailure())
            fs::remove_all(dir_);
        else
            std::printf("kept %s\n", dir_.string().c_str());
    }
    fs::path dir_;
    PageFixture fixture_;
    std::string html_;
};

TEST_F(ReviewPage, UntrustedTextIsEscaped) {
    EXPECT_EQ(html_.find("<img src=x"), std::string::npos);
    EXPECT_EQ(html_.find("<script>alert"), std::string::npos);
    EXPECT_NE(html_.find("&lt;img src=x onerror=alert(1)&gt; &quot;q&quot; &amp; &#39;a&#39;"),
              std::string::npos);
    EXPECT_NE(html_.find("&lt;/p&gt;&lt;script&gt;alert(2)&lt;/script&gt;"), std::string::npos);
    // A bug link that is not http(s) is text, never an href.
    EXPECT_EQ(html_.find("href=\"javascript"), std::string::npos);
    EXPECT_NE(html_.find("href=\"" + kBugLink + "\""), std::string::npos);
    // Every tag the cases' part of the page holds is the page's own: as many < as >.
    const std::string cases =
        html_.substr(html_.find("<main>"), html_.find("</main>") - html_.find("<main>"));
    EXPECT_EQ(std::count(cases.begin(), cases.end(), '<'), std::count(cases.begin(), cases.end(), '>'));
}

TEST_F(ReviewPage, InvalidUtf8AndControlsInANameAreReplaced) {
    CaseResult& c = fixture_.report.cases.front();
    c.name = std::string("bad\xff\xfe name\x1b[31m \xe2\x80\xae");
    const std::string html = reviewPageHtml(fixture_.report, dir_ / "out");
    EXPECT_EQ(html.find('\xff'), std::string::npos);
    EXPECT_EQ(html.find('\x1b'), std::string::npos);
    EXPECT_EQ(html.find("\xe2\x80\xae"), std::string::npos) << "a bidi override reached the page";
    EXPECT_NE(html.find("bad\\xff\\xfe name\\x1b[31m \\xe2\\x80\\xae<"),
              std::string::npos); // printable()'s escapes
}

TEST_F(ReviewPage, EveryLoadIsInlinedAndForbiddenByThePolicy) {
    EXPECT_NE(html_.find("default-src 'none'; img-src data:;"), std::string::npos);
    // The one script runs by the policy's nonce, which differs from page to page.
    const std::size_t policy = html_.find("script-src 'nonce-");
    ASSERT_NE(policy, std::string::npos);
    const std::string nonce = html_.substr(policy + 18, html_.find('\'', policy + 18) - (policy + 18));
    EXPECT_EQ(nonce.size(), 24u) << nonce;
    EXPECT_NE(html_.find("<script nonce=\"" + nonce + "\">"), std::string::npos);
    EXPECT_EQ(reviewPageHtml(fixture_.report, dir_ / "out").find(nonce), std::string::npos)
        << "the same nonce twice";
    // Every src and href (std::regex would overflow its stack on the pictures' megabyte of base64).
    int images = 0;
    for (const std::string attribute : {" src=\"", " href=\""})
        for (std::size_t at = html_.find(attribute); at != std::string::npos;
             at = html_.find(attribute, at + 1)) {
            const std::size_t start = at + attribute.size();
            const std::string value = html_.substr(start, html_.find('"', start) - start);
            if (attribute == " src=\"") {
                EXPECT_EQ(value.rfind("data:image/png;base64,", 0), 0u) << value.substr(0, 80);
                ++images;
            } else {
                EXPECT_EQ(value, kBugLink);
            }
        }
    EXPECT_EQ(images, 3 * 4);
    EXPECT_EQ(html_.find("<link"), std::string::npos);
    EXPECT_EQ(html_.find("<script src"), std::string::npos);
}

TEST_F(ReviewPage, EveryStatusInItsGroup) {
    // One case of each status, in the report's order; the page groups them: those failing the run, then
    // expected-fail and flaky, then passing (folded), then skipped (listed without pictures).
    ReviewReport report = fixture_.report;
    const CaseResult model = report.cases.front();
    report.cases.clear();
    for (const auto& [name, status] :
         std::vector<std::pair<std::string, CaseStatus>>{{"s-skip", CaseStatus::Skipped},
                                                         {"s-pass", CaseStatus::Pass},
                                                         {"s-flaky", CaseStatus::FlakyFail},
                                                         {"s-expected", CaseStatus::ExpectedFail},
                                                         {"s-unexpected", CaseStatus::UnexpectedPass},
                                                         {"s-stale", CaseStatus::Stale},
                                                         {"s-new", CaseStatus::New},
                                                         {"s-fail", CaseStatus::Fail}}) {
        CaseResult c = model;
        c.name = name;
        c.status = status;
        if (status == CaseStatus::New) c.expectedFile.clear();
        if (status == CaseStatus::Stale) c.actualFile = "gone.png"; // named but not there: said so
        report.cases.push_back(c);
    }
    const std::string html = reviewPageHtml(report, dir_ / "out");
    const auto at = [&](const std::string& text) { return html.find(text); };
    const std::vector<std::string> order = {"<h2>Failing (4)</h2>",
                                            "s-unexpected",
                                            "s-stale",
                                            "s-new",
                                            "s-fail",
                                            "<h2>Expected to fail or flaky (2)</h2>",
                                            "s-flaky",
                                            "s-expected",
                                            "<summary>Passing (1)</summary>",
                                            "s-pass",
                                            "</details>",
                                            "<h2>Skipped (1)</h2>",
                                            "s-skip"};
    for (std::size_t i = 1; i < order.size(); ++i) {
        ASSERT_NE(at(order[i]), std::string::npos) << order[i];
        EXPECT_LT(at(order[i - 1]), at(order[i])) << order[i - 1] << " before " << order[i];
    }
    // NEW: its one picture, no viewer; STALE: the missing file named; SKIP: no picture.
    const std::string newCase = html.substr(at("s-new"), at("s-fail") - at("s-new"));
    EXPECT_EQ(newCase.find("class=\"viewer\""), std::string::npos);
    EXPECT_NE(newCase.find("new (no reference)"), std::string::npos);
    const std::string staleCase = html.substr(at("s-stale"), at("s-new") - at("s-stale"));
    EXPECT_NE(staleCase.find("unreadable gone.png"), std::string::npos);
    EXPECT_EQ(html.substr(at("<h2>Skipped")).find("<img"), std::string::npos);
}

// RFC 4648 §4 base64, written out bit by bit (the page has its own encoder).
std::string base64(const std::string& bytes) {
    static const std::string kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string encoded;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t bits = 0;
        for (std::size_t k = 0; k < 3; ++k)
            bits = bits << 8 | (i + k < bytes.size() ? std::uint8_t(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k)
            encoded += k * 6 < (bytes.size() - i) * 8 ? kAlphabet[(bits >> (18 - 6 * k)) & 63] : '=';
    }
    return encoded;
}

TEST_F(ReviewPage, TheImagesAreTheFilesBytes) {
    // Every picture's data: URI is its file's bytes; the files' sizes leave each remainder modulo 3.
    std::set<std::size_t> remainders;
    for (const CaseResult& c : fixture_.report.cases)
        for (const std::string& name : {c.actualFile, c.expectedFile, c.diffFile, c.heatmapFile}) {
            std::ifstream in(dir_ / "out" / name, std::ios::binary);
            const std::string bytes((std::istreambuf_iterator<char>(in)), {});
            remainders.insert(bytes.size() % 3);
            EXPECT_NE(html_.find("src=\"data:image/png;base64," + base64(bytes) + "\""), std::string::npos)
                << name;
        }
    EXPECT_EQ(remainders.size(), 3u) << "the fixture's files do not try every padding";
    EXPECT_NE(html_.find("title=\"" + kFailingName + ".png\" style=\"--w:80;--h:60\" src=\"data:"),
              std::string::npos);
}

// Why the page cannot be opened in a browser here, or "".
std::string pageBrowserUnavailable() {
    if (!fs::exists("/usr/bin/chromium") || !fs::exists("/usr/bin/chromedriver"))
        return "no Debian chromium / chromium-driver (apt-get install chromium chromium-driver)";
    if (!fs::exists("/usr/lib/python3/dist-packages/selenium"))
        return "no Debian python3-selenium (apt-get install python3-selenium)";
    addrinfo* found = nullptr; // chromedriver is reached at "localhost" (tests/web/browser_support.cpp)
    if (::getaddrinfo("localhost", nullptr, nullptr, &found) != 0)
        return "the name localhost does not resolve (no /etc/hosts?): add '127.0.0.1 localhost'";
    ::freeaddrinfo(found);
    return "";
}

TEST_F(ReviewPage, InHeadlessChromium) {
    if (const std::string why = pageBrowserUnavailable(); !why.empty()) {
        if (std::getenv("CI")) FAIL() << why;
        GTEST_SKIP() << why;
    }
    cli_test::RunOptions options;
    options.program = "/usr/bin/python3";
    options.timeout = std::chrono::seconds(240);
    const fs::path desktop = dir_ / "desktop.png", phone = dir_ / "phone.png";
    const cli_test::Outcome run =
        cli_test::runWith({SHADELAB_REVIEW_PAGE_DRIVER, (dir_ / "out" / "index.html").string(),
                           desktop.string(), phone.string()},
                          dir_, options);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const json seen = json::parse(run.out);
    if (const char* keep = std::getenv("SHADELAB_REVIEW_PAGE_SCREENSHOTS");
        keep != nullptr && *keep != '\0') {
        fs::copy_file(desktop, fs::path(keep) / "desktop.png", fs::copy_options::overwrite_existing);
        fs::copy_file(phone, fs::path(keep) / "phone.png", fs::copy_options::overwrite_existing);
    }

    // Failures first (in the report's order), then the passing (folded).
    const json& cases = seen.at("cases");
    ASSERT_EQ(cases.size(), 3u) << seen.dump(1);
    EXPECT_EQ(cases[0].at("name"), kFailingName);
    EXPECT_TRUE(cases[0].at("failsRun"));
    EXPECT_EQ(cases[1].at("name"), kHostileName) << "the hostile name is the page's text, as it was given";
    EXPECT_TRUE(cases[1].at("failsRun"));
    EXPECT_EQ(cases[2].at("name"), kPassingName);
    EXPECT_TRUE(cases[2].at("inPassing"));
    EXPECT_FALSE(cases[0].at("inPassing"));

    // Nothing injected, nothing run: the page's pictures only, one script, no event attribute, no dialog.
    EXPECT_EQ(seen.at("foreignImages"), 0);
    EXPECT_EQ(seen.at("eventAttributes"), 0);
    EXPECT_EQ(seen.at("scripts"), 1);
    EXPECT_EQ(seen.at("dialogs"), json::array());
    EXPECT_EQ(seen.at("links"), json::array({kBugLink}));

    // Slide: the reference's clip follows the range input.
    EXPECT_EQ(seen.at("slideMode"), "slide");
    EXPECT_EQ(seen.at("clipBefore"), "inset(0px 0px 0px 50%)");
    EXPECT_EQ(seen.at("clipAfter"), "inset(0px 0px 0px 20%)");
    // Hover-flip: new away from the picture, the reference with the pointer over it.
    EXPECT_EQ(seen.at("flipMode"), "flip");
    EXPECT_EQ(seen.at("refVisibilityAway"), "hidden");
    EXPECT_EQ(seen.at("shownAway"), "px new");
    EXPECT_EQ(seen.at("refVisibilityOver"), "visible");
    EXPECT_EQ(seen.at("shownOver"), "px ref");
    // Blend: the reference's opacity; 2-up: the reference beside new, on the same line.
    EXPECT_EQ(seen.at("blendMode"), "blend");
    EXPECT_EQ(seen.at("blendOpacity"), "0.3");
    EXPECT_EQ(seen.at("twoUpMode"), "2up");
    const json& twoUp = seen.at("twoUp");
    EXPECT_LT(twoUp[0].get<double>(), twoUp[1].get<double>());
    EXPECT_EQ(twoUp[2], twoUp[3]);
    // Pixelated scaling at the zoom chosen.
    EXPECT_EQ(seen.at("rendering"), "pixelated");
    EXPECT_EQ(seen.at("zoom2Width"), 2 * seen.at("naturalWidth").get<int>());
    // j, j, k: the failing cases in page order.
    EXPECT_EQ(seen.at("keys"), json::array({kFailingName, kHostileName, kFailingName}));
    // A phone's width: no sideways scrolling.
    // (A page wider than the phone makes Chromium widen its layout viewport, so the width is checked too.)
    EXPECT_EQ(seen.at("phoneWidths")[0], 390) << seen.at("phoneWidths");
    EXPECT_LE(seen.at("phoneWidths")[1].get<int>(), 390) << seen.at("phoneWidths");

    // No load but data: URIs, nothing on the console (a policy violation or a script error shows there).
    for (const json& resource : seen.at("resources"))
        EXPECT_EQ(resource.get<std::string>().rfind("data:", 0), 0u) << resource;
    EXPECT_EQ(seen.at("requests"), json::array());
    EXPECT_EQ(seen.at("console"), json::array());
    EXPECT_FALSE(seen.at("injectedHandlerRan")) << "the policy lets an inline event handler run";
    EXPECT_GT(fs::file_size(desktop), 0u);
    EXPECT_GT(fs::file_size(phone), 0u);
}

} // namespace
} // namespace shadelab::app
