// FloatRay picks its axes and reads components by arithmetic, not branches (float_ray.cpp): on
// every direction whose components are zeros of either sign, ties and ordinary values, its axes,
// sign bits, shears and box values must be what the plain rule gives.
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

#include "rt/accel/float_prefilter/float_ray.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

struct ExpectedAxes {
    int kx;
    int ky;
    int kz;
};

// The rule as it reads in words: the axis of the largest magnitude, the later one on a tie.
ExpectedAxes axes_by_rule(const Vec3& d) {
    const double ax = std::fabs(d.x);
    const double ay = std::fabs(d.y);
    const double az = std::fabs(d.z);
    int kz = 2;
    if (ax > ay) {
        kz = ax > az ? 0 : 2;
    } else {
        kz = ay > az ? 1 : 2;
    }
    return {(kz + 1) % 3, (kz + 2) % 3, kz};
}

TEST(FloatRayAxes, MatchTheRuleOnEveryMixOfZerosTiesAndSigns) {
    const std::array<double, 9> values{0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 3.0, -3.0, 1e-300};
    int checked = 0;
    for (const double x : values) {
        for (const double y : values) {
            for (const double z : values) {
                const Vec3 d{x, y, z};
                const FloatRay r(Ray{{1.0, 2.0, 3.0}, d}, 10.0);
                if (x == 0.0 && y == 0.0 && z == 0.0) {
                    EXPECT_FALSE(r.usable);
                    continue;
                }
                ASSERT_TRUE(r.usable) << x << " " << y << " " << z;
                ++checked;
                const ExpectedAxes e = axes_by_rule(d);
                EXPECT_EQ(r.kx, e.kx) << x << " " << y << " " << z;
                EXPECT_EQ(r.ky, e.ky) << x << " " << y << " " << z;
                EXPECT_EQ(r.kz, e.kz) << x << " " << y << " " << z;
                const std::array<double, 3> along{x / r.scale_t, y / r.scale_t, z / r.scale_t};
                for (int k = 0; k < 3; ++k) {
                    const bool negative = ((r.negative >> k) & 1U) != 0;
                    EXPECT_EQ(negative, std::signbit(along[k])) << k;
                    EXPECT_EQ(negative, std::signbit(r.inverse[k])) << k;  // box_test.h's planes
                }
                // scale_t is a power of two: the scaled components above are exact, and 1 / the
                // largest is the unclamped inverse the shears are taken with.
                const double inverse_kz = 1.0 / along[e.kz];
                EXPECT_EQ(r.shear_x, static_cast<float>(along[e.kx] * inverse_kz));
                EXPECT_EQ(r.shear_y, static_cast<float>(along[e.ky] * inverse_kz));
                EXPECT_EQ(r.inverse[e.kz], static_cast<float>(inverse_kz));
            }
        }
    }
    EXPECT_EQ(checked, 9 * 9 * 9 - 8);
}

// The box-less set-up (the voxel methods'), which keeps the rule as branches, picks the same
// axes and shears.
TEST(FloatRayAxes, TheTrianglesOnlySetUpAgrees) {
    const std::array<Vec3, 4> directions{Vec3{-0.0, 2.0, -2.0}, Vec3{3.0, -3.0, 1.0},
                                         Vec3{-1e-300, 0.0, 0.0}, Vec3{0.25, -0.5, 0.5}};
    for (const Vec3& d : directions) {
        const Ray ray{{-4.0, 0.5, 7.0}, d};
        const FloatRay full(ray, 10.0);
        const FloatRay triangles(ray, 10.0, FloatRay::TrianglesOnly{});
        ASSERT_TRUE(full.usable && triangles.usable);
        EXPECT_EQ(full.kx, triangles.kx);
        EXPECT_EQ(full.ky, triangles.ky);
        EXPECT_EQ(full.kz, triangles.kz);
        EXPECT_EQ(full.shear_x, triangles.shear_x);
        EXPECT_EQ(full.shear_y, triangles.shear_y);
    }
}

// Whether the set-up in two steps (the box values, then the triangle values) gives every field
// of the full one bit for bit; false for a ray neither can use.
bool staged_set_up_agrees(const Ray& ray) {
    const FloatRay full(ray, 10.0);
    FloatRay staged(ray, 10.0, FloatRay::BoxesFirst{});
    EXPECT_EQ(full.usable, staged.usable);
    if (!full.usable) {
        return false;
    }
    const auto bits = [](float f) { return std::bit_cast<std::uint32_t>(f); };
    EXPECT_EQ(full.scale_t, staged.scale_t);
    EXPECT_EQ(full.negative, staged.negative);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(bits(full.origin[k]), bits(staged.origin[k]));
        EXPECT_EQ(bits(full.inverse[k]), bits(staged.inverse[k]));
        EXPECT_EQ(full.slab_margin[k], staged.slab_margin[k]);
    }
    staged.set_up_triangles(ray);
    EXPECT_EQ(full.kx, staged.kx);
    EXPECT_EQ(full.ky, staged.ky);
    EXPECT_EQ(full.kz, staged.kz);
    EXPECT_EQ(bits(full.shear_x), bits(staged.shear_x));
    EXPECT_EQ(bits(full.shear_y), bits(staged.shear_y));
    EXPECT_EQ(full.edge_margin_linear, staged.edge_margin_linear);
    EXPECT_EQ(full.edge_margin_constant, staged.edge_margin_constant);
    return true;
}

// The BVH's single-ray set-up: the box values first, the triangle values at the first leaf. Both
// halves must be the full set-up's bit for bit, on every mix of zeros, ties, signs and sizes
// (subnormal and huge components among them).
TEST(FloatRayAxes, TheBoxesFirstSetUpThenItsTrianglesAgree) {
    const std::array<double, 8> values{0.0, -0.0, 1.0, -1.0, 3.0, -1e-300, 7.5e200, -3e-310};
    const std::array<Vec3, 3> origins{Vec3{-4.0, 0.5, 7.0}, Vec3{1e6, -2e5, 3.0}, Vec3{}};
    int checked = 0;
    for (const Vec3& origin : origins) {
        for (const double x : values) {
            for (const double y : values) {
                for (const double z : values) {
                    checked += staged_set_up_agrees(Ray{origin, {x, y, z}}) ? 1 : 0;
                }
            }
        }
    }
    // Every direction but the zero ones (two signs of zero, 2^3 of them) is usable from each
    // origin.
    EXPECT_EQ(checked, 3 * (8 * 8 * 8 - 8));
}

}  // namespace
}  // namespace rt
