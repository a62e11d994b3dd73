// When a voxel walk may stop (manual 3.1, "near hits"). A hit found while testing one voxel's
// polygons may lie beyond that voxel; a polygon met only in a later voxel could then be nearer.
// By default such a near hit is kept as a candidate and accepted only once the walk reaches it
// (the voxel whose exit lies at or beyond its t), or when the walk runs out of voxels: the answer
// is then exactly brute force's (docs/accelerators.md argues why). -on accepts it at once; -tv
// gives up after so many voxels without any hit.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "rt/accel/accel_settings.h"
#include "rt/accel/accelerator.h"
#include "rt/accel/voxel/box.h"

namespace rt {

struct WalkRules {
    bool accept_near_hits = false;                                                    ///< -on
    std::uint64_t fruitless_voxel_limit = std::numeric_limits<std::uint64_t>::max();  ///< -tv
    bool no_fudge = false;                                                            ///< -of

    static WalkRules from(const AccelSettings& settings);
};

/// How far in t a computed hit may lie from its true point, for this ray: the plane's t is off by
/// a few units in the last place of the distance from the ray's origin, divided by |cos| >= 1e-6
/// (below that intersect_polygon leaves the plane), so 2^-29 of (distance to the world's centre
/// plus the world's size) covers it; both lengths are bounded from the safe side without square
/// roots. The walk starts and ends that much beyond the interval and
/// accepts a hit only that much before a voxel's exit, so it stays exact wherever the origin is.
/// Zero with -of. Inline: asked once a voxel query, where its division overlaps the line probe's.
inline double rounding_slack(const Ray& ray, const Box3& world, const WalkRules& rules) {
    if (rules.no_fudge) {
        return 0.0;
    }
    // Bounds that need no square root, each at least the length it stands for: the sum of
    // |components| for the distance, the largest |component| for the direction's length. A
    // larger slack only walks a little further; the answers stay exact.
    const Vec3 centre = (world.lo + world.hi) * 0.5;
    const Vec3 away = ray.origin - centre;
    const Vec3& d = ray.direction;
    const double distance = std::fabs(away.x) + std::fabs(away.y) + std::fabs(away.z);
    const double direction = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
    return 0x1p-29 * (distance + world.largest_extent()) / direction;
}

/// The interval to walk for a ray asked about `t`: `t` widened by the slack at both ends.
inline Interval walk_interval(Interval t, double slack) {
    return {t.min - slack, t.max + slack};
}

class NearHitRule {
public:
    NearHitRule(const WalkRules& rules, double slack) : rules_(rules), slack_(slack) {}

    /// Called after each voxel's polygons are tested, with the nearest hit so far and the t at
    /// which the ray leaves that voxel: whether the walk ends here. Counts the voxel and any new
    /// near hit.
    bool ends_walk(const std::optional<Hit>& nearest, double t_exit, TraceCounters& counters) {
        ++counters.voxels_stepped;
        if (!nearest) {
            return ++fruitless_ >= rules_.fruitless_voxel_limit;
        }
        if (nearest->t <= t_exit - slack_) {
            return true;
        }
        if (!counted_any_ || last_.t != nearest->t || last_.polygon != nearest->polygon) {
            ++counters.near_hits;
            last_ = *nearest;
            counted_any_ = true;
        }
        return rules_.accept_near_hits;
    }

private:
    WalkRules rules_;
    double slack_ = 0.0;
    std::uint64_t fruitless_ = 0;
    Hit last_;  ///< the last near hit counted (a plain Hit: GCC 12 misreads an optional here)
    bool counted_any_ = false;
};

}  // namespace rt
