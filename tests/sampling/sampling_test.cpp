// Counter-based random numbers, strata, and the chi-square rule (directions_test.cpp has the
// cone and hemisphere directions).
#include <array>
#include <cmath>
#include <set>

#include "rt/sampling/chi_square.h"
#include "rt/sampling/philox.h"
#include "rt/sampling/sample_stream.h"
#include "rt/sampling/strata.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(Philox, MatchesTheKnownAnswersOfItsAuthors) {
    // Random123's kat_vectors for philox4x32 with 10 rounds.
    EXPECT_EQ(philox4x32_10({0, 0, 0, 0}, {0, 0}),
              (PhiloxCounter{0x6627e8d5, 0xe169c58d, 0xbc57ac4c, 0x9b00dbd8}));
    EXPECT_EQ(
        philox4x32_10({0xffffffff, 0xffffffff, 0xffffffff, 0xffffffff}, {0xffffffff, 0xffffffff}),
        (PhiloxCounter{0x408f276d, 0x41c83b0e, 0xa20bc7c6, 0x6d5451fd}));
    EXPECT_EQ(
        philox4x32_10({0x243f6a88, 0x85a308d3, 0x13198a2e, 0x03707344}, {0xa4093822, 0x299f31d0}),
        (PhiloxCounter{0xd16cfe09, 0x94fdcceb, 0x5001e420, 0x24126ea1}));
}

TEST(SampleStream, IsAPureFunctionOfSeedPixelAndSample) {
    SampleStream a(7, 3, 4, 5);
    SampleStream b(7, 3, 4, 5);
    SampleStream other_seed(8, 3, 4, 5);
    SampleStream other_pixel(7, 4, 3, 5);
    for (int i = 0; i < 10; ++i) {
        const double value = a.uniform();
        EXPECT_EQ(value, b.uniform());
        EXPECT_NE(value, other_seed.uniform());
        EXPECT_NE(value, other_pixel.uniform());
    }
}

TEST(SampleStream, IsUniformOnTheUnitInterval) {
    SampleStream s(1, 0, 0, 0);
    constexpr int kCount = 100000;
    double sum = 0.0;
    double squares = 0.0;
    for (int i = 0; i < kCount; ++i) {
        const double u = s.uniform();
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        sum += u;
        squares += u * u;
    }
    EXPECT_NEAR(sum / kCount, 0.5, 0.005);
    EXPECT_NEAR(squares / kCount, 1.0 / 3.0, 0.005);
}

TEST(ProgressiveStrata, VisitsEveryStratumOnceAndSpreadsEveryPrefix) {
    const ProgressiveStrata strata(4, 4);
    ASSERT_EQ(strata.size(), 16U);
    std::set<std::pair<int, int>> seen;
    std::set<int> first_quadrants;
    for (std::uint32_t k = 0; k < strata.size(); ++k) {
        double x = 0.0;
        double y = 0.0;
        strata.point(k, 0.5, 0.5, x, y);
        seen.insert({static_cast<int>(x * 4), static_cast<int>(y * 4)});
        if (k < 4) {
            first_quadrants.insert(static_cast<int>(x * 2) + 2 * static_cast<int>(y * 2));
        }
    }
    EXPECT_EQ(seen.size(), 16U);
    EXPECT_EQ(first_quadrants.size(), 4U);  // the first four samples: one per quadrant
    const ProgressiveStrata odd(3, 2);
    EXPECT_EQ(odd.size(), 6U);
}

// Where n is a power of two, point() multiplies by 1 / n instead of dividing: the same bits,
// which keeps every picture as it was. Elsewhere it divides.
TEST(ProgressiveStrata, PointsAreTheQuotientsBitForBit) {
    const std::array<std::pair<int, int>, 5> sizes{{{4, 4}, {8, 2}, {1, 16}, {3, 3}, {5, 4}}};
    SampleStream stream(3, 1, 2, 0);
    for (const auto& [nx, ny] : sizes) {
        const ProgressiveStrata strata(nx, ny);
        for (int trial = 0; trial < 2000; ++trial) {
            const auto k = static_cast<std::uint32_t>(trial) % strata.size();
            // Jitters with every bit set as well as the stream's.
            const double u1 = trial == 0 ? std::nextafter(1.0, 0.0) : stream.uniform();
            const double u2 = trial == 1 ? std::nextafter(1.0, 0.0) : stream.uniform();
            double x = 0.0;
            double y = 0.0;
            strata.point(k, u1, u2, x, y);
            // The stratum's corner, from its point for a zero jitter.
            double i = 0.0;
            double j = 0.0;
            strata.point(k, 0.0, 0.0, i, j);
            ASSERT_EQ(x, (i * nx + u1) / nx) << nx << " x " << ny << ", trial " << trial;
            ASSERT_EQ(y, (j * ny + u2) / ny) << nx << " x " << ny << ", trial " << trial;
        }
    }
}

TEST(ChiSquare, CdfMatchesTables) {
    EXPECT_NEAR(chi_square_cdf(1.0, 1.0), 0.682689492137, 1e-9);
    EXPECT_NEAR(chi_square_cdf(2.0, 2.0), 1.0 - std::exp(-1.0), 1e-12);
    EXPECT_NEAR(chi_square_cdf(3.841458820694, 1.0), 0.95, 1e-9);
    EXPECT_NEAR(chi_square_cdf(18.307038053275, 10.0), 0.95, 1e-9);
    EXPECT_NEAR(chi_square_cdf(124.342113404, 100.0), 0.95, 1e-8);
    EXPECT_EQ(chi_square_cdf(0.0, 3.0), 0.0);
}

TEST(ChiSquare, StopsOnFlatSamplesAndNotOnNoisyOnes) {
    const ChiSquareStop rule{0.2, 0.2};
    EXPECT_FALSE(rule.satisfied(1, 0.0));
    EXPECT_TRUE(rule.satisfied(2, 0.0));
    EXPECT_TRUE(rule.satisfied(4, 0.01));
    // A pixel on an edge: half the samples black, half at 200 display levels.
    EXPECT_FALSE(rule.satisfied(16, 100.0 * 100.0));
    // The variance of the mean exactly at the bound: the CDF is near one half, never below 0.2.
    for (std::uint32_t k = 2; k < 200; ++k) {
        EXPECT_FALSE(rule.satisfied(k, 0.2 * k)) << k;
    }
}

TEST(ChiSquare, RunningStatisticsInDisplayLevels) {
    RunningStatistics s;
    s.add({0.0, 0.0, 0.0});
    s.add({1.0, 0.5, 0.0});
    EXPECT_EQ(s.count(), 2U);
    EXPECT_DOUBLE_EQ(s.mean().r, 0.5);
    EXPECT_NEAR(s.display_variance(), 0.5 * 255.0 * 255.0, 1e-6);
    EXPECT_EQ(minimum_samples(1), 1U);
    EXPECT_EQ(minimum_samples(4), 2U);
    EXPECT_EQ(minimum_samples(16), 4U);
    EXPECT_EQ(minimum_samples(64), 16U);
}

}  // namespace
}  // namespace rt
