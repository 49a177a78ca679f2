// GPU-synchronized timing shared by `shadelab bench` and `shadelab report`: frames, and one-off costs (no
// Google Benchmark here, so the report's measuring core links without it).
#pragma once

#include <functional>
#include <vector>

#include "shadelab/gl/mesh.h"
#include "shadelab/gl/program_variant.h"

namespace shadelab::app {

// Linear interpolation between the order statistics of `values` (p in [0, 1]); values need not be sorted.
double percentile(std::vector<double> values, double p);

// One frame: `draw`, then glFinish; its time in milliseconds. The framebuffer to draw into must be bound.
double timeFrameMs(const std::function<void()>& draw);
// `warmup` untimed frames, then glFinish.
void warmUp(int warmup, const std::function<void()>& draw);
// warmUp, then `frames` frames (timeFrameMs); each frame's time in milliseconds.
std::vector<double> timeFramesMs(int warmup, int frames, const std::function<void()>& draw);

// Compile and link of `variant` up to its first draw of `mesh`, synchronized: Mesa translates to machine
// code at the first draw, not at glLinkProgram. Milliseconds; the framebuffer to draw into must be bound
// and the GPU idle (gl::finish).
double compileAndFirstDrawMs(const gl::ProgramVariant& variant, const gl::GpuMesh& mesh);

// The median of `repeats` timings of `run`, each after an untimed `reset` and glFinish (a one-off cost
// measured once is at the mercy of one page fault or one preemption). `run` calls gl::finish itself when its
// work is on the GPU.
double medianOneOffMs(int repeats, const std::function<void()>& reset, const std::function<void()>& run);

} // namespace shadelab::app
