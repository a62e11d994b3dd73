// A ray's hit on a polygon, and the one order every intersection method answers by: the nearer
// hit first, and at equal t the lower polygon id. Brute force keeps that order by testing the
// polygons in ascending id and keeping only a strictly nearer hit; the other methods meet
// polygons in their own order (voxels along the ray, BVH leaves, a pixel's list) and keep the
// first hit by this rule, so that they answer exactly as brute force does.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>

#include "rt/core/next_up.h"
#include "rt/core/ray.h"

namespace rt {

struct Hit {
    double t = 0.0;
    std::uint32_t polygon = 0;
};

/// Whether `a` comes before `b`: nearer, or as near on a lower polygon id.
constexpr bool comes_before(const Hit& a, const Hit& b) {
    return a.t < b.t || (a.t == b.t && a.polygon < b.polygon);
}

/// The first hit in that order among the polygons asked so far along one ray, inside the
/// interval the ray was asked about. Small and inline: the methods call it in their inner loops.
class ClosestHitSoFar {
public:
    explicit ClosestHitSoFar(Interval t) : t_(t) {}

    /// The interval to ask the next polygon about: up to and including the best t so far, so
    /// that a polygon at that very t comes back and can still win with a lower id.
    Interval search_interval() const { return {t_.min, best_ ? next_up(best_->t) : t_.max}; }
    /// A hit found on `polygon` at `t`, kept if it comes before the best so far.
    void offer(double t, std::uint32_t polygon) {
        const Hit hit{t, polygon};
        if (!best_ || comes_before(hit, *best_)) {
            best_ = hit;
        }
    }
    const std::optional<Hit>& best() const { return best_; }
    /// The largest t a hit may have and still matter, inclusive (ties included).
    double reach() const { return best_ ? best_->t : t_.max; }

private:
    Interval t_;
    std::optional<Hit> best_;
};

}  // namespace rt
