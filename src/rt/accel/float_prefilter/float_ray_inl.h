// FloatRay's set-up, inline: included at the end of float_ray.h, not on its own. The BVH makes a
// FloatRay for every ray. Out of line, the call, its stack frame and the stores of default values
// that the set-up then overwrote cost the BVH's query 37 instructions a ray, 4.8 %
// (docs/lab/inline-setup-2026-12-06.md). float_ray.cpp argues the bounds it computes.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace rt {

namespace float_ray_detail {

inline constexpr double kLargestScale = 0x1p40;
inline constexpr double kSmallestScale = 0x1p-40;
inline constexpr double kLargestInverse = 0x1p60;

// A positive bound, rounded up: the 2^-20 spare swallows the conversion's rounding.
inline float bound_up(double x) {
    return static_cast<float>(x * (1.0 + 0x1p-20));
}

// 2^-e for the exponent e of x, so that x * result lies in [1, 2): cheap bit work for the usual
// magnitudes, ldexp for the extremes.
inline double power_of_two_below(double x, double& inverse) {
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

inline Axes axes_along(double ax, double ay, double az) {
    const int x_above_y = static_cast<int>(ax > ay);
    const int x_largest = x_above_y & static_cast<int>(ax > az);
    const int y_largest = (1 - x_above_y) & static_cast<int>(ay > az);
    // x largest: 1, 2, 0; y largest: 2, 0, 1; neither: 0, 1, 2.
    return {x_largest + 2 * y_largest, 1 + x_largest - y_largest, 2 - 2 * x_largest - y_largest};
}

// The BVH's set-up of the box tests' values, without a branch on the direction: the lab's random
// rays ran 6-29 % faster so (docs/lab/axes-2026-12-06.md). `scaled` is d scaled to a largest
// |component| in [1, 2). Returns the three reciprocals, clamped.
inline std::array<double, 3> set_up_boxes(FloatRay& r, const Vec3& d, const Vec3& scaled,
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
    return inv;
}

// The triangle pre-filter's edge margins, from m (the scene's scale plus the origin's size).
inline void set_up_edge_margins(FloatRay& r, double m) {
    const double eps = 0x1p-20 * m;
    r.edge_margin_linear = bound_up(8.0 * eps);
    r.edge_margin_constant = bound_up(8.0 * eps * eps);
}

// The triangle pre-filter's axes and shears, given |d| per axis (`magnitude`), d scaled as above
// and the reciprocal of its component on kz, and its edge margins from m. |scaled[kz]| is in
// [1, 2), so that reciprocal needs no clamp (the voxel methods' set-up takes it unclamped: the
// same bits either way); two roundings, well inside the 8u of the bound.
template <class InverseOnKz>
inline void set_up_triangles(FloatRay& r, const Vec3& magnitude, const Vec3& scaled, double m,
                             InverseOnKz inverse_on) {
    const auto [kx, ky, kz] = axes_along(magnitude.x, magnitude.y, magnitude.z);
    r.kx = kx;
    r.ky = ky;
    r.kz = kz;
    const std::array<double, 3> along{scaled.x, scaled.y, scaled.z};
    const double inverse_kz = inverse_on(kz, along);
    r.shear_x = static_cast<float>(along[static_cast<std::size_t>(kx)] * inverse_kz);
    r.shear_y = static_cast<float>(along[static_cast<std::size_t>(ky)] * inverse_kz);
    set_up_edge_margins(r, m);
}

// The set-up: the box tests' values and the triangle pre-filter's (Both, the full one, which
// reuses its reciprocal on kz for the shears), the box tests' alone (BoxesFirst: the triangles'
// wait for FloatRay::set_up_triangles), or the triangle pre-filter's alone (the voxel methods').
enum class Parts { Both, BoxesFirst, TrianglesOnly };

template <Parts kParts>
inline void set_up(FloatRay& r, const Ray& ray, double scene_scale) {
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
    if constexpr (kParts == Parts::Both) {
        const std::array<double, 3> inv = set_up_boxes(r, d, scaled, m);
        set_up_triangles(r, {ax, ay, az}, scaled, m, [&](int axis, const std::array<double, 3>&) {
            return inv[static_cast<std::size_t>(axis)];
        });
    } else if constexpr (kParts == Parts::BoxesFirst) {
        set_up_boxes(r, d, scaled, m);
        r.size = m;
        r.shrink = shrink;
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
        set_up_edge_margins(r, m);
    }
}

}  // namespace float_ray_detail

inline FloatRay::FloatRay(const Ray& ray, double scene_scale) {
    float_ray_detail::set_up<float_ray_detail::Parts::Both>(*this, ray, scene_scale);
}

inline FloatRay::FloatRay(const Ray& ray, double scene_scale, BoxesFirst) {
    float_ray_detail::set_up<float_ray_detail::Parts::BoxesFirst>(*this, ray, scene_scale);
}

inline void FloatRay::set_up_triangles(const Ray& ray) {
    const Vec3& d = ray.direction;
    // The same values as the full set-up's: d times the same power of two, and its reciprocal on
    // kz by the same division (unclamped there too: its magnitude is in [1, 2)).
    float_ray_detail::set_up_triangles(*this, {std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)},
                                       d * shrink, size,
                                       [](int axis, const std::array<double, 3>& along) {
                                           return 1.0 / along[static_cast<std::size_t>(axis)];
                                       });
}

}  // namespace rt
