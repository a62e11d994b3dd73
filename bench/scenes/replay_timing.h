// --replay: the queries of one render, recorded, then asked again of the methods with nothing
// else running, so that a method's rate on rt's own rays can be set beside the renderer's.
#pragma once

#include <string>
#include <vector>

#include "rt/accel/debug/query_recorder.h"
#include "rt/render/renderer.h"
#include "rt/scene/scene.h"

namespace rt::bench {

/// The queries of one render of the scene through `accel`, on one thread (the order is then the
/// render's own and the same on every run).
RecordedQueries record_render(const Scene& scene, const Accelerator& accel,
                              RenderSettings settings);

struct ReplayTimes {
    std::string accelerator;      ///< its name()
    std::vector<double> seconds;  ///< one per replay of every query
    std::uint64_t found = 0;      ///< hits and blocked rays of one replay
    int threads = 1;
};

/// Asks every recorded query of `accel` `repeat` times over, on `threads` threads (each a
/// contiguous share of the queries), timing each round.
ReplayTimes time_replays(const RecordedQueries& recorded, const Accelerator& accel, int threads,
                         int repeat);

}  // namespace rt::bench
