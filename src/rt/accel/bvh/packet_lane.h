// One lane of a packet walk (bvh_packet_traversal.cpp), shared with the walk a lane takes alone
// below a node (single_ray_walk.h): its ray, its exact form made on its first exact test, and
// its nearest hit so far in brute force's order (its float form is in PacketValues).
#pragma once

#include <cstdint>
#include <new>
#include <optional>

#include "rt/accel/accelerator.h"
#include "rt/accel/bvh/bvh_layout.h"
#include "rt/accel/hit.h"
#include "rt/accel/lane_exact_hit.h"
#include "rt/geometry/ray_polygon.h"
#include "rt/scene/scene.h"

namespace rt::bvh {

/// Nothing is initialised until the lane is started: zeroing eight lanes of a packet took half
/// of closest_hit_packet's own time.
class PacketLane {
public:
    PacketLane() {}  // NOLINT(cppcoreguidelines-pro-type-member-init,modernize-use-equals-default)
    /// For a nearest hit over `t`.
    void start(const Ray& ray, Interval t) {
        start(ray);
        t_ = t;
        new (&best_) ClosestHitSoFar(t);
    }
    /// For occlusion alone: best() is not to be used.
    void start(const Ray& ray) {
        ray_ = &ray;
        has_space_ = false;
    }
    const RaySpace& space() {
        if (!has_space_) {
            new (&space_) RaySpace(*ray_);
            has_space_ = true;
        }
        return space_;
    }
    ClosestHitSoFar& best() { return best_; }
    const Ray& ray() const { return *ray_; }
    /// The interval asked about (for a nearest hit).
    Interval interval() const { return t_; }

    /// Offers polygon `id`, in lane `t` of `packet` (null: read from the scene), to the nearest
    /// hit, as the single ray's walk does: nothing for the polygon the ray leaves, and before
    /// the ray's first exact test the plane alone (lane_exact_hit.h), which a feeler ending on
    /// its light or a ray leaving a surface beside coplanar neighbours often needs alone.
    /// `sure` when the pre-filter found the ray surely crossing the lane's triangle: a triangle
    /// polygon is then decided by its plane alone (lane_sure_hit).
    /// Returns whether the exact test found a hit (the nearest so far may then have moved).
    bool offer(const Scene& scene, const TrianglePacket* packet, int t, std::uint32_t id, bool sure,
               TraceCounters& counters) {
        if (leaves_polygon(*ray_, id)) {
            return false;
        }
        ++counters.polygon_tests;
        const Interval search = best_.search_interval();
        std::optional<double> hit;
        if (sure && lane_sure_hit(*ray_, scene, packet->position, t, id, search, hit)) {
            if (hit) {
                best_.offer(*hit, id);
            }
            return hit.has_value();
        }
        if (!has_space_) {
            if (packet != nullptr
                    ? lane_plane_certainly_missed(*ray_, scene, packet->position, t, id, search)
                    : polygon_plane_certainly_missed(*ray_, scene, id, search)) {
                return false;
            }
        }
        hit = packet != nullptr ? lane_exact_hit(space(), scene, packet->position, t, id, search)
                                : intersect_polygon(space(), scene.polygon_view(id), search);
        if (hit) {
            best_.offer(*hit, id);
        }
        return hit.has_value();
    }
    /// Whether polygon `id` blocks the ray within the interval `t` (occlusion), with the same
    /// plane test first.
    bool blocks(const Scene& scene, const TrianglePacket& packet, int lane, std::uint32_t id,
                bool sure, Interval t, TraceCounters& counters) {
        if (leaves_polygon(*ray_, id)) {
            return false;
        }
        ++counters.polygon_tests;
        std::optional<double> hit;
        if (sure && lane_sure_hit(*ray_, scene, packet.position, lane, id, t, hit)) {
            return hit.has_value();
        }
        if (!has_space_ &&
            lane_plane_certainly_missed(*ray_, scene, packet.position, lane, id, t)) {
            return false;
        }
        return lane_exact_hit(space(), scene, packet.position, lane, id, t).has_value();
    }

    std::uint32_t previous;  ///< the polygon last offered: fan triangles are adjacent

private:
    const Ray* ray_;
    Interval t_;
    bool has_space_;
    union {
        RaySpace space_;  ///< prepared on the lane's first exact test
    };
    union {
        ClosestHitSoFar best_;
    };
};

}  // namespace rt::bvh
