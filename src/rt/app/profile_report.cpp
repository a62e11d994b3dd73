#include "rt/app/profile_report.h"

#include <fmt/format.h>

namespace rt {

namespace {

std::string row(std::string_view name, const TraceCounters& c) {
    return fmt::format("  {:<14}{:>12}{:>13}{:>11}{:>14}{:>11}{:>10}{:>10}{:>10}\n", name, c.rays,
                       c.voxels_stepped, c.nodes_visited, c.polygon_tests, c.hits, c.near_hits,
                       c.culled_exits, c.guard_answers);
}

}  // namespace

std::string profile_report(const ProfileInputs& in) {
    std::string text = fmt::format("profile: {} over {} polygons\n", in.method, in.polygons);
    text +=
        fmt::format("  {:<14}{:>12}{:>13}{:>11}{:>14}{:>11}{:>10}{:>10}{:>10}\n", "rays", "traced",
                    "voxels", "nodes", "poly tests", "hits", "near", "culled", "guarded");
    if (in.counters != nullptr) {
        for (std::size_t k = 0; k < kRayKinds; ++k) {
            const TraceCounters& c = in.counters->kinds[k];
            if (c.rays > 0 || c.polygon_tests > 0) {
                text += row(ray_kind_name(static_cast<RayKind>(k)), c);
            }
        }
        text += row("all", in.counters->total());
    }
    text += fmt::format(
        "  structure: {} bytes ({:.1f} per polygon)\n", in.structure_bytes,
        in.polygons > 0 ? static_cast<double>(in.structure_bytes) / static_cast<double>(in.polygons)
                        : 0.0);
    text += fmt::format("  time: load {:.3f} s, build {:.3f} s, trace {:.3f} s, write {:.3f} s\n",
                        in.times.load_seconds, in.times.build_seconds, in.times.trace_seconds,
                        in.times.write_seconds);
    if (in.counters != nullptr && in.times.trace_seconds > 0.0) {
        // Every kind of ray in the table, over the trace's wall time: the renderer's rate.
        const double rays = static_cast<double>(in.counters->total().rays);
        text += fmt::format("  rate: {:.2f} Mrays/s of every kind over the trace's wall time\n",
                            rays / in.times.trace_seconds * 1e-6);
    }
    return text;
}

}  // namespace rt
