// Why the float tests never lose a hit the exact test would find.
//
// Let m = S + |O| (S the largest |coordinate| of any box, |O| the largest |coordinate| of the
// origin) and u = 2^-24, float's rounding unit. Every bound below is taken with a factor of at
// least 2 to spare; kRelativeSlack = 2^-20 = 16u. Each bound counts one rounding per operation;
// where a multiply and an add are fused into one step (fused_float8.h), that step rounds once
// instead of twice, so the same bound holds.
//
// 1. Where the exact test can hit. intersect_polygon decides by the winding number of the ray
//    around the polygon's corners projected in double (RaySpace::project), each projected
//    coordinate within about 2^-49 m of the real projection. A nonzero winding number means the
//    ray passes through one of the polygon's fan triangles as projected, so within 2^-49 m of
//    that real triangle: the ray's line passes within 2^-49 m of the polygon's box.
//    The t it returns is either the plane's (polygon normal, |cos| above RaySpace's grazing
//    limit of 1e-6) or a grazing depth. The plane's point lies within 2^-49 m / 1e-6 < 2^-28 m
//    of the polygon, so of its box, as long as the plane is the polygon's (non-planar corners
//    are covered by inflating the box, polygon_references.cpp); its t's own rounding, at most
//    2^-52 * 1e6 * m / |D'| < 2^-31 m / |D'|, moves it less than 2^-31 m. The grazing depth is
//    kept where the line is within 2^-39 m of the corners' box (ray_polygon.cpp, part 4). So
//    the hit's point is within 2^-27 m of the box on every axis, and a box is culled only when
//    its line misses it or meets it only outside [t_min, t_max] (slab test, below), with margins
//    that swallow that distance and the rounding of the double and float computations.
//
// 2. Slab test. With o = float(O) (error <= u|O|), inverse = float(1/D') (relative error <= u),
//    plane p a float, a plane's t is taken in one of two forms, against the real (p - O) / D':
//    - a ray's own test (bvh/box_test.h), two float operations: p * inverse - offset, the offset
//      o * inverse + slab_margin (near planes) or o * inverse - slab_margin (far planes), rounded
//      in float once a ray. Off from the real t -+ slab_margin by at most 3u |t| (the inverse's
//      and the subtraction's relative roundings) plus u (|p| + 3|O|) |1/D'| <= 3u m |1/D'| (the
//      roundings of the two products and of the offset's sum, and the origin's rounding divided
//      by D');
//    - a packet's tests (bvh/packet_node_tests.h), lane by lane and as a bound over its lanes
//      (each operation is monotone in each operand): (p - o) * inverse -+ slab_margin, off from
//      the real t -+ slab_margin by at most 3u |t| + u |O| |1/D'| (relative roundings, and the
//      origin's rounding divided by D').
//    slab_margin[k] = 2^-20 m |inverse[k]| = 16u m |inverse[k]| covers the 3u m |1/D'| and the
//    2^-27 m of part 1 five times over; the 3u |t| is covered by widening the final interval by
//    kRelativeSlack |t|. A zero direction component is clamped to 2^-60 times the largest: the
//    pretend ray drifts by 2^-60 t, below 2^-57 m for any t at which it is still within the
//    scene, far inside the margin (and p * inverse stays below 2^100, a finite float). The
//    interval, so widened, holds the scaled t of every hit the exact test can find in the box,
//    and t_min and t_max are rounded outward (scaled_down, scaled_up) before they are compared.
//
// 3. Triangle pre-filter. The float projection of a corner (stored rounded to nearest) differs
//    from the double one by at most eps = 2^-20 m (about 8u m: the corner's and origin's
//    rounding, the shear's, three operations). The edge function E = x_a y_b - y_a x_b computed
//    in float then differs from the double one by at most 4 eps L + 4 eps^2 + 4u L^2, L the
//    largest |coordinate| of the triangle's projected corners. If the double E of the three
//    edges had strictly mixed signs, the origin would lie outside the triangle as projected in
//    double, and so would the exact test's displaced ray (which is within an infinitesimal of
//    the origin): rejecting needs the float E's to have mixed signs beyond
//    8 eps L + 2^-20 L^2 + 8 eps^2.
#include "rt/accel/float_prefilter/float_ray.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace rt {

namespace {

constexpr double kLargestScale = 0x1p40;
constexpr double kSmallestScale = 0x1p-40;
constexpr double kLargestInverse = 0x1p60;

// A positive bound, rounded up: the 2^-20 spare swallows the conversion's rounding.
float bound_up(double x) {
    return static_cast<float>(x * (1.0 + 0x1p-20));
}

// 2^-e for the exponent e of x, so that x * result lies in [1, 2): cheap bit work for the usual
// magnitudes, ldexp for the extremes.
double power_of_two_below(double x, double& inverse) {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const int exponent = static_cast<int>((bits >> 52) & 0x7ff) - 1023;
    if (exponent < -1000 || exponent > 1000) {
        const int e = std::ilogb(x);
        inverse = std::ldexp(1.0, e);
        return std::ldexp(1.0, -e);
    }
    inverse = std::bit_cast<double>(static_cast<std::uint64_t>(1023 + exponent) << 52);
    return std::bit_cast<double>(static_cast<std::uint64_t>(1023 - exponent) << 52);
}

// The axes of the ray's sheared frame: kz the axis of the largest of the three magnitudes (the
// later one on a tie), kx and ky after it, as `(ax > ay) ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2)`
// and then (kz + 1) % 3, (kz + 2) % 3, but by arithmetic on the comparisons. As branches (the
// choice, and a component read by axis), each was a coin toss for rays in random directions.
struct Axes {
    int kx;
    int ky;
    int kz;
};

Axes axes_along(double ax, double ay, double az) {
    const int x_above_y = static_cast<int>(ax > ay);
    const int x_largest = x_above_y & static_cast<int>(ax > az);
    const int y_largest = (1 - x_above_y) & static_cast<int>(ay > az);
    // x largest: 1, 2, 0; y largest: 2, 0, 1; neither: 0, 1, 2.
    return {x_largest + 2 * y_largest, 1 + x_largest - y_largest, 2 - 2 * x_largest - y_largest};
}

// The BVH's set-up of the box tests' values, the axes and the shears, without a branch on the
// direction: the lab's random rays ran 6-29 % faster so (docs/lab/axes-2026-12-06.md).
// `magnitude` holds |d| per axis, `scaled` d scaled to a largest |component| in [1, 2).
void set_up_boxes_and_axes(FloatRay& r, const Vec3& d, const Vec3& magnitude, const Vec3& scaled,
                           double m) {
    // From the direction's sign bits, not the inverse's: known before the divisions end.
    r.negative = static_cast<std::uint32_t>(std::signbit(d.x)) |
                 static_cast<std::uint32_t>(std::signbit(d.y)) << 1U |
                 static_cast<std::uint32_t>(std::signbit(d.z)) << 2U;
    // Components read by index from an array: Vec3's operator[] picks among x, y, z by branches.
    const std::array<double, 3> along{scaled.x, scaled.y, scaled.z};
    std::array<double, 3> inv{};
    for (std::size_t k = 0; k < 3; ++k) {
        inv[k] = 1.0 / along[k];
        if (!(std::fabs(inv[k]) <= kLargestInverse)) {
            inv[k] = std::copysign(kLargestInverse, along[k]);
        }
        r.inverse[k] = static_cast<float>(inv[k]);
        r.slab_margin[k] = bound_up(0x1p-20 * m * std::fabs(inv[k]));
    }
    const auto [kx, ky, kz] = axes_along(magnitude.x, magnitude.y, magnitude.z);
    r.kx = kx;
    r.ky = ky;
    r.kz = kz;
    // |scaled[kz]| is in [1, 2), so its inverse needs no clamp (the voxel methods' set-up takes
    // it unclamped: the same bits either way); two roundings, well inside the 8u of the bound.
    const double inverse_kz = inv[static_cast<std::size_t>(kz)];
    r.shear_x = static_cast<float>(along[static_cast<std::size_t>(kx)] * inverse_kz);
    r.shear_y = static_cast<float>(along[static_cast<std::size_t>(ky)] * inverse_kz);
}

// The set-up, with or without the box tests' values: the BVH's full one reuses its reciprocal on
// kz for the shears.
template <bool kBoxes>
void set_up(FloatRay& r, const Ray& ray, double scene_scale) {
    const Vec3& d = ray.direction;
    const double ax = std::fabs(d.x);
    const double ay = std::fabs(d.y);
    const double az = std::fabs(d.z);
    const double largest = std::max({ax, ay, az});
    const double origin_size =
        std::max({std::fabs(ray.origin.x), std::fabs(ray.origin.y), std::fabs(ray.origin.z)});
    const double m = scene_scale + origin_size;
    // (max ignores a NaN, so finiteness is asked of every component.)
    r.usable = is_finite(d) && is_finite(ray.origin) && largest > 0.0 && m >= kSmallestScale &&
               m <= kLargestScale;
    if (!r.usable) {
        return;
    }
    const double shrink = power_of_two_below(largest, r.scale_t);  // D = scale_t D'; t' = t scale_t
    const Vec3 scaled = d * shrink;                                // exact
    for (int k = 0; k < 3; ++k) {
        r.origin[k] = static_cast<float>(ray.origin[k]);
    }
    if constexpr (kBoxes) {
        set_up_boxes_and_axes(r, d, {ax, ay, az}, scaled, m);
    } else {
        // The voxel methods' set-up keeps its branches: without them their camera rays ran
        // 2-3 % slower and their random rays no faster (docs/lab/axes-2026-12-06.md).
        r.kz = (ax > ay) ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        r.kx = (r.kz + 1) % 3;
        r.ky = (r.kx + 1) % 3;
        // |scaled[kz]| is in [1, 2): the same reciprocal as the full set-up's, unclamped.
        const double inverse_kz = 1.0 / scaled[r.kz];
        r.shear_x = static_cast<float>(scaled[r.kx] * inverse_kz);
        r.shear_y = static_cast<float>(scaled[r.ky] * inverse_kz);
    }
    const double eps = 0x1p-20 * m;
    r.edge_margin_linear = bound_up(8.0 * eps);
    r.edge_margin_constant = bound_up(8.0 * eps * eps);
}

}  // namespace

FloatRay::FloatRay(const Ray& ray, double scene_scale) {
    set_up<true>(*this, ray, scene_scale);
}

FloatRay::FloatRay(const Ray& ray, double scene_scale, TrianglesOnly) {
    set_up<false>(*this, ray, scene_scale);
}

}  // namespace rt
