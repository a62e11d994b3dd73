// Cone and hemisphere directions against the cos^n law written out here: the mean and second
// moment of the cosine to the axis, with tolerances from the law's own spread (so they shrink
// with the cone), and a chi-square test of the joint histogram of cosine and azimuth, as pbrt-v4
// and Mitsuba test their samplers.
//
// The law. Over a cone of half-angle theta around the axis, density proportional to cos^n per
// unit solid angle. With c = cos(angle) and phi the azimuth, d(omega) = dc dphi, so c has
// density (n+1) c^n / (1 - c0^(n+1)) on [c0, 1] (c0 = cos theta), phi is uniform and the two
// are independent. Hence
//     F(c)   = (c^(n+1) - c0^(n+1)) / (1 - c0^(n+1))                     (the CDF of c)
//     E[c^k] = (n+1)/(n+k+1) * (1 - c0^(n+k+1)) / (1 - c0^(n+1)).
// The cosine-weighted hemisphere is n = 1, theta = 90 degrees.
#include "rt/sampling/directions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "rt/sampling/chi_square.h"
#include "rt/sampling/sample_stream.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

// The law of one cone, computed without cancellation for narrow cones: 1 - c0^a is
// -expm1(a log c0), and log c0 = log1p(-2 sin^2(theta/2)).
class CosPowerLaw {
public:
    CosPowerLaw(double half_angle, double exponent)
        : n_(exponent),
          c0_(std::cos(half_angle)),
          log_c0_(std::log1p(-2.0 * std::pow(std::sin(half_angle / 2), 2))) {}

    double edge() const { return c0_; }
    /// 1 - c0^a.
    double one_minus_edge_power(double a) const { return -std::expm1(a * log_c0_); }
    double cdf(double c) const {
        if (c <= c0_) {
            return 0.0;
        }
        // c^(n+1) - c0^(n+1) = (1 - c0^(n+1)) - (1 - c^(n+1)).
        const double below = -std::expm1((n_ + 1) * std::log(c));
        return 1.0 - below / one_minus_edge_power(n_ + 1);
    }
    /// The c at which cdf(c) = p, to choose bins of equal probability.
    double inverse_cdf(double p) const {
        return std::exp(std::log1p(-(1.0 - p) * one_minus_edge_power(n_ + 1)) / (n_ + 1));
    }
    double moment(int k) const {
        return (n_ + 1) / (n_ + k + 1) * one_minus_edge_power(n_ + k + 1) /
               one_minus_edge_power(n_ + 1);
    }

private:
    double n_;
    double c0_;
    double log_c0_;
};

struct ConeCase {
    std::string name;
    CosPowerCone cone;
};

const std::vector<ConeCase>& cone_cases() {
    static const std::vector<ConeCase> cases{
        {"60 degrees, n 4", {60 * kDegree, 4.0}},
        {"4 degrees, n 1", {4 * kDegree, 1.0}},
        {"half a degree, n 0", {0.5 * kDegree, 0.0}},
        {"hemisphere, uniform", {90 * kDegree, 0.0}},
        {"hemisphere, n 1", {90 * kDegree, 1.0}},
        {"30 degrees, n 50", {30 * kDegree, 50.0}},
        {"10 degrees, n 1000", {10 * kDegree, 1000.0}},
        {"45 degrees, n 0.5", {45 * kDegree, 0.5}},
    };
    return cases;
}

// Directions around an axis off every coordinate axis, with their cosine and azimuth measured in
// a basis built here (not the sampler's).
struct Sampled {
    std::vector<double> cosine;
    std::vector<double> azimuth;  ///< in [0, 1): turns
};

const Vec3 kAxis = normalize(Vec3{0.3, -0.5, 0.8});

template <class Sample>
Sampled sample(int count, std::uint64_t seed, Sample sample_direction) {
    const Vec3 t1 = normalize(cross(kAxis, Vec3{1, 0, 0}));
    const Vec3 t2 = cross(kAxis, t1);
    SampleStream stream(seed, 0, 0, 0);
    Sampled out;
    for (int i = 0; i < count; ++i) {
        const double u1 = stream.uniform();
        const double u2 = stream.uniform();
        const Vec3 d = sample_direction(u1, u2);
        EXPECT_NEAR(length(d), 1.0, 1e-12);
        out.cosine.push_back(dot(d, kAxis));
        const double turns = std::atan2(dot(d, t2), dot(d, t1)) / (2 * kPi);
        out.azimuth.push_back(turns < 0 ? turns + 1 : turns);
    }
    return out;
}

// Five standard errors: a correct sampler misses by more about once in 1.7 million.
constexpr double kStandardErrors = 5.0;
constexpr int kSamples = 100000;

// The sample mean of c^k against E[c^k], within five standard errors of the law's own variance
// of c^k, which shrinks with the cone: for 4 degrees and n = 1 it is about 1.6e-6, while every
// mean lies in [cos 4deg, 1], 2.4e-3 wide.
void expect_moment(const Sampled& s, const CosPowerLaw& law, int k) {
    double sum = 0.0;
    for (const double c : s.cosine) {
        sum += std::pow(c, k);
    }
    const double mean = sum / static_cast<double>(s.cosine.size());
    const double variance = std::max(law.moment(2 * k) - law.moment(k) * law.moment(k), 0.0);
    const double tolerance =
        kStandardErrors * std::sqrt(variance / static_cast<double>(s.cosine.size())) + 1e-14;
    EXPECT_LT(tolerance, 0.05 * (1 - law.edge())) << "a tolerance this wide proves nothing";
    EXPECT_NEAR(mean, law.moment(k), tolerance) << "moment " << k;
}

// Pearson's statistic over a joint histogram: cosine in kCosineBins bins of equal probability
// under the law, azimuth in kAzimuthBins equal turns; expected counts from the law's CDF.
constexpr int kCosineBins = 10;
constexpr int kAzimuthBins = 8;
// Significance: the test of every sampler below together fails a correct set of samplers with
// probability 1% (Sidak's correction over the number of tests).
constexpr double kSignificance = 0.01;
constexpr int kChiSquareTests = 9;

void expect_chi_square_fit(const Sampled& s, const CosPowerLaw& law) {
    std::vector<double> edges;
    for (int b = 0; b <= kCosineBins; ++b) {
        edges.push_back(b == 0             ? law.edge()
                        : b == kCosineBins ? 1.0
                                           : law.inverse_cdf(double(b) / kCosineBins));
    }
    std::vector<double> observed(kCosineBins * kAzimuthBins, 0.0);
    for (std::size_t i = 0; i < s.cosine.size(); ++i) {
        const auto at = std::upper_bound(edges.begin() + 1, edges.end() - 1, s.cosine[i]);
        const int b = static_cast<int>(at - (edges.begin() + 1));
        const int a = std::min(static_cast<int>(s.azimuth[i] * kAzimuthBins), kAzimuthBins - 1);
        observed[b * kAzimuthBins + a] += 1;
    }
    const double n = static_cast<double>(s.cosine.size());
    double statistic = 0.0;
    for (int b = 0; b < kCosineBins; ++b) {
        const double p = law.cdf(edges[b + 1]) - law.cdf(edges[b]);
        ASSERT_GT(p * n / kAzimuthBins, 5.0) << "cells too small for the chi-square law";
        for (int a = 0; a < kAzimuthBins; ++a) {
            const double expected = p * n / kAzimuthBins;
            const double miss = observed[b * kAzimuthBins + a] - expected;
            statistic += miss * miss / expected;
        }
    }
    const double p_value = 1.0 - chi_square_cdf(statistic, kCosineBins * kAzimuthBins - 1);
    const double per_test = 1.0 - std::pow(1.0 - kSignificance, 1.0 / kChiSquareTests);
    EXPECT_GT(p_value, per_test) << "chi-square " << statistic << " on "
                                 << kCosineBins * kAzimuthBins - 1 << " degrees of freedom";
}

TEST(Directions, TheLawsClosedFormsAgreeWithEachOther) {
    // Uniform over the hemisphere: mean 1/2, second moment 1/3; cosine-weighted 2/3 and 1/2.
    EXPECT_NEAR(CosPowerLaw(kPi / 2, 0).moment(1), 0.5, 1e-15);
    EXPECT_NEAR(CosPowerLaw(kPi / 2, 0).moment(2), 1.0 / 3.0, 1e-15);
    EXPECT_NEAR(CosPowerLaw(kPi / 2, 1).moment(1), 2.0 / 3.0, 1e-15);
    EXPECT_NEAR(CosPowerLaw(kPi / 2, 1).moment(2), 0.5, 1e-15);
    for (const ConeCase& c : cone_cases()) {
        const CosPowerLaw law(c.cone.half_angle, c.cone.exponent);
        EXPECT_NEAR(law.cdf(law.inverse_cdf(0.3)), 0.3, 1e-9) << c.name;
        // The mean from the CDF: E[c] = 1 - int_c0^1 F(c) dc, by Simpson's rule.
        constexpr int kIntervals = 2000;
        const double h = (1 - law.edge()) / kIntervals;
        double integral = law.cdf(law.edge()) + law.cdf(1.0);
        for (int i = 1; i < kIntervals; ++i) {
            integral += (i % 2 == 1 ? 4 : 2) * law.cdf(law.edge() + i * h);
        }
        integral *= h / 3;
        EXPECT_NEAR(1 - integral, law.moment(1), 1e-7 * (1 - law.edge())) << c.name;
        // The library's mean_cosine (used by tests only) is the same law.
        EXPECT_NEAR(mean_cosine(c.cone), law.moment(1), 1e-6 * (1 - law.edge())) << c.name;
    }
}

TEST(Directions, ConeSamplesFollowTheCosPowerLaw) {
    std::uint64_t seed = 10;  // a stream of its own for each cone, so the tests are independent
    for (const ConeCase& c : cone_cases()) {
        SCOPED_TRACE(c.name);
        const CosPowerLaw law(c.cone.half_angle, c.cone.exponent);
        const Sampled s = sample(kSamples, ++seed, [&](double u1, double u2) {
            return sample_cone(c.cone, kAxis, u1, u2);
        });
        const auto lowest = *std::min_element(s.cosine.begin(), s.cosine.end());
        EXPECT_GE(lowest, law.edge() - 1e-12);
        expect_moment(s, law, 1);
        expect_moment(s, law, 2);
        expect_chi_square_fit(s, law);
    }
}

TEST(Directions, CosineHemisphereIsTheCosPowerLawWithNOne) {
    const CosPowerLaw law(kPi / 2, 1.0);
    const Sampled s = sample(
        kSamples, 3, [](double u1, double u2) { return sample_cosine_hemisphere(kAxis, u1, u2); });
    EXPECT_GE(*std::min_element(s.cosine.begin(), s.cosine.end()), 0.0);
    expect_moment(s, law, 1);
    expect_moment(s, law, 2);
    expect_chi_square_fit(s, law);
}

// The renderer draws all the rays of a lobe from one sampler: a sampler used many times must give
// each draw exactly what a fresh one gives (no state carried from draw to draw), and so must one
// made from a shape worked out once for its material.
TEST(Directions, ReusedSamplersAndShapesGiveFreshSamplersDirections) {
    const Vec3 axis = normalize(Vec3{0.3, -0.8, 0.52});
    const CosPowerCone cone{20 * kDegree, 10.0};
    const ConeSampler cone_rays(cone, axis);
    const ConeShape shape(cone);  // one material's cone, worked out once for all its lobes
    const CosineHemisphereSampler hemisphere_rays(axis);
    SampleStream stream(7, 0, 0, 0);
    for (int k = 0; k < 1000; ++k) {
        const double u1 = k == 0 ? 1.0 : stream.uniform();  // u1 = 1: the rim probes'
        const double u2 = stream.uniform();
        const Vec3 reused = cone_rays(u1, u2);
        const Vec3 fresh = ConeSampler(cone, axis)(u1, u2);
        ASSERT_TRUE(reused.x == fresh.x && reused.y == fresh.y && reused.z == fresh.z) << k;
        const Vec3 shaped = ConeSampler(shape, axis)(u1, u2);
        ASSERT_TRUE(shaped.x == fresh.x && shaped.y == fresh.y && shaped.z == fresh.z) << k;
        const Vec3 reused_diffuse = hemisphere_rays(u1, u2);
        const Vec3 fresh_diffuse = CosineHemisphereSampler(axis)(u1, u2);
        ASSERT_TRUE(reused_diffuse.x == fresh_diffuse.x && reused_diffuse.y == fresh_diffuse.y &&
                    reused_diffuse.z == fresh_diffuse.z)
            << k;
        EXPECT_GE(dot(reused, axis), std::cos(cone.half_angle) - 1e-12);
    }
}

// The adaptive rule's rim probes take the rim from rim(): the same directions, bit for bit, as
// the sampler gives for u1 = 1 at the four quarters, for narrow, wide and flat cones and any axis.
TEST(Directions, RimIsTheSamplersOwnRim) {
    SampleStream stream(11, 0, 0, 0);
    for (int k = 0; k < 200; ++k) {
        const Vec3 axis = normalize(Vec3{stream.uniform() - 0.5, stream.uniform() - 0.5,
                                         k == 0 ? 0.0 : stream.uniform() - 0.5});
        const CosPowerCone cone{(k % 90) * kDegree, 0.5 * (k % 60)};
        const ConeSampler sampler(cone, axis);
        const std::array<Vec3, 4> rim = sampler.rim();
        for (int q = 0; q < 4; ++q) {
            const Vec3 expected = sampler(1.0, q / 4.0);
            const Vec3& got = rim[static_cast<std::size_t>(q)];
            ASSERT_TRUE(got.x == expected.x && got.y == expected.y && got.z == expected.z)
                << k << " " << q;
        }
    }
}

TEST(Directions, OrthonormalBasisIsOrthonormal) {
    for (const Vec3& n : {Vec3{0, 0, 1}, Vec3{0, 0, -1}, normalize(Vec3{1, 2, 3}),
                          normalize(Vec3{-1, 0.001, -0.2})}) {
        Vec3 t;
        Vec3 b;
        orthonormal_basis(n, t, b);
        EXPECT_NEAR(length(t), 1.0, 1e-12);
        EXPECT_NEAR(length(b), 1.0, 1e-12);
        EXPECT_NEAR(dot(t, n), 0.0, 1e-12);
        EXPECT_NEAR(dot(b, n), 0.0, 1e-12);
        EXPECT_NEAR(dot(t, b), 0.0, 1e-12);
    }
}

}  // namespace
}  // namespace rt
