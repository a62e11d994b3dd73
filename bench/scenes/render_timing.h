// Renders a loaded scene several times and keeps the wall time of each render.
#pragma once

#include <cstdint>
#include <vector>

#include "rt/accel/accelerator.h"
#include "rt/render/renderer.h"
#include "rt/scene/scene.h"

namespace rt::bench {

struct RenderTimes {
    std::vector<double> seconds;  ///< one per render, in the order run
    TraceCounters counters;       ///< of one render (every render traces the same rays)
    int threads = 0;              ///< the renderer's worker threads

    double median() const;
    double minimum() const;
};

/// The median and the least of a run of timings; 0 for none.
double median_of(std::vector<double> seconds);
double minimum_of(const std::vector<double>& seconds);

/// Renders `repeat` times with a silent observer; the films are dropped.
RenderTimes time_renders(const Scene& scene, const Accelerator& accel,
                         const RenderSettings& settings, int repeat);

}  // namespace rt::bench
