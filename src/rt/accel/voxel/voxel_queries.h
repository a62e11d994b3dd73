// The closest-hit and occlusion queries of the octree and SEADS, written once: clip the ray to the
// world, prepare it, then walk the structure's voxels nearest first, testing each voxel's polygons
// (after its bounds, where it has them) until the near-hit rule ends the walk, or, for
// occlusion, until any polygon is hit. The two methods differ only in their walk, which each
// passes in; everything is a template, forced inline (as one function per method, the compiler
// would not inline it on its own: some 45 instructions a ray more), so the walk and the tests
// inline into one loop as they did when each method wrote the queries out.
//
// Both queries clip the ray to the world before anything else: a ray that misses it (about half
// of random rays starting outside) then costs no search setup, and the exact RaySpace waits for
// the first exact test. Invalid rays answer "no hit" either way.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "rt/accel/accelerator.h"
#include "rt/accel/voxel/box.h"
#include "rt/accel/voxel/cell_packets.h"
#include "rt/accel/voxel/near_hit_rule.h"
#include "rt/accel/voxel/polygon_boxes.h"
#include "rt/accel/voxel/voxel_hit_search.h"
#include "rt/geometry/ray_polygon.h"

namespace rt {

/// What the queries need of a voxel structure besides its walk.
struct VoxelSearchParts {
    const Scene& scene;
    const PolygonBoxes& boxes;
    const Box3& world;
    std::uint32_t bounds_slots = 0;  ///< in front of each voxel's ids (voxel_bounds.h), or 0
    const WalkRules& rules;
    const CellPackets& packets;  ///< each voxel's triangles, by the voxel's number
    /// The float tests' scene scale: covers the boxes' triangles and the packets' lanes.
    double float_scale() const { return std::max(boxes.scale(), packets.scale()); }
};

// `walk(inside, inverse, visit)` calls visit(cell, t_exit) for each voxel along the ray within
// `inside` (the interval already clipped to the world), nearest first, until visit returns true:
// `cell` the voxel's view in `packets`, empty for a voxel (or a run of them) known empty.
// `inverse` holds 1 / direction on each axis the ray moves along: the line probe's reciprocals,
// computed once a ray for the clip, the walk and the probe's box tests.

/// The query's interval, held in one 16-byte register across the calls that prepare the ray. It
/// arrives in two registers; kept as it is, GCC spilled it as two 8-byte stores and read it back
/// as one 16-byte load, which the store buffer cannot forward: a stall at the start of every ray,
/// 13 % of the octree's own samples on twocubes.
class HeldInterval {
public:
#if defined(__SSE2__)
    explicit HeldInterval(Interval t) {
        double min = t.min;
        double max = t.max;
        // Each end stays in a register of its own here, so the pair is made by a shuffle.
        asm("" : "+x"(min), "+x"(max));
        held_ = _mm_unpacklo_pd(_mm_set_sd(min), _mm_set_sd(max));
    }
    Interval get() const {
        return {_mm_cvtsd_f64(held_), _mm_cvtsd_f64(_mm_unpackhi_pd(held_, held_))};
    }

private:
    __m128d held_;
#else
    explicit HeldInterval(Interval t) : held_(t) {}
    Interval get() const {
        return held_;
    }

private:
    Interval held_;
#endif
};

/// The nearest hit, as brute force finds it (docs/accelerators.md, "Near hits and the fudge").
template <class Walk>
[[gnu::always_inline]] inline std::optional<Hit> voxel_closest_hit(const VoxelSearchParts& parts,
                                                                   const Ray& ray, Interval query,
                                                                   TraceCounters& counters,
                                                                   Walk&& walk) {
    const HeldInterval held(query);
    const double slack = rounding_slack(ray, parts.world, parts.rules);
    const LineProbe line(ray);
    const Interval t = held.get();
    Interval inside;
    if (!clip_to_box(ray, line.inverse, parts.world, walk_interval(t, slack), inside)) {
        return std::nullopt;
    }
    if (!may_hit_anything(ray)) {
        return std::nullopt;
    }
    NearestHitSearch search(parts.scene, parts.boxes, parts.float_scale(), ray, line, t, counters);
    NearHitRule rule(parts.rules, slack);
    walk(inside, line.inverse, [&](const CellView& cell, double t_exit) {
        if (voxel_may_hold_hit(cell, search.line())) {
            search.test(search.packets_to_test(cell));
        }
        return rule.ends_walk(search.nearest(), t_exit, counters);
    });
    return search.nearest();
}

/// Whether any polygon is hit inside the interval; not subject to -tv.
template <class Walk>
[[gnu::always_inline]] inline bool voxel_occluded(const VoxelSearchParts& parts, const Ray& ray,
                                                  Interval query, TraceCounters& counters,
                                                  Walk&& walk) {
    const HeldInterval held(query);
    const LineProbe line(ray);
    const Interval t = held.get();
    Interval inside;
    if (!clip_to_box(ray, line.inverse, parts.world,
                     walk_interval(t, rounding_slack(ray, parts.world, parts.rules)), inside)) {
        return false;
    }
    if (!may_hit_anything(ray)) {
        return false;
    }
    AnyHitSearch search(parts.scene, parts.boxes, parts.float_scale(), ray, line, t, counters);
    bool hit = false;
    walk(inside, line.inverse, [&](const CellView& cell, double) {
        ++counters.voxels_stepped;
        hit = voxel_may_hold_hit(cell, search.line()) && search.test(search.packets_to_test(cell));
        return hit;
    });
    return hit;
}

}  // namespace rt
