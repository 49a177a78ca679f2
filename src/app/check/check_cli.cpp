#include "app/check/check_cli.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "shadelab/io/text.h"

namespace shadelab::app {
namespace {

[[noreturn]] void refuseValue(const std::string& flag, const std::string& value, const std::string& fix) {
    throw CLI::ValidationError(flag, "got \"" + printable(value) + "\"; " + fix);
}

// A whole decimal integer, nothing before or after it.
bool parseCheckInt(const std::string& text, long long& value) {
    const char* end = text.data() + text.size();
    const auto [ptr, error] = std::from_chars(text.data(), end, value);
    return error == std::errc() && ptr == end && !text.empty();
}

// A finite decimal number (CLI11 would take "nan" and "inf"), nothing before or after it.
bool parseCheckNumber(const std::string& text, double& value) {
    const char* end = text.data() + text.size();
    const auto [ptr, error] = std::from_chars(text.data(), end, value);
    return error == std::errc() && ptr == end && !text.empty() && std::isfinite(value);
}

// A number flag from `low` to `high`, checked as it is parsed; `fix` says what to give.
void addCheckNumber(CLI::App& command, const std::string& flag, const std::string& help, double low,
                    double high, const std::string& fix, const std::function<void(double)>& set) {
    command.add_option_function<std::string>(
        flag,
        [flag, low, high, fix, set](const std::string& text) {
            double value = 0;
            if (!parseCheckNumber(text, value) || value < low || value > high) refuseValue(flag, text, fix);
            set(value);
        },
        help);
}

IgnoreRect parseIgnoreRect(const std::string& text) {
    const std::string fix =
        "give x,y,w,h: four whole numbers in ACTUAL's pixels, w and h at least 1, e.g. 0,0,64,16";
    long long parts[4] = {};
    std::size_t start = 0;
    for (int i = 0; i < 4; ++i) {
        const std::size_t comma = i < 3 ? text.find(',', start) : text.size();
        if (comma == std::string::npos || !parseCheckInt(text.substr(start, comma - start), parts[i]) ||
            parts[i] < 0 || parts[i] > INT32_MAX)
            refuseValue("--ignore", text, fix);
        start = comma + 1;
    }
    if (parts[2] < 1 || parts[3] < 1) refuseValue("--ignore", text, fix);
    return {int(parts[0]), int(parts[1]), int(parts[2]), int(parts[3])};
}

} // namespace

void addLimitFlags(CLI::App& command, CheckLimits& limits) {
    Tolerance& t = limits.tolerance;
    command.add_option("--max", t.maxDelta, "Largest per-channel difference, 0..255")
        ->check(CLI::Range(0, 255))
        ->capture_default_str();
    addCheckNumber(command, "--mean",
                   "Largest mean per-channel difference over the compared pixels (default 0)", 0, 255,
                   "give a number from 0 to 255", [&t](double v) { t.meanDelta = v; });
    command.add_option("--outliers", t.outlierBudget, "Pixels allowed over --max")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    addCheckNumber(command, "--ssim-min",
                   "Smallest mean SSIM (luma, 11x11 Gaussian window), -1..1; 1 is identical", -1, 1,
                   "give a number from -1 to 1 (1: identical)", [&limits](double v) { limits.ssimMin = v; });
    command.add_option_function<std::string>(
        "--perceptual-max-pixels",
        [&limits](const std::string& text) {
            long long count = 0;
            if (!parseCheckInt(text, count) || count < 0)
                refuseValue("--perceptual-max-pixels", text, "give a whole number of pixels >= 0");
            limits.perceptualMaxPixels = long(count);
        },
        "Most pixels pixelmatch's YIQ delta may count as differing (anti-aliased pixels not counted)");
    addCheckNumber(command, "--perceptual-threshold",
                   "pixelmatch's threshold, 0..1, smaller is stricter (default 0.1)", 0, 1,
                   "give a number from 0 to 1 (pixelmatch's default 0.1)",
                   [&limits](double v) { limits.perceptualThreshold = v; });
    command.add_option_function<std::vector<std::string>>(
        "--ignore",
        [&limits](const std::vector<std::string>& texts) {
            for (const std::string& text : texts) limits.ignore.push_back(parseIgnoreRect(text));
        },
        "x,y,w,h: a rectangle of ACTUAL's pixels left out of every figure (repeatable), as --mask's black");
    command.add_flag("--ignore-alpha", limits.ignoreAlpha,
                     "Compare colour only (by default alpha is a fourth channel: a transparent image fails "
                     "against an opaque one)");
}

CLI::App* addCompareCommand(CLI::App& parent, CompareOptions& o) {
    CLI::App* compare = parent.add_subcommand(
        "compare", "Compare two PNGs as the image tests do: exit 0 within every limit, 1 beyond one");
    compare->add_option("actual", o.actual, "The image under test (PNG)")->required();
    compare->add_option("expected", o.expected, "The reference (PNG)")->required();
    addLimitFlags(*compare, o.limits);
    compare->add_option("--mask", o.mask,
                        "PNG of ACTUAL's size: black pixels are not compared, nor counted in any figure");
    compare->add_option("--diff", o.diff,
                        "Where to write the difference x8 on failure (a file; never an input); pixels left "
                        "out by --mask or --ignore are dark grey");
    compare->add_option("--heatmap", o.heatmap,
                        "Where to write 1 - SSIM as a colour-blind-safe heatmap with its scale, on failure");
    compare->add_flag("--json", o.json,
                      "Print the result as one JSON object (sizes, every figure, limits, failures, passed, "
                      "diff, heatmap) instead of the summary");
    return compare;
}

CLI::App* addReviewCommand(CLI::App& parent, ReviewOptions& o) {
    CLI::App* review = parent.add_subcommand(
        "review", "Compare a folder of PNGs with a folder of approved ones, paired by name: a page, JSON, "
                  "JUnit; exit 0 all pass, 1 a failure");
    review->add_option("actual_dir", o.actualDir, "The run's PNGs")->required();
    review->add_option("expected_dir", o.expectedDir, "The approved PNGs (NAME.png, alternatives NAME.N.png)")
        ->required();
    addLimitFlags(*review, o.limits);
    review->add_option("--out", o.out, "Folder for index.html, one self-contained page, and its images");
    review->add_option("--json", o.json, "Write every case's figures as JSON to this file");
    review->add_option("--junit", o.junit, "Write JUnit XML (one testcase a case) to this file");
    review->add_option("--expectations", o.expectations,
                       "Rules CASE DRIVER-GLOB PASS|FAIL|SKIP|FLAKY # reason, the first match deciding");
    review->add_option("--driver", o.driver, "The driver key the expectations' globs match");
    review->add_option("--masks", o.masks,
                       "Folder of masks: DIR/NAME.png is case NAME's mask (black = not compared)");
    review->add_option("--bless", o.bless, "Write this case's actual image as approved (repeatable)");
    review->add_flag("--bless-failed", o.blessFailed,
                     "Write every failed or new case's actual image as approved");
    review->add_flag("--quiet", o.quiet, "Print only failures");
    return review;
}

} // namespace shadelab::app
