// A run's memory estimate against what the process may have: the address-space limit (ulimit -v, RLIMIT_AS)
// and the machine's physical memory (docs/ci-engineers.md "Memory"). No scene and no GL: the light
// `shadelab-compare` checks its images with it; app/measure/memory_budget.h adds the estimates of renders.
#pragma once

#include <string>
#include <string_view>

namespace shadelab::app {

// The process without GL (the program, its libraries and heap at start): what `reference` and `compare`
// add their images to.
inline constexpr double kProcessBaselineBytes = 64.0 * 1024 * 1024;

// Throws RuntimeError (exit 1) when `needBytes` is over the address-space limit: names `what`, the
// estimate, the limit and the fix. Throws InputError (exit 2) naming `sizeField` when it is over the
// machine's physical memory: no limit could make such a run work here.
void checkMemoryBudget(std::string_view what, double needBytes, std::string_view sizeField);

std::string mebibytes(double bytes);

} // namespace shadelab::app
