// The figures of one judgement as JSON, written alike by `compare --json` and `review --json`, so that a
// dashboard reads one schema (docs/ci-engineers.md "Which metric"): max_delta, mean_delta, outliers,
// compared_pixels, pixels when the sizes match, ssim, and perceptual {differing_pixels, antialiased_pixels,
// threshold}.
#pragma once

#include <nlohmann/json.hpp>

#include "shadelab/compare/judge.h"

namespace shadelab::app {

void addFiguresJson(nlohmann::json& out, const Judgement& judgement, const CheckLimits& limits);

} // namespace shadelab::app
