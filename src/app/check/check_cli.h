// The command lines of `compare` and `review`, shared by `shadelab` (app/shells/cli.cpp) and the light
// `shadelab-compare` (compare_main.cpp), so that both take the same flags with the same checks. A bad value
// is refused while parsing, as a CLI::ValidationError naming the flag, the value and the fix (exit 2).
#pragma once

#include "app/check/compare_command.h"
#include "app/check/review.h"

namespace CLI {
class App;
}

namespace shadelab::app {

// --max, --mean, --outliers, --ssim-min, --perceptual-max-pixels, --perceptual-threshold,
// --ignore x,y,w,h (repeatable), --ignore-alpha; bound to `limits`.
void addLimitFlags(CLI::App& command, CheckLimits& limits);

// The `compare` subcommand of `parent`, bound to `options` (filled when the subcommand is parsed).
CLI::App* addCompareCommand(CLI::App& parent, CompareOptions& options);
// The `review` subcommand of `parent`, bound to `options`; the caller runs runReview (review.h) with it.
CLI::App* addReviewCommand(CLI::App& parent, ReviewOptions& options);

} // namespace shadelab::app
