#include "render_timing.h"

#include <algorithm>
#include <chrono>

namespace rt::bench {

double RenderTimes::median() const {
    if (seconds.empty()) {
        return 0.0;
    }
    std::vector<double> sorted = seconds;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t middle = sorted.size() / 2;
    return sorted.size() % 2 == 1 ? sorted[middle] : 0.5 * (sorted[middle - 1] + sorted[middle]);
}

double RenderTimes::minimum() const {
    return seconds.empty() ? 0.0 : *std::min_element(seconds.begin(), seconds.end());
}

RenderTimes time_renders(const Scene& scene, const Accelerator& accel,
                         const RenderSettings& settings, int repeat) {
    RenderTimes times;
    RenderObserver silent;
    for (int i = 0; i < repeat; ++i) {
        RenderStatistics statistics;
        const auto start = std::chrono::steady_clock::now();
        render(scene, accel, settings, silent, statistics);  // the picture is not wanted
        const auto stop = std::chrono::steady_clock::now();
        times.seconds.push_back(std::chrono::duration<double>(stop - start).count());
        times.counters = statistics.counters;
        times.threads = statistics.threads;
    }
    return times;
}

}  // namespace rt::bench
