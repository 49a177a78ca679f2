// GPU-synchronized timing shared by `shadelab bench` and `shadelab report`: frames, and one-off costs (no
// Google Benchmark here, so the report's measuring core links without it).
#pragma once

#include <functional>
#include <vector>

namespace shadelab::app {

// Linear interpolation between the order statistics of `values` (p in [0, 1]); values need not be sorted.
double percentile(std::vector<double> values, double p);

// Draws `warmup` untimed frames, then `frames` frames each followed by glFinish; returns each frame's time
// in milliseconds. The framebuffer to draw into must be bound.
std::vector<double> timeFramesMs(int warmup, int frames, const std::function<void()>& draw);

// The median of `repeats` timings of `run`, each after an untimed `reset` and glFinish (a one-off cost
// measured once is at the mercy of one page fault or one preemption). `run` calls gl::finish itself when its
// work is on the GPU.
double medianOneOffMs(int repeats, const std::function<void()>& reset, const std::function<void()>& run);

} // namespace shadelab::app
