// `shadelab compare ACTUAL EXPECTED` (and `shadelab-compare compare`): one pair of PNGs judged against the
// limits (compare/judge.h) from a shell, as the image tests judge (DESIGN §6; docs/ci-engineers.md
// "Which metric"). No GL and no scene: part of the light library shadelab_check.
#pragma once

#include <string>

#include "shadelab/compare/judge.h"

namespace shadelab::app {

// Exit 0 within every limit, 1 beyond one (with the figures, and --diff / --heatmap written), 2 for bad
// input.
struct CompareOptions {
    std::string actual, expected, mask;
    std::string diff;    // --diff FILE: the difference ×8 on failure, left-out pixels dark grey
    std::string heatmap; // --heatmap FILE: 1 − SSIM as heatmap() draws it, 0..1, on failure
    CheckLimits limits;  // --max, --mean, --outliers, --ssim-min, ..., --ignore, --ignore-alpha
    bool json = false;   // --json: standard output carries one JSON object instead of the summary
};
int runCompare(const CompareOptions& options);

} // namespace shadelab::app
