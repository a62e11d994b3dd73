// edge_sign and exact_edge_sign against exact integer arithmetic: on integer-valued inputs below
// 2^53 the products fit in 128 bits, so __int128 gives the true sign to compare with. Inputs are
// chosen nearly collinear, where the quick floating-point evaluation cannot decide.
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "rt/geometry/exact_edge_sign.h"
#include "rt/geometry/ray_polygon.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// 128-bit integers hold every product of two integers below 2^63 exactly: the reference.
__extension__ typedef __int128 Int128;  // NOLINT(modernize-use-using): __extension__ needs typedef

struct EdgeInput {
    std::int64_t xa, ya, xb, yb;
};

int true_sign(const EdgeInput& in) {
    const Int128 e = static_cast<Int128>(in.xa) * in.yb - static_cast<Int128>(in.ya) * in.xb;
    return (e > 0) - (e < 0);
}

int sign_of(const EdgeInput& in, int scale_power = 0) {
    return edge_sign(std::ldexp(static_cast<double>(in.xa), scale_power),
                     std::ldexp(static_cast<double>(in.ya), scale_power),
                     std::ldexp(static_cast<double>(in.xb), scale_power),
                     std::ldexp(static_cast<double>(in.yb), scale_power));
}

// b = k a + (small offset): collinear up to a few units in 2^50, so the two products agree in
// their first ~50 bits and the double difference is mostly rounding error.
EdgeInput nearly_collinear(std::mt19937_64& random) {
    std::uniform_int_distribution<std::int64_t> base(-(std::int64_t{1} << 25),
                                                     std::int64_t{1} << 25);
    std::uniform_int_distribution<std::int64_t> factor(-(std::int64_t{1} << 26),
                                                       std::int64_t{1} << 26);
    std::uniform_int_distribution<std::int64_t> offset(-2, 2);
    const std::int64_t xa = base(random);
    const std::int64_t ya = base(random);
    const std::int64_t k = factor(random);
    return {xa, ya, k * xa + offset(random), k * ya + offset(random)};
}

// Values near 2^52 whose products differ in the last few of their 105 bits.
EdgeInput wide_nearly_collinear(std::mt19937_64& random) {
    std::uniform_int_distribution<std::int64_t> big(std::int64_t{1} << 51, std::int64_t{1} << 52);
    std::uniform_int_distribution<std::int64_t> offset(-1, 1);
    const std::int64_t xa = big(random);
    const std::int64_t ya = xa + offset(random);
    const std::int64_t xb = big(random);
    return {xa, ya, xb, xb + offset(random)};
}

TEST(EdgeSign, SimpleCases) {
    EXPECT_EQ(edge_sign(1, 0, 0, 1), 1);
    EXPECT_EQ(edge_sign(0, 1, 1, 0), -1);
    EXPECT_EQ(edge_sign(1, 1, 2, 2), 0);
    EXPECT_EQ(edge_sign(0, 0, 0, 0), 0);
    EXPECT_EQ(edge_sign(-3, 2, 5, 7), -1);  // -21 - 10
}

TEST(EdgeSign, MatchesIntegerArithmeticOnNearlyCollinearInputs) {
    std::mt19937_64 random(1);
    int undecidable_by_doubles = 0;
    for (int i = 0; i < 20000; ++i) {
        const EdgeInput in = i % 2 == 0 ? nearly_collinear(random) : wide_nearly_collinear(random);
        const int expected = true_sign(in);
        ASSERT_EQ(sign_of(in), expected) << in.xa << " " << in.ya << " " << in.xb << " " << in.yb;
        const double naive = static_cast<double>(in.xa) * static_cast<double>(in.yb) -
                             static_cast<double>(in.ya) * static_cast<double>(in.xb);
        undecidable_by_doubles += ((naive > 0) - (naive < 0)) != expected ? 1 : 0;
    }
    // The inputs must really be hard: plain doubles get many of them wrong.
    EXPECT_GT(undecidable_by_doubles, 1000);
}

TEST(EdgeSign, ExactZeroForExactlyCollinearInputs) {
    std::mt19937_64 random(2);
    std::uniform_int_distribution<std::int64_t> base(-(std::int64_t{1} << 26),
                                                     std::int64_t{1} << 26);
    for (int i = 0; i < 5000; ++i) {
        const std::int64_t xa = base(random);
        const std::int64_t ya = base(random);
        const std::int64_t k = base(random);
        EXPECT_EQ(sign_of({xa, ya, k * xa, k * ya}), 0);
    }
}

TEST(EdgeSign, IsAntisymmetricForEveryInput) {
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> any(-1.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        const EdgeInput in = nearly_collinear(random);
        const double xa = static_cast<double>(in.xa) * any(random);
        const double ya = static_cast<double>(in.ya) * any(random);
        const double xb = static_cast<double>(in.xb);
        const double yb = static_cast<double>(in.yb);
        ASSERT_EQ(edge_sign(xb, yb, xa, ya), -edge_sign(xa, ya, xb, yb));
        ASSERT_EQ(exact_edge_sign(xb, yb, xa, ya), -exact_edge_sign(xa, ya, xb, yb));
    }
}

TEST(EdgeSign, AgreesWithTheQuickEvaluationWhereThatIsSafe) {
    std::mt19937_64 random(4);
    std::uniform_real_distribution<double> any(-100.0, 100.0);
    for (int i = 0; i < 20000; ++i) {
        const double xa = any(random), ya = any(random), xb = any(random), yb = any(random);
        const double e = xa * yb - ya * xb;
        if (std::fabs(e) > 1e-9) {
            ASSERT_EQ(edge_sign(xa, ya, xb, yb), e > 0 ? 1 : -1);
            ASSERT_EQ(exact_edge_sign(xa, ya, xb, yb), e > 0 ? 1 : -1);
        }
    }
}

// A common power-of-two scale does not change the sign; at 2^-1000 the products underflow and at
// 2^+950 they overflow, so both ends go through the exact path's own rescaling.
TEST(EdgeSign, ExactUnderUnderflowAndOverflow) {
    std::mt19937_64 random(5);
    for (int i = 0; i < 5000; ++i) {
        const EdgeInput in = i % 2 == 0 ? nearly_collinear(random) : wide_nearly_collinear(random);
        const int expected = true_sign(in);
        ASSERT_EQ(sign_of(in, -1000), expected);
        ASSERT_EQ(sign_of(in, 950), expected);
        ASSERT_EQ(sign_of(in, -30), expected);
    }
}

TEST(EdgeSign, ExactOnFractionalInputsOfMixedMagnitude) {
    // Dyadic fractions m * 2^e: scaled by 2^16 they are the integers true_sign() checks.
    std::mt19937_64 random(6);
    std::uniform_int_distribution<std::int64_t> mantissa(-(std::int64_t{1} << 28),
                                                         std::int64_t{1} << 28);
    std::uniform_int_distribution<int> exponent(-16, 16);
    for (int i = 0; i < 20000; ++i) {
        std::int64_t v[4];
        for (std::int64_t& x : v) {
            x = mantissa(random) << (exponent(random) + 16);
        }
        // Nearly collinear half the time: b's y from a's slope, rounded toward zero.
        if (i % 2 == 0 && v[0] != 0) {
            const Int128 on_line = static_cast<Int128>(v[1]) * v[2] / v[0];
            if (on_line > -(Int128{1} << 53) && on_line < (Int128{1} << 53)) {
                v[3] = static_cast<std::int64_t>(on_line);
            }
        }
        const EdgeInput in{v[0], v[1], v[2], v[3]};
        ASSERT_EQ(sign_of(in, -16), true_sign(in));
    }
}

TEST(EdgeSign, NotANumberGivesZero) {
    EXPECT_EQ(edge_sign(kNaN, 1, 1, 1), 0);
    EXPECT_EQ(edge_sign(1, kNaN, 1, 1), 0);
    EXPECT_EQ(edge_sign(1, 1, kNaN, 1), 0);
    EXPECT_EQ(edge_sign(1, 1, 1, kNaN), 0);
    EXPECT_EQ(exact_edge_sign(kNaN, kNaN, kNaN, kNaN), 0);
}

TEST(EdgeSign, InfinitiesAreAntisymmetric) {
    const double values[] = {kInf, -kInf, 1.0, -1.0, 0.0, 1e308};
    for (const double xa : values) {
        for (const double ya : values) {
            for (const double xb : values) {
                for (const double yb : values) {
                    ASSERT_EQ(edge_sign(xb, yb, xa, ya), -edge_sign(xa, ya, xb, yb));
                }
            }
        }
    }
}

TEST(EdgeSign, SignedZerosAndSubnormals) {
    const double tiny = std::numeric_limits<double>::denorm_min();
    EXPECT_EQ(edge_sign(-0.0, 0.0, 0.0, -0.0), 0);
    EXPECT_EQ(edge_sign(tiny, 0.0, 0.0, tiny), 1);  // the product underflows to 0 in doubles
    EXPECT_EQ(edge_sign(0.0, tiny, tiny, 0.0), -1);
    EXPECT_EQ(edge_sign(1.0, 1.0, 1.0, std::nextafter(1.0, 2.0)), 1);
    EXPECT_EQ(edge_sign(1.0, 1.0, 1.0, std::nextafter(1.0, 0.0)), -1);
}

}  // namespace
}  // namespace rt
