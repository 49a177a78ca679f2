// GPU-synchronized frame timing shared by `shadelab bench` and `shadelab report` (no Google Benchmark here,
// so the report's measuring core links without it).
#pragma once

#include <functional>
#include <vector>

namespace shadelab::app {

// Linear interpolation between the order statistics of `values` (p in [0, 1]); values need not be sorted.
double percentile(std::vector<double> values, double p);

// Draws `warmup` untimed frames, then `frames` frames each followed by glFinish; returns each frame's time
// in milliseconds. The framebuffer to draw into must be bound.
std::vector<double> timeFramesMs(int warmup, int frames, const std::function<void()>& draw);

} // namespace shadelab::app
