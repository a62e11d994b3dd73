// What the SEADS and octree walks share: testing a voxel's polygons against one ray, remembering
// the nearest hit so far, and skipping polygons this ray has already tested (a polygon lies in
// every voxel it touches, so a ray meets it again and again).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>

#include "rt/accel/accelerator.h"
#include "rt/accel/lane_exact_hit.h"
#include "rt/accel/voxel/cell_packets.h"
#include "rt/accel/voxel/cell_pair_test.h"
#include "rt/accel/voxel/polygon_boxes.h"
#include "rt/accel/voxel/voxel_bounds.h"
#include "rt/geometry/ray_polygon.h"

namespace rt {

/// The per-ray tested-polygon set: a small direct-mapped cache of polygon ids, on the stack, so
/// that one const accelerator serves many threads. A collision only forgets a polygon, which is
/// then tested again with the same result: never wrong, just slower.
class TestedPolygons {
public:
    /// True if `id` was tested already; otherwise records it and returns false.
    bool seen(std::uint32_t id) {
        std::uint32_t& slot = slots_[id % kSlots];
        if (slot == id) {
            return true;
        }
        slot = id;
        return false;
    }

private:
    static constexpr std::uint32_t kSlots = 64;
    static constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();
    static constexpr std::array<std::uint32_t, kSlots> kAllEmpty = [] {
        std::array<std::uint32_t, kSlots> slots{};
        slots.fill(kEmpty);
        return slots;
    }();
    std::array<std::uint32_t, kSlots> slots_ = kAllEmpty;
};

/// Whether a voxel's polygons need testing against this line: there are some, and the line meets
/// the voxel's bounds where the structure has them (bounds_slots != 0; voxel_bounds.h).
inline bool voxel_may_hold_hit(std::span<const std::uint32_t> polygons, std::uint32_t bounds_slots,
                               const LineProbe& line) {
    return !polygons.empty() &&
           (bounds_slots == 0 || line_may_meet_box(line, bounds_before(polygons).data()));
}

/// The same for a voxel's packets, with the bounds copied in front of them (cell_packets.h).
inline bool voxel_may_hold_hit(const CellView& cell, const LineProbe& line) {
    return !cell.packets.empty() &&
           (cell.bounds == nullptr || line_may_meet_box(line, cell.bounds));
}

/// What both searches share: the ray's box probes and the polygons it has tested, so that each
/// polygon along the ray is tested once, and only when its boxes may meet the ray.
class PolygonSieve {
public:
    /// `scale`: at least the boxes' and the packets' scale (the float tests' error bounds).
    /// `line`: the ray's line probe, which the caller keeps (it shares its reciprocals).
    /// `t_min`: the least t the query asks about.
    PolygonSieve(const Scene& scene, const PolygonBoxes& boxes, double scale, const Ray& ray,
                 const LineProbe& line, double t_min, TraceCounters& counters)
        : scene_(scene),
          boxes_(boxes),
          line_(line),
          triangle_(ray, scale),
          counters_(counters),
          ray_(ray),
          scale_(scale),
          t_min_(t_min) {}

    const LineProbe& line() const { return line_; }

    /// The cell's packets this ray must test: all of them, or for a ray leaving a polygon of the
    /// cell's plane group (cell_packets.h) those after the group's, when its exact tests
    /// certainly all miss (plane_group_certainly_missed). The group
    /// is the polygons the float pre-filter keeps for a ray starting in their plane, to no end.
    std::span<const CellPacket> packets_to_test(const CellView& cell) const {
        if (cell.plane_packets != 0 && ray_.leaves != kLeavesNoPolygon) {
            const Polygon& leader = scene_.polygons[cell.plane_polygon];
            const Vec3& left = scene_.polygons[ray_.leaves].normal;
            // Component by component: Vec3's defaulted == cost 0.35 % more of twocubes4's
            // instructions here.
            if (left.x == leader.normal.x && left.y == leader.normal.y &&
                left.z == leader.normal.z &&
                plane_group_certainly_missed(ray_, leader.normal, scene_.corner_position(leader, 0),
                                             scale_, t_min_)) {
                return cell.packets.subspan(cell.plane_packets);
            }
        }
        return cell.packets;
    }

protected:
    /// Calls test(id, packet.position, lane, sure) for each polygon of a voxel's packets that
    /// passes the sieve, counting the test, until test returns true; returns whether one did. The
    /// float test rejects four fan triangles at a time; a polygon with a lane left is tested once
    /// (and, for a lane marked "always", or a ray the float test cannot serve, after its box
    /// look). `sure` when the float test found the ray's line surely crossing the lane's triangle.
    template <class Test>
    bool test_packets(std::span<const CellPacket> packets, Test&& test) {
        const FloatRay& ray = triangle_.get();
        for (const CellPacket& packet : packets) {
            if (!ray.usable) {
                if (test_lanes(packet, used_lanes(packet), 0u, test)) {
                    return true;
                }
                continue;
            }
            const bvh::FanVerdicts verdicts = cell_packet_verdicts(packet, ray);
            if (test_lanes(packet, verdicts.maybe, verdicts.sure, test)) {
                return true;
            }
        }
        return false;
    }

#ifdef RT_VOXEL_AVX2
    /// The same, the float test taking two packets at a time (cell_pair_test.h).
    template <class Test>
    __attribute__((target("avx2"))) bool test_packets_avx2(std::span<const CellPacket> packets,
                                                           Test&& test) {
        const FloatRay& ray = triangle_.get();
        if (!ray.usable) {
            return test_packets(packets, test);
        }
        const CellPacket* packet = packets.data();
        const CellPacket* const end = packet + packets.size();
        for (; end - packet >= 2; packet += 2) {
            const bvh::FanVerdicts verdicts = cell_pair_verdicts(packet, ray);
            if (verdicts.maybe != 0 &&
                (test_lanes(packet[0], verdicts.maybe & 0xfu, verdicts.sure & 0xfu, test) ||
                 test_lanes(packet[1], verdicts.maybe >> 4, verdicts.sure >> 4, test))) {
                return true;
            }
        }
        if (packet == end) {
            return false;
        }
        const bvh::FanVerdicts verdicts = cell_packet_verdicts(*packet, ray);
        return test_lanes(*packet, verdicts.maybe, verdicts.sure, test);
    }
#endif

    const Scene& scene_;
    const PolygonBoxes& boxes_;
    const LineProbe& line_;
    TriangleProbe triangle_;
    TraceCounters& counters_;
    TestedPolygons tested_;

    /// The ray's exact form, prepared on its first exact test: most rays (nearly all of those
    /// that miss everything) never reach one, and its two divisions and square root were a tenth
    /// of the octree's time on such rays.
    const RaySpace& space() {
        if (!space_) {
            space_.emplace(ray_);
        }
        return *space_;
    }

    /// Whether the exact test of this lane's polygon certainly misses within `t` by its plane,
    /// asked while the ray has no RaySpace (lane_plane_certainly_missed): the ray then makes
    /// one only for a polygon it may hit.
    bool missed_before_space(const LaneCorners& position, int lane, std::uint32_t id,
                             Interval t) const {
        return !space_ && lane_plane_certainly_missed(ray_, scene_, position, lane, id, t);
    }

    /// lane_sure_hit for a lane the float test found the ray surely crossing: true when it
    /// decided the exact test's answer, which is then in `hit`.
    bool decided_surely(const LaneCorners& position, int lane, std::uint32_t id, Interval t,
                        std::optional<double>& hit) const {
        return lane_sure_hit(ray_, scene_, position, lane, id, t, hit);
    }

private:
    const Ray& ray_;
    double scale_;
    double t_min_;
    std::optional<RaySpace> space_;

    // The polygons of the packet's `lanes` (those the float test kept, or every used one), `sure`
    // those it found the ray surely crossing.
    template <class Test>
    [[gnu::always_inline]] bool test_lanes(const CellPacket& packet, unsigned lanes, unsigned sure,
                                           Test& test) {
        const bool usable = triangle_.get().usable;
        for (; lanes != 0; lanes &= lanes - 1) {
            const int lane = __builtin_ctz(lanes);
            const std::uint32_t word = packet.polygon[lane];
            const std::uint32_t id = word & ~kAlwaysTestBit;
            const bool needs_box = (word & kAlwaysTestBit) != 0 || !usable;
            if (leaves_polygon(ray_, id) || tested_.seen(id) ||
                (needs_box && !boxes_.line_may_meet(line_, id))) {
                continue;
            }
            ++counters_.polygon_tests;
            if (test(id, packet.position, lane, ((sure >> lane) & 1u) != 0)) {
                return true;
            }
        }
        return false;
    }
};

/// The nearest hit over every polygon tested so far along one ray, in brute force's order
/// (hit.h): the same rule as brute force, so the same answer.
class NearestHitSearch : public PolygonSieve {
public:
    NearestHitSearch(const Scene& scene, const PolygonBoxes& boxes, double scale, const Ray& ray,
                     const LineProbe& line, Interval t, TraceCounters& counters)
        : PolygonSieve(scene, boxes, scale, ray, line, t.min, counters), nearest_(t) {}

    void test(std::span<const CellPacket> packets);
    const std::optional<Hit>& nearest() const { return nearest_.best(); }

private:
    // The exact test of one polygon, offering its hit. Polygons arrive in voxel order, not id
    // order: the tie rule picks among equal t.
    auto offer_to_nearest() {
        return [this](std::uint32_t id, const LaneCorners& position, int lane, bool sure)
            __attribute__((always_inline)) {
            const Interval within = nearest_.search_interval();
            std::optional<double> t;
            if (sure && decided_surely(position, lane, id, within, t)) {
                if (t) {
                    nearest_.offer(*t, id);
                }
                return false;
            }
            if (missed_before_space(position, lane, id, within)) {
                return false;
            }
            if ((t = lane_exact_hit(space(), scene_, position, lane, id, within))) {
                nearest_.offer(*t, id);
            }
            return false;
        };
    }

    ClosestHitSoFar nearest_;
};

/// Whether any polygon tested is hit inside the interval (shadow feelers: any hit will do).
class AnyHitSearch : public PolygonSieve {
public:
    AnyHitSearch(const Scene& scene, const PolygonBoxes& boxes, double scale, const Ray& ray,
                 const LineProbe& line, Interval t, TraceCounters& counters)
        : PolygonSieve(scene, boxes, scale, ray, line, t.min, counters), t_(t) {}

    /// True as soon as one of them is hit.
    bool test(std::span<const CellPacket> packets);

private:
    auto hit_within() {
        return [this](std::uint32_t id, const LaneCorners& position, int lane, bool sure)
            __attribute__((always_inline)) {
            std::optional<double> hit;
            if (sure && decided_surely(position, lane, id, t_, hit)) {
                return hit.has_value();
            }
            return !missed_before_space(position, lane, id, t_) &&
                   lane_exact_hit(space(), scene_, position, lane, id, t_).has_value();
        };
    }

    Interval t_;
};

}  // namespace rt
