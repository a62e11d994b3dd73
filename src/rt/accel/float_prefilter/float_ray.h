// A ray prepared for the float pre-filters, with the error bounds that make them conservative: a
// box (the BVH's nodes) or a triangle (the BVH's packets, the voxel methods' triangle look) is
// rejected only when the exact test (intersect_polygon, in double on the untransformed ray) could
// not hit anything in it. The bounds are argued in float_ray.cpp.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "rt/core/ray.h"

namespace rt {

/// t in the float tests is t * scale_t (scale_t a power of two, making the largest direction
/// component lie in [1, 2)).
struct FloatRay {
    /// False when the float tests cannot be trusted for this ray (scene or origin beyond
    /// 2^+-40 in size): the caller then tests every polygon exactly.
    bool usable = false;
    double scale_t = 1.0;

    // Box tests (left at 0 when set up TrianglesOnly); the triangle pre-filter reads origin.
    float origin[3] = {};
    float inverse[3] = {};      ///< 1 / scaled direction, clamped to +-2^60 (never 0)
    float slab_margin[3] = {};  ///< added to each axis's slab interval
    /// Bit k set when direction component k is negative (so is inverse[k]): taken from the
    /// direction, not the inverse, so that the box test's choice of planes need not wait for
    /// the division (box_test.h).
    std::uint32_t negative = 0;

    // Triangle pre-filter, in the ray's sheared 2D space (as RaySpace, in float).
    int kx = 0;
    int ky = 1;
    int kz = 2;
    float shear_x = 0.0f;
    float shear_y = 0.0f;
    float edge_margin_linear = 0.0f;    ///< times the triangle's 2D size
    float edge_margin_constant = 0.0f;  ///< plus this

    // Kept by a BoxesFirst set-up for set_up_triangles().
    double shrink = 1.0;  ///< 1 / scale_t, a power of two
    double size = 0.0;    ///< the scene's scale plus the origin's largest |coordinate|

    FloatRay(const Ray& ray, double scene_scale);
    /// Asks for only the triangle pre-filter's values (and origin); the box tests' stay 0. The
    /// voxel methods test boxes with their own LineProbe: setting up the box tests' values too
    /// cost them two divisions and some thirty other instructions a ray.
    struct TrianglesOnly {};
    FloatRay(const Ray& ray, double scene_scale, TrianglesOnly);
    /// Sets up only the box tests' values (and the origin): the triangle pre-filter's wait for
    /// set_up_triangles(), which the BVH's single-ray walk calls at its first leaf, as most of a
    /// mesh's camera rays reach none (docs/accelerators.md, "Set-up deferred to the first leaf").
    struct BoxesFirst {};
    FloatRay(const Ray& ray, double scene_scale, BoxesFirst);
    /// The triangle pre-filter's values of a usable FloatRay set up BoxesFirst from `ray`: bit
    /// for bit those of the full set-up.
    void set_up_triangles(const Ray& ray);
    /// Unusable until its fields are filled (a packet's lane, bvh/packet_setup.h).
    FloatRay() = default;

    /// t as the float tests see it, rounded towards -inf or +inf (so comparisons stay safe).
    /// Inline: the traversal calls them after every leaf.
    float scaled_down(double t) const;
    float scaled_up(double t) const;
};

/// x as a float rounded towards -inf (float_below) or +inf (float_above); NaN stays NaN.
///
/// Whether rounding to nearest went the wrong way is a coin toss, and a branch on it mispredicted
/// half the time (a fifth of the BVH's reference making). So the step is chosen without one: one
/// unit towards -inf is bits + 1 for a negative float (its magnitude grows) and bits - 1 for a
/// positive one, whose sign bit gives the step. The cases next_down (core/next_up.h) treats apart
/// never need a step the other way: +0 is never above x (x would have rounded to -0 or below), and
/// +inf steps to the largest float as bits - 1 does. The same, mirrored, for float_above.
inline float float_below(double x) {
    const auto f = static_cast<float>(x);
    const auto bits = std::bit_cast<std::uint32_t>(f);
    const std::uint32_t stepped = bits + ((bits >> 31) << 1) - 1u;
    return std::bit_cast<float>(static_cast<double>(f) > x ? stepped : bits);
}

inline float float_above(double x) {
    const auto f = static_cast<float>(x);
    const auto bits = std::bit_cast<std::uint32_t>(f);
    const std::uint32_t stepped = bits + 1u - ((bits >> 31) << 1);
    return std::bit_cast<float>(static_cast<double>(f) < x ? stepped : bits);
}

inline float FloatRay::scaled_down(double t) const {
    return float_below(t * scale_t);
}

inline float FloatRay::scaled_up(double t) const {
    return float_above(t * scale_t);
}

/// The relative slack of every float bound (2^-20, sixteen times float's rounding unit).
constexpr float kRelativeSlack = 0x1p-20f;

}  // namespace rt

#include "rt/accel/float_prefilter/float_ray_inl.h"  // IWYU pragma: export
