#include "replay_timing.h"

#include <algorithm>
#include <chrono>
#include <thread>

#include "rt/accel/debug/query_recorder.h"

namespace rt::bench {

RecordedQueries record_render(const Scene& scene, const Accelerator& accel,
                              RenderSettings settings) {
    QueryRecorder recorder(accel);
    settings.threads = 1;
    RenderObserver silent;
    RenderStatistics statistics;
    render(scene, recorder, settings, silent, statistics);  // the picture is not wanted
    return recorder.take();
}

ReplayTimes time_replays(const RecordedQueries& recorded, const Accelerator& accel, int threads,
                         int repeat) {
    ReplayTimes times;
    times.accelerator = std::string(accel.name());
    times.threads = std::max(threads, 1);
    const std::size_t count = recorded.queries.size();
    const auto share = [&](int part) {
        return count * static_cast<std::size_t>(part) / static_cast<std::size_t>(times.threads);
    };
    for (int round = 0; round < repeat; ++round) {
        std::vector<std::uint64_t> found(static_cast<std::size_t>(times.threads), 0);
        const auto start = std::chrono::steady_clock::now();
        {
            std::vector<std::jthread> workers;
            for (int part = 0; part < times.threads; ++part) {
                workers.emplace_back([&, part] {
                    TraceCounters counters;
                    found[static_cast<std::size_t>(part)] =
                        replay_queries(recorded, share(part), share(part + 1), accel, counters);
                });
            }
        }
        const auto stop = std::chrono::steady_clock::now();
        times.seconds.push_back(std::chrono::duration<double>(stop - start).count());
        times.found = 0;
        for (const std::uint64_t f : found) {
            times.found += f;
        }
    }
    return times;
}

}  // namespace rt::bench
