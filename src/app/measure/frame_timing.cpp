#include "app/measure/frame_timing.h"

#include <algorithm>
#include <chrono>

#include "shadelab/gl/loader.h"
#include "shadelab/gl/program.h"

namespace shadelab::app {

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const double index = p * double(values.size() - 1);
    const std::size_t lo = std::size_t(index), hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (index - double(lo)) * (values[hi] - values[lo]);
}

namespace {
using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}
} // namespace

double timeFrameMs(const std::function<void()>& draw) {
    const auto start = Clock::now();
    draw();
    gl::finish();
    return msSince(start);
}

void warmUp(int warmup, const std::function<void()>& draw) {
    for (int i = 0; i < warmup; ++i) draw();
    gl::finish();
}

std::vector<double> timeFramesMs(int warmup, int frames, const std::function<void()>& draw) {
    warmUp(warmup, draw);
    std::vector<double> ms;
    ms.reserve(std::size_t(std::max(frames, 0)));
    for (int i = 0; i < frames; ++i) ms.push_back(timeFrameMs(draw));
    return ms;
}

double compileAndFirstDrawMs(const gl::ProgramVariant& variant, const gl::GpuMesh& mesh) {
    const auto start = Clock::now();
    const gl::Program program = gl::buildProgram(variant);
    gl::drawWith(program, mesh);
    gl::finish();
    return msSince(start);
}

double medianOneOffMs(int repeats, const std::function<void()>& reset, const std::function<void()>& run) {
    std::vector<double> ms;
    for (int i = 0; i < repeats; ++i) {
        reset();
        gl::finish();
        const auto start = Clock::now();
        run();
        ms.push_back(msSince(start));
    }
    return percentile(ms, 0.5);
}

} // namespace shadelab::app
