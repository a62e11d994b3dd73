// A closed axis-aligned box, for the conservative tables of exit culling and the z-buffer.
#pragma once

#include <algorithm>
#include <limits>

#include "rt/core/vec3.h"

namespace rt {

struct AxisBox {
    static constexpr double kInfinity = std::numeric_limits<double>::infinity();
    Vec3 lo{kInfinity, kInfinity, kInfinity};  ///< empty until something is added
    Vec3 hi{-kInfinity, -kInfinity, -kInfinity};

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void add(const Vec3& p) {
        lo = min_components(lo, p);
        hi = max_components(hi, p);
    }
    void add(const AxisBox& b) {
        lo = min_components(lo, b.lo);
        hi = max_components(hi, b.hi);
    }
    /// Grown by `by` (per axis, >= 0) on every side.
    AxisBox grown(const Vec3& by) const { return {lo - by, hi + by}; }
    AxisBox grown(double by) const { return grown(Vec3{by, by, by}); }
    Vec3 extent() const { return hi - lo; }
    Vec3 corner(int index) const {
        return {(index & 1) ? hi.x : lo.x, (index & 2) ? hi.y : lo.y, (index & 4) ? hi.z : lo.z};
    }
    /// The largest |coordinate| of the box, for rounding allowances.
    double magnitude() const {
        double m = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
            m = std::max({m, std::fabs(lo[axis]), std::fabs(hi[axis])});
        }
        return m;
    }
};

inline AxisBox intersection(const AxisBox& a, const AxisBox& b) {
    return {max_components(a.lo, b.lo), min_components(a.hi, b.hi)};
}

/// Euclidean distance from a point to the box (0 inside).
inline double distance_to(const AxisBox& box, const Vec3& p) {
    Vec3 gap;
    for (int axis = 0; axis < 3; ++axis) {
        gap[axis] = std::max({box.lo[axis] - p[axis], 0.0, p[axis] - box.hi[axis]});
    }
    return length(gap);
}

}  // namespace rt
