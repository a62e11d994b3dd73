// Exact, watertight ray-polygon intersection for planar polygons of any number of corners,
// convex or concave (manual 1.3: "the most time-consuming process ... is finding intersections").
// Every accelerator calls these routines on the untransformed ray, so they all agree bit for bit
// with brute force. Why a ray through a shared edge or corner hits exactly one of the polygons
// sharing it is argued in ray_polygon.cpp.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

#include "rt/core/ray.h"
#include "rt/core/vec3.h"
#include "rt/geometry/polygon_view.h"

namespace rt {

/// False for a ray every exact test misses: a non-finite origin or direction, or a zero
/// direction. (So is a finite direction whose length overflows, which this lets through.)
inline bool may_hit_anything(const Ray& ray) {
    const Vec3& d = ray.direction;
    return is_finite(d) && is_finite(ray.origin) && (d.x != 0.0 || d.y != 0.0 || d.z != 0.0);
}

/// A ray prepared once for many polygon tests: the shear that takes it to the z axis of its own
/// 2D space (Woop, Benthin and Wald, "Watertight ray/triangle intersection", JCGT 2013).
class RaySpace {
public:
    explicit RaySpace(const Ray& ray);
    const Ray& ray() const { return ray_; }
    /// False for a zero, infinite or NaN direction (or one whose length overflows), or a
    /// non-finite origin: every test misses.
    bool valid() const { return valid_; }
    /// The corner's 2D position seen along the ray (the ray itself is at 0,0). The same arithmetic
    /// for every corner, so a corner shared by neighbouring polygons gets the same bits in each.
    void project(const Vec3& corner, double& x, double& y) const;
    /// The axis the direction is largest along (0, 1 or 2): the one project() drops.
    int dropped_axis() const { return kz_; }
    /// project() for a ray whose dropped_axis() is Kz, with the axes known when compiled: the
    /// exact test calls it once a corner, and project() is this for the ray's own kz.
    template <int Kz>
    void project_dropping(const Vec3& corner, double& x, double& y) const {
        constexpr int kX = (Kz + 1) % 3;
        constexpr int kY = (kX + 1) % 3;
        const Vec3 a = corner - ray_.origin;
        // Separate statements: nothing for a compiler to fuse into a multiply-add.
        const double along_x = shear_x_ * component<Kz>(a);
        const double along_y = shear_y_ * component<Kz>(a);
        x = component<kX>(a) - along_x;
        y = component<kY>(a) - along_y;
    }
    /// |dot(unit normal, direction)| at or below which a polygon counts as seen edge-on.
    double grazing_limit() const { return grazing_limit_; }
    /// The direction's length and the unit vector along it, computed without overflow or
    /// underflow for any finite nonzero direction (t is measured in units of that length).
    double direction_length() const { return direction_length_; }
    /// Computed on each call: only a ray seen edge-on by some polygon needs it.
    Vec3 unit_direction() const { return scaled_direction_ / scaled_length_; }

private:
    template <int K>
    static double component(const Vec3& v) {
        if constexpr (K == 0) {
            return v.x;
        } else if constexpr (K == 1) {
            return v.y;
        } else {
            return v.z;
        }
    }

    Ray ray_;
    int kx_ = 0;
    int ky_ = 1;
    int kz_ = 2;
    double shear_x_ = 0.0;
    double shear_y_ = 0.0;
    double grazing_limit_ = 0.0;
    double direction_length_ = 0.0;
    Vec3 scaled_direction_;  ///< the direction over its largest |component|
    double scaled_length_ = 1.0;
    bool valid_ = false;
};

/// The exact sign (-1, 0 or +1) of x_a * y_b - y_a * x_b, the edge function of the projected
/// edge a->b seen from the ray. Antisymmetric by construction: edge_sign(b, a) == -edge_sign(a, b)
/// for every input, NaN included (which gives 0).
int edge_sign(double xa, double ya, double xb, double yb);

/// The winding number of the ray around the loop of corners (in loop order), the ray being moved
/// by one consistent infinitesimal displacement so that it never meets an edge or a corner.
/// 0 for an invalid RaySpace or fewer than 3 corners.
int winding_number(const RaySpace& space, std::span<const Vec3> corners);
int winding_number(const RaySpace& space, const PolygonView& polygon);

/// Whether the ray's line passes through the polygon: a nonzero winding number (so the middle of a
/// self-crossing star counts as inside).
bool ray_passes_through(const RaySpace& space, std::span<const Vec3> corners);

/// The t at which the ray meets the plane through `point` with normal `normal`:
/// dot(normal, point - origin) / dot(normal, direction); none for a ray parallel to the plane or
/// a non-finite t.
std::optional<double> plane_hit(const Ray& ray, const Vec3& point, const Vec3& normal);

/// Below this |cos| between a polygon's unit normal and the ray, the plane's t is ill-conditioned
/// and the exact test takes a grazing depth instead (ray_polygon.cpp, part 4).
inline constexpr double kGrazing = 1e-6;

/// The plane's t as the exact test takes it, for the plane through `first_corner` (the polygon's
/// corner 0) and `denominator` = dot(normal, direction).
inline double plane_depth(const Ray& ray, const Vec3& normal, const Vec3& first_corner,
                          double denominator) {
    return dot(normal, first_corner - ray.origin) / denominator;
}

/// Whether a ray with direction `d` certainly meets a plane away from edge-on, given
/// `denominator` = dot(normal, d): above the exact test's limit, kGrazing times the direction's
/// length as RaySpace computes it, which is below sqrt(3) (1 + 2^-50) times the largest
/// |component|; 1.75 times covers it (rounding is monotone, and where the products fall below the
/// smallest subnormal both round to 0). False for a NaN.
inline bool certainly_not_edge_on(double denominator, const Vec3& d) {
    const double largest = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
    return std::fabs(denominator) > (kGrazing * 1.75) * largest;
}

/// True only if the exact test certainly misses the polygon (unit `normal`, corner 0
/// `first_corner`) within `t` by its plane alone: the ray meets the plane away from edge-on, at a
/// t outside the interval. The exact test's own first step, on the same values with the same
/// operations (plane_depth), decided without the ray's RaySpace, so that a ray whose every
/// candidate fails here never makes one: a ray leaving a surface beside coplanar neighbours, or
/// a shadow feeler ending on its light's polygon ("away from edge-on": certainly_not_edge_on).
/// False when unsure, and for a NaN.
inline bool plane_certainly_missed(const Ray& ray, const Vec3& normal, const Vec3& first_corner,
                                   Interval t) {
    const double denominator = dot(normal, ray.direction);
    const double along = plane_depth(ray, normal, first_corner, denominator);
    return certainly_not_edge_on(denominator, ray.direction) && std::isfinite(along) &&
           !(along > t.min && along < t.max);
}

/// The exact test's answer for a polygon whose projection the ray certainly crosses (its winding
/// number is known to be nonzero, e.g. from a float pre-filter's sure verdict, float_ray.cpp part
/// 4): away from edge-on that test returns the plane's t when it lies strictly inside `t` and
/// misses otherwise, and so does this, with the same operations on the same values (plane_depth),
/// without the ray's RaySpace or a corner's projection. Returns false, deciding nothing, near
/// edge-on, for a NaN, and for a direction so long that RaySpace could not measure it (no test
/// hits then); otherwise sets `hit`.
inline bool plane_decides_crossing(const Ray& ray, const Vec3& normal, const Vec3& first_corner,
                                   Interval t, std::optional<double>& hit) {
    const Vec3& d = ray.direction;
    const double denominator = dot(normal, d);
    const double along = plane_depth(ray, normal, first_corner, denominator);
    const double largest = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
    if (!(largest < 0x1p1000) || !certainly_not_edge_on(denominator, d) || !std::isfinite(along)) {
        return false;
    }
    hit = along > t.min && along < t.max ? std::optional<double>(along) : std::nullopt;
    return true;
}

/// Whether two normals are the same bit for bit: the exact test's denominators of two polygons are
/// then the same for any ray, as plane groups need.
inline bool same_normal_bits(const Vec3& a, const Vec3& b) {
    return std::bit_cast<std::uint64_t>(a.x) == std::bit_cast<std::uint64_t>(b.x) &&
           std::bit_cast<std::uint64_t>(a.y) == std::bit_cast<std::uint64_t>(b.y) &&
           std::bit_cast<std::uint64_t>(a.z) == std::bit_cast<std::uint64_t>(b.z);
}

/// A hash of a normal's bits, to find normals that may be the same bit for bit quickly.
inline std::uint64_t normal_bits_hash(const Vec3& n) {
    return std::bit_cast<std::uint64_t>(n.x) ^ (std::bit_cast<std::uint64_t>(n.y) * 3) ^
           (std::bit_cast<std::uint64_t>(n.z) * 7);
}

/// Whether a polygon with unit normal `normal` and corner 0 `first` lies in the plane group of a
/// polygon with the same normal (bit for bit: the caller compares them) and corner 0 `leader`:
/// dot(normal, first) within 2^-40 |normal|_1 max(|first|, |leader|) (largest |coordinate|s) of
/// dot(normal, leader). plane_group_certainly_missed answers for every polygon of such a group.
inline bool in_plane_group(const Vec3& normal, const Vec3& leader, const Vec3& first) {
    const double n1 = std::fabs(normal.x) + std::fabs(normal.y) + std::fabs(normal.z);
    const double size = std::max({std::fabs(first.x), std::fabs(first.y), std::fabs(first.z),
                                  std::fabs(leader.x), std::fabs(leader.y), std::fabs(leader.z)});
    return std::fabs(dot(normal, first) - dot(normal, leader)) <= 0x1p-40 * n1 * size;
}

/// True only if the exact test certainly misses, within any interval whose min is `t_min`, every
/// polygon of the plane group of a polygon with corner 0 `leader` (in_plane_group; the group's
/// normal bit for bit `normal`) whose corner 0 has no |coordinate| above `scale`: the ray meets
/// their plane away from edge-on (certainly_not_edge_on) and so near its origin that each one's
/// plane t (plane_depth, computed) is below t_min. For a ray leaving a polygon of a flat surface,
/// whose other polygons the float pre-filter keeps for nothing. The exact test's numerator dot(n,
/// q0 - o) is off from the real one by under 7u |n|_1 (|q0| + |o|); the group's spread is 2^-40
/// |n|_1 |q0| and the leader's plane offset from the origin is measured: their sum, with 2^-48 for
/// the roundings, times (1 + 2^-46), is compared with t_min |dot(n, d)| (1 - 2^-48). False when
/// unsure, for a NaN, or t_min <= 0.
inline bool plane_group_certainly_missed(const Ray& ray, const Vec3& normal, const Vec3& leader,
                                         double scale, double t_min) {
    const Vec3& d = ray.direction;
    const Vec3& o = ray.origin;
    const double denominator = std::fabs(dot(normal, d));
    if (!certainly_not_edge_on(denominator, d)) {
        return false;  // near edge-on the exact test takes corner depths
    }
    const double n1 = std::fabs(normal.x) + std::fabs(normal.y) + std::fabs(normal.z);
    const double size = scale * (1.0 + 0x1p-20);
    const double origin_size = std::max({std::fabs(o.x), std::fabs(o.y), std::fabs(o.z)});
    const double offset = std::fabs(dot(normal, o) - dot(normal, leader));
    const double reach =
        (0x1p-40 * n1 * size + offset + 0x1p-48 * n1 * (size + origin_size)) * (1.0 + 0x1p-46);
    return reach < t_min * denominator * (1.0 - 0x1p-48);
}

/// The exact tests below return a miss as NaN (no hit's t is NaN: a t outside the interval, NaN
/// included, is a miss). Accelerators call them through the inline std::optional forms: returned
/// from a call, GCC builds a std::optional<double> in memory, one byte then a load of eight, a
/// store-forwarding stall on every polygon test (a third of the exact test's own time).
double polygon_hit_or_nan(const Ray& ray, std::span<const Vec3> corners, const Vec3& normal,
                          Interval t);
double polygon_hit_or_nan(const RaySpace& space, const PolygonView& polygon, Interval t);

/// NaN (a miss) as no value.
inline std::optional<double> hit_unless_nan(double t) {
    if (t != t) {
        return std::nullopt;
    }
    return t;
}

/// The t of the ray's hit on the polygon with these corners and this unit normal, strictly inside
/// the interval. Hit or miss is decided by winding_number() alone; t is the plane's, except for a
/// polygon seen (nearly) edge-on, whose t is kept within its corners' depths along the ray and
/// (up to a rounding margin) where the line is inside the corners' box.
inline std::optional<double> intersect_polygon(const Ray& ray, std::span<const Vec3> corners,
                                               const Vec3& normal, Interval t) {
    return hit_unless_nan(polygon_hit_or_nan(ray, corners, normal, t));
}

/// The t of the ray's hit on the polygon, strictly inside the interval. The form to call in a loop
/// over polygons: the RaySpace is computed once per ray. Corners are read through their indices,
/// so an accelerator keeping its own copy of the indices (PolygonView over them) gets the same
/// answer bit for bit.
inline std::optional<double> intersect_polygon(const RaySpace& space, const PolygonView& polygon,
                                               Interval t) {
    return hit_unless_nan(polygon_hit_or_nan(space, polygon, t));
}

/// As above, preparing the ray itself.
inline std::optional<double> intersect_polygon(const Ray& ray, const PolygonView& polygon,
                                               Interval t) {
    return intersect_polygon(RaySpace(ray), polygon, t);
}

}  // namespace rt
