// The two kinds of bounds rt needs: a closed axis-aligned box in space (scene bounds, voxels,
// polygon boxes, the conservative tables of exit culling and the z-buffer) and an inclusive
// rectangle of pixels (the .scn output matrix, the film's window, render tiles).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "rt/core/vec3.h"

namespace rt {

/// A closed axis-aligned box, lo to hi. Default-constructed it is empty (lo above hi on every
/// axis), so adding points to it gives their bounds; a box made of one point has no extent.
struct Box3 {
    static constexpr double kInfinity = std::numeric_limits<double>::infinity();
    Vec3 lo{kInfinity, kInfinity, kInfinity};
    Vec3 hi{-kInfinity, -kInfinity, -kInfinity};

    /// The box holding just `p`.
    static constexpr Box3 around(const Vec3& p) { return {p, p}; }

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    bool contains(const Vec3& p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z &&
               p.z <= hi.z;
    }
    void add(const Vec3& p) {
        lo = min_components(lo, p);
        hi = max_components(hi, p);
    }
    void add(const Box3& b) {
        lo = min_components(lo, b.lo);
        hi = max_components(hi, b.hi);
    }
    /// Grown by `by` (per axis, >= 0) on every side.
    Box3 grown(const Vec3& by) const { return {lo - by, hi + by}; }
    Box3 grown(double by) const { return grown(Vec3{by, by, by}); }
    Vec3 extent() const { return hi - lo; }
    Vec3 centre() const { return (lo + hi) * 0.5; }
    double largest_extent() const {
        const Vec3 e = extent();
        return std::max({e.x, e.y, e.z});
    }
    /// Corner `index` in 0..7: bit 0 picks hi.x, bit 1 hi.y, bit 2 hi.z.
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
    friend constexpr bool operator==(const Box3&, const Box3&) = default;
};

/// The common part of two boxes (empty if they do not meet).
inline Box3 intersection(const Box3& a, const Box3& b) {
    return {max_components(a.lo, b.lo), min_components(a.hi, b.hi)};
}

/// Euclidean distance from a point to the box (0 inside).
inline double distance_to(const Box3& box, const Vec3& p) {
    Vec3 gap;
    for (int axis = 0; axis < 3; ++axis) {
        gap[axis] = std::max({box.lo[axis] - p[axis], 0.0, p[axis] - box.hi[axis]});
    }
    return length(gap);
}

/// An inclusive rectangle of pixels: columns left..right, rows top..bottom, row 0 at the top (the
/// manual's output matrix is written this way). Empty when right < left or bottom < top.
struct PixelRect {
    int left = 0;
    int top = 0;
    int right = 0;
    int bottom = 0;

    int width() const { return right - left + 1; }
    int height() const { return bottom - top + 1; }
    friend constexpr bool operator==(const PixelRect&, const PixelRect&) = default;
};

}  // namespace rt
