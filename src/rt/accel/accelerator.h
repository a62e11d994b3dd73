// The one interface every intersection method implements (manual 3.1). A coarse, run-time choice,
// so it is virtual; the ray-polygon test inside is not.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>

#include "rt/accel/hit.h"
#include "rt/core/ray.h"
#include "rt/scene/scene.h"

namespace rt {

/// Per-thread counters; summed at the end of a run (-p prints them).
struct TraceCounters {
    std::uint64_t rays = 0;
    std::uint64_t polygon_tests = 0;
    std::uint64_t hits = 0;
    std::uint64_t voxels_stepped = 0;  ///< octree and SEADS cells entered
    std::uint64_t nodes_visited = 0;   ///< BVH nodes entered
    std::uint64_t near_hits = 0;       ///< hits found outside the current voxel (manual 3.1)
    std::uint64_t culled_exits = 0;    ///< rays ended by exit-ray culling

    TraceCounters& operator+=(const TraceCounters& o) {
        rays += o.rays;
        polygon_tests += o.polygon_tests;
        hits += o.hits;
        voxels_stepped += o.voxels_stepped;
        nodes_visited += o.nodes_visited;
        near_hits += o.near_hits;
        culled_exits += o.culled_exits;
        return *this;
    }
};

class Accelerator {
public:
    virtual ~Accelerator() = default;
    virtual std::string_view name() const = 0;
    /// The nearest hit with t strictly inside the interval; equal t goes to the lowest polygon id.
    virtual std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                           TraceCounters& counters) const = 0;
    /// closest_hit for an eye ray: one the renderer sends from the eye through the screen. A
    /// method that keeps something for eye rays alone (the z-buffer) answers it from that; the
    /// others, and the layers that only pass rays on, answer as closest_hit.
    virtual std::optional<Hit> eye_ray_closest_hit(const Ray& ray, Interval t,
                                                   TraceCounters& counters) const {
        return closest_hit(ray, t, counters);
    }
    /// Whether any polygon is hit with t inside the interval (shadow feelers that stop dead).
    virtual bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const = 0;
    /// Bytes held by the structure (not the scene), for -p and the lab.
    virtual std::size_t memory_bytes() const { return 0; }
};

}  // namespace rt
