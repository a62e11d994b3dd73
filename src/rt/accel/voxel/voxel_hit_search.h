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

/// What both searches share: the ray's box probes and the polygons it has tested, so that each
/// polygon along the ray is tested once, and only when its boxes may meet the ray.
class PolygonSieve {
public:
    PolygonSieve(const Scene& scene, const PolygonBoxes& boxes, const RaySpace& space,
                 TraceCounters& counters)
        : scene_(scene),
          boxes_(boxes),
          line_(space.ray()),
          triangle_(space.ray(), boxes.scale()),
          space_(space),
          counters_(counters) {}

    const LineProbe& line() const { return line_; }

protected:
    /// Calls test(id) for each of the polygons that passes the sieve, counting the test, until
    /// test returns true; returns whether one did.
    template <class Test>
    bool test_each(std::span<const std::uint32_t> polygons, Test&& test) {
        // Every box this voxel needs, and every polygon record, asked for at once: their cache
        // misses then overlap instead of each waiting for the one before.
        for (const std::uint32_t id : polygons) {
            boxes_.prefetch(id);
            __builtin_prefetch(scene_.polygons.data() + id);
        }
        for (const std::uint32_t id : polygons) {
            if (tested_.seen(id) || !boxes_.line_may_meet(line_, id) ||
                !boxes_.triangle_may_be_hit(triangle_, id)) {
                continue;
            }
            ++counters_.polygon_tests;
            if (test(id)) {
                return true;
            }
        }
        return false;
    }

    const Scene& scene_;
    const PolygonBoxes& boxes_;
    LineProbe line_;
    TriangleProbe triangle_;
    const RaySpace& space_;
    TraceCounters& counters_;
    TestedPolygons tested_;
};

/// The nearest hit over every polygon tested so far along one ray, in brute force's order
/// (hit.h): the same rule as brute force, so the same answer.
class NearestHitSearch : public PolygonSieve {
public:
    NearestHitSearch(const Scene& scene, const PolygonBoxes& boxes, const RaySpace& space,
                     Interval t, TraceCounters& counters)
        : PolygonSieve(scene, boxes, space, counters), nearest_(t) {}

    void test(std::span<const std::uint32_t> polygons);
    const std::optional<Hit>& nearest() const { return nearest_.best(); }

private:
    ClosestHitSoFar nearest_;
};

/// Whether any polygon tested is hit inside the interval (shadow feelers: any hit will do).
class AnyHitSearch : public PolygonSieve {
public:
    AnyHitSearch(const Scene& scene, const PolygonBoxes& boxes, const RaySpace& space, Interval t,
                 TraceCounters& counters)
        : PolygonSieve(scene, boxes, space, counters), t_(t) {}

    /// True as soon as one of them is hit.
    bool test(std::span<const std::uint32_t> polygons);

private:
    Interval t_;
};

}  // namespace rt
