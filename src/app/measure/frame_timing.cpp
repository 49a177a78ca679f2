#include "app/measure/frame_timing.h"

#include <algorithm>
#include <chrono>

#include "shadelab/gl/loader.h"

namespace shadelab::app {

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const double index = p * double(values.size() - 1);
    const std::size_t lo = std::size_t(index), hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (index - double(lo)) * (values[hi] - values[lo]);
}

std::vector<double> timeFramesMs(int warmup, int frames, const std::function<void()>& draw) {
    using Clock = std::chrono::steady_clock;
    for (int i = 0; i < warmup; ++i) draw();
    gl::finish();
    std::vector<double> ms;
    ms.reserve(std::size_t(std::max(frames, 0)));
    for (int i = 0; i < frames; ++i) {
        const auto start = Clock::now();
        draw();
        gl::finish();
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    return ms;
}

double medianOneOffMs(int repeats, const std::function<void()>& reset, const std::function<void()>& run) {
    using Clock = std::chrono::steady_clock;
    std::vector<double> ms;
    for (int i = 0; i < repeats; ++i) {
        reset();
        gl::finish();
        const auto start = Clock::now();
        run();
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
    return percentile(ms, 0.5);
}

} // namespace shadelab::app
