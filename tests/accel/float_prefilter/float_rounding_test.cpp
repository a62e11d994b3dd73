// float_below and float_above against their definition: the largest float at or below x, and the
// smallest at or above, as std::nextafter steps from the nearest float. They choose their step
// without a branch, so every case of sign, zero, subnormal, overflow and NaN is checked.
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "rt/accel/float_prefilter/float_ray.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

float below_by_definition(double x) {
    const auto f = static_cast<float>(x);
    return static_cast<double>(f) > x ? std::nextafter(f, -HUGE_VALF) : f;
}

float above_by_definition(double x) {
    const auto f = static_cast<float>(x);
    return static_cast<double>(f) < x ? std::nextafter(f, HUGE_VALF) : f;
}

void expect_both_match(double x) {
    const float below = float_below(x);
    const float above = float_above(x);
    if (std::isnan(x)) {
        EXPECT_TRUE(std::isnan(below));
        EXPECT_TRUE(std::isnan(above));
        return;
    }
    // Bit for bit, so that -0 and +0 are told apart.
    EXPECT_EQ(std::bit_cast<std::uint32_t>(below),
              std::bit_cast<std::uint32_t>(below_by_definition(x)))
        << x;
    EXPECT_EQ(std::bit_cast<std::uint32_t>(above),
              std::bit_cast<std::uint32_t>(above_by_definition(x)))
        << x;
    EXPECT_LE(static_cast<double>(below), x);
    EXPECT_GE(static_cast<double>(above), x);
}

TEST(FloatRounding, EdgeCases) {
    const double tiny = std::numeric_limits<float>::denorm_min();
    const double largest = std::numeric_limits<float>::max();
    const std::vector<double> cases = {0.0,
                                       -0.0,
                                       tiny,
                                       -tiny,
                                       tiny / 3,
                                       -tiny / 3,
                                       tiny * 1.5,
                                       -tiny * 1.5,
                                       std::numeric_limits<float>::min(),
                                       -static_cast<double>(std::numeric_limits<float>::min()),
                                       largest,
                                       -largest,
                                       largest * 1.0000001,
                                       -largest * 1.0000001,
                                       largest * 4,
                                       -largest * 4,
                                       std::numeric_limits<double>::max(),
                                       -std::numeric_limits<double>::max(),
                                       HUGE_VAL,
                                       -HUGE_VAL,
                                       std::numeric_limits<double>::quiet_NaN(),
                                       1.0,
                                       -1.0,
                                       0.1,
                                       -0.1,
                                       1e-300,
                                       -1e-300,
                                       3.0000001,
                                       -3.0000001};
    for (const double x : cases) {
        expect_both_match(x);
    }
}

TEST(FloatRounding, RandomDoublesOfEveryMagnitude) {
    std::mt19937_64 random(12345);
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-160, 140);
    for (int i = 0; i < 200000; ++i) {
        expect_both_match(std::ldexp(mantissa(random), exponent(random)));
    }
}

}  // namespace
}  // namespace rt
