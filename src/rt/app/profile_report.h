// -p: the metrics printed at the end of a run (manual Appendix -p, "Prints out various internal
// metrics at the end of the run").
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "rt/render/ray_kinds.h"

namespace rt {

struct PhaseTimes {
    double load_seconds = 0.0;
    double build_seconds = 0.0;
    double trace_seconds = 0.0;
    double write_seconds = 0.0;
};

struct ProfileInputs {
    std::string_view method;  ///< the intersection method's name
    std::size_t polygons = 0;
    std::size_t structure_bytes = 0;
    PhaseTimes times;
    const KindCounters* counters = nullptr;
};

/// A table: one row per kind of ray that was traced (rays, voxels, nodes, polygon tests, hits,
/// near hits, culled exits, rays answered from a leaving polygon's guards), a total row, then the
/// build's memory, the time of each phase and the rays traced per second.
std::string profile_report(const ProfileInputs& inputs);

}  // namespace rt
