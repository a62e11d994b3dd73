// FloatRay's vectorised set-up must give exactly the portable one's values: the filters' error
// bounds are argued for those (float_ray.cpp), and the BVH's packet set-up repeats them.
#include "rt/accel/float_prefilter/float_ray.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include <gtest/gtest.h>

namespace rt {
namespace {

void expect_same(const FloatRay& a, const FloatRay& b, const Ray& ray) {
    ASSERT_EQ(a.usable, b.usable);
    if (!a.usable) {
        return;
    }
    EXPECT_EQ(a.scale_t, b.scale_t);
    for (int k = 0; k < 3; ++k) {
        // Bits, so that a sign of zero or a NaN would show.
        EXPECT_EQ(std::bit_cast<std::uint32_t>(a.origin[k]),
                  std::bit_cast<std::uint32_t>(b.origin[k]));
        EXPECT_EQ(std::bit_cast<std::uint32_t>(a.inverse[k]),
                  std::bit_cast<std::uint32_t>(b.inverse[k]))
            << "axis " << k << " direction " << ray.direction.x << " " << ray.direction.y << " "
            << ray.direction.z;
        EXPECT_EQ(std::bit_cast<std::uint32_t>(a.slab_margin[k]),
                  std::bit_cast<std::uint32_t>(b.slab_margin[k]));
    }
    EXPECT_EQ(a.kx, b.kx);
    EXPECT_EQ(a.ky, b.ky);
    EXPECT_EQ(a.kz, b.kz);
    EXPECT_EQ(std::bit_cast<std::uint32_t>(a.shear_x), std::bit_cast<std::uint32_t>(b.shear_x));
    EXPECT_EQ(std::bit_cast<std::uint32_t>(a.shear_y), std::bit_cast<std::uint32_t>(b.shear_y));
    EXPECT_EQ(a.edge_margin_linear, b.edge_margin_linear);
    EXPECT_EQ(a.edge_margin_constant, b.edge_margin_constant);
}

TEST(FloatRay, SetUpEqualsThePortableOne) {
    std::mt19937_64 random(23);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-70, 70);
    std::uniform_int_distribution<int> pick(0, 9);
    const double specials[] = {0.0,
                               -0.0,
                               std::numeric_limits<double>::denorm_min(),
                               1e-300,
                               -0x1p-61,
                               0x1p-60,
                               std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::quiet_NaN(),
                               1e300,
                               1.0};
    int usable = 0;
    for (int round = 0; round < 20000; ++round) {
        const double scale = std::ldexp(1.0, exponent(random));
        Ray ray{Vec3{unit(random), unit(random), unit(random)} * std::ldexp(1.0, exponent(random)),
                Vec3{unit(random), unit(random), unit(random)} * scale};
        // Now and then one component special: zero (clamped inverses), tiny, huge, not finite;
        // equal magnitudes (ties in the largest axis).
        const int which = pick(random);
        if (round % 3 == 0 && which < 3) {
            ray.direction[which] = specials[pick(random)];
        }
        if (round % 5 == 0) {
            ray.direction.y = (which & 1) != 0 ? ray.direction.x : -ray.direction.z;
        }
        if (round % 11 == 0) {
            ray.origin[which % 3] = specials[pick(random)];
        }
        const double scene_scale = std::ldexp(1.0, exponent(random) / 2);
        const FloatRay vectorised(ray, scene_scale);
        const FloatRay portable = FloatRay::portable(ray, scene_scale);
        expect_same(vectorised, portable, ray);
        usable += portable.usable ? 1 : 0;
        if (HasFailure()) {
            return;
        }
    }
    EXPECT_GT(usable, 10000);
}

}  // namespace
}  // namespace rt
