// One lab measurement: build an intersection method on a scene, then trace the coherent and the
// incoherent rays on one thread and on all, timing each.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rt/accel/bvh/tree_cost.h"
#include "rt/core/ray.h"
#include "rt/scene/scene.h"

#include "lab_options.h"

namespace rt::lab {

struct TraceRate {
    double mrays_per_second = 0.0;
    std::size_t rays = 0;        ///< distinct rays traced (fewer than offered when subsampled)
    bool subsampled = false;     ///< brute force on a big scene traces every k-th ray only
    std::uint64_t hits = 0;      ///< in one pass, as a sanity check between methods
    double nodes_per_ray = 0.0;  ///< TraceCounters::nodes_visited per ray
    double tests_per_ray = 0.0;  ///< TraceCounters::polygon_tests per ray
};

struct Measurement {
    std::string mesh;
    std::uint64_t triangles = 0;  ///< fan triangles of the scene's polygons
    std::string accel;
    unsigned round = 1;  ///< which of --rounds, from 1
    double build_ms = 0.0;
    double bytes_per_triangle = 0.0;
    TraceRate primary_one;  ///< coherent rays, one thread
    TraceRate random_one;   ///< incoherent rays, one thread
    TraceRate primary_all;  ///< coherent rays, all threads
    TraceRate random_all;   ///< incoherent rays, all threads
    /// The same rays eight at a time (Accelerator::closest_hit_packet), one thread: camera rays
    /// in tiles of 4x2 pixels, random rays in the order drawn. Unmeasured for brute force.
    TraceRate primary_packet_one;
    TraceRate random_packet_one;
    unsigned threads = 1;
    /// The CPU the one-thread runs ended on (sched_getcpu) when --pin held them there; else
    /// LabOptions::kNoPin.
    int pinned_cpu = LabOptions::kNoPin;
    /// The BVH's tree's expected cost (bvh/tree_cost.h); none for the other methods.
    std::optional<bvh::TreeCost> tree_cost;
};

struct LabRays {
    std::vector<Ray> primary;
    std::vector<Ray> random;
};

std::uint64_t fan_triangles(const Scene& scene);

/// Nothing when the method is not built into this rt (NotImplementedError).
std::optional<Measurement> measure(const Scene& scene, const std::string& mesh, AccelKind kind,
                                   const LabRays& rays, const LabOptions& options);

}  // namespace rt::lab
