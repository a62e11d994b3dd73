// The chi-square stop rule of adaptive supersampling (manual Appendix -X): keep sampling until
// the variance of the samples is, with enough confidence, below a bound.
#pragma once

#include <cstdint>

#include "rt/core/rgb.h"

namespace rt {

/// The cumulative distribution function of chi-square with `degrees` degrees of freedom at x:
/// the regularised lower incomplete gamma function P(degrees/2, x/2).
double chi_square_cdf(double x, double degrees);

/// -Xp prob,var and -Xr prob,var. The samples are measured in display levels (an intensity of
/// 1 is 255; the -m multiplier is not applied), channel by channel; `variance` bounds the
/// variance of the *mean* of the samples, so the rule asks for an estimate good to about
/// sqrt(variance) display levels.
struct ChiSquareStop {
    double probability = 0.2;
    double variance = 0.2;

    /// True when, after `count` samples with the given sample variance (the largest channel's,
    /// in display levels squared), the chance that the true variance of the mean exceeds the
    /// bound is below `probability`: with s^2 the sample variance and k the count, the
    /// statistic (k-1) s^2 / (k var) is chi-square with k-1 degrees of freedom when the mean's
    /// variance is exactly var; a small value of its CDF says the variance is below.
    bool satisfied(std::uint32_t count, double sample_variance) const;
};

/// Welford's running mean and variance of RGB samples (intensities).
class RunningStatistics {
public:
    void add(const Rgb& sample);
    std::uint32_t count() const { return count_; }
    Rgb mean() const { return mean_; }
    /// The largest channel's unbiased sample variance, in display levels squared.
    double display_variance() const;

private:
    std::uint32_t count_ = 0;
    Rgb mean_;
    Rgb squares_;  ///< sums of squared deviations from the running mean
};

/// How many of `total` samples are always taken before the rule may stop: a quarter, at least
/// two (a variance needs two), at most all.
std::uint32_t minimum_samples(std::uint32_t total);

}  // namespace rt
