// The one interface every intersection method implements (manual 3.1). A coarse, run-time choice,
// so it is virtual; the ray-polygon test inside is not.
#pragma once

#include <array>
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
    /// Rays exit culling confined to a few polygons, answered by their exact tests alone.
    std::uint64_t guard_answers = 0;

    TraceCounters& operator+=(const TraceCounters& o) {
        rays += o.rays;
        polygon_tests += o.polygon_tests;
        hits += o.hits;
        voxels_stepped += o.voxels_stepped;
        nodes_visited += o.nodes_visited;
        near_hits += o.near_hits;
        culled_exits += o.culled_exits;
        guard_answers += o.guard_answers;
        return *this;
    }
};

/// Rays asked together: coherent ones (eye rays of neighbouring pixels, shadow feelers from
/// neighbouring hits toward one light point) share the walk through a structure. A lane whose
/// bit in `active` is clear is not asked, and its answer is left as it was.
constexpr int kPacketSize = 8;
struct RayPacket {
    std::array<Ray, kPacketSize> rays{};
    std::array<Interval, kPacketSize> t{};
    std::uint32_t active = 0;  ///< bit k: lane k is asked
};
using PacketHits = std::array<std::optional<Hit>, kPacketSize>;

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
    /// closest_hit for each active lane of the packet, into hits[lane]: each answer is exactly
    /// the single ray's. Methods without a packet walk ask closest_hit lane by lane.
    virtual void closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                                    TraceCounters& counters) const {
        for (int lane = 0; lane < kPacketSize; ++lane) {
            if ((packet.active >> lane) & 1u) {
                hits[lane] = closest_hit(packet.rays[lane], packet.t[lane], counters);
            }
        }
    }
    /// Whether closest_hit_packet walks the packet's lanes together, so that coherent rays are
    /// cheaper asked eight at a time than one by one (the renderer then plans rays to ask so:
    /// RayTracer::eye_feelers). False for the lane-by-lane loop above.
    virtual bool walks_packets() const { return false; }
    /// closest_hit_packet for eye rays (see eye_ray_closest_hit): a method that answers eye rays
    /// from something of its own (the z-buffer) asks eye_ray_closest_hit lane by lane.
    virtual void eye_ray_closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                                            TraceCounters& counters) const {
        closest_hit_packet(packet, hits, counters);
    }
    /// occluded for each active lane: bit k set when lane k is blocked (inactive lanes: 0).
    virtual std::uint32_t occluded_packet(const RayPacket& packet, TraceCounters& counters) const {
        std::uint32_t blocked = 0;
        for (int lane = 0; lane < kPacketSize; ++lane) {
            if (((packet.active >> lane) & 1u) &&
                occluded(packet.rays[lane], packet.t[lane], counters)) {
                blocked |= 1u << lane;
            }
        }
        return blocked;
    }
    /// Bytes held by the structure (not the scene), for -p and the lab.
    virtual std::size_t memory_bytes() const { return 0; }
};

}  // namespace rt
