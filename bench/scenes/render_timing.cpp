#include "render_timing.h"

#include <algorithm>
#include <chrono>

namespace rt::bench {

double median_of(std::vector<double> seconds) {
    if (seconds.empty()) {
        return 0.0;
    }
    std::sort(seconds.begin(), seconds.end());
    const std::size_t middle = seconds.size() / 2;
    return seconds.size() % 2 == 1 ? seconds[middle]
                                   : 0.5 * (seconds[middle - 1] + seconds[middle]);
}

double minimum_of(const std::vector<double>& seconds) {
    return seconds.empty() ? 0.0 : *std::min_element(seconds.begin(), seconds.end());
}

double RenderTimes::median() const {
    return median_of(seconds);
}

double RenderTimes::minimum() const {
    return minimum_of(seconds);
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
