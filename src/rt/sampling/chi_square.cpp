#include "rt/sampling/chi_square.h"

#include <algorithm>
#include <cmath>

namespace rt {

namespace {

// lgamma_r rather than std::lgamma: glibc's lgamma also writes the global signgam, and the render
// threads call this at the same time (concurrency-mt-unsafe).
double log_gamma(double a) {
    int sign = 0;
    return ::lgamma_r(a, &sign);
}

constexpr double kDisplayLevels = 255.0;

// P(a, x) by its power series; converges quickly for x < a + 1.
double lower_gamma_series(double a, double x) {
    double term = 1.0 / a;
    double sum = term;
    for (int n = 1; n < 1000; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::fabs(term) < std::fabs(sum) * 1e-15) {
            break;
        }
    }
    return sum * std::exp(-x + a * std::log(x) - log_gamma(a));
}

// Q(a, x) = 1 - P(a, x) by Lentz's continued fraction; converges quickly for x >= a + 1.
double upper_gamma_fraction(double a, double x) {
    constexpr double kTiny = 1e-300;
    double b = x + 1.0 - a;
    double c = 1.0 / kTiny;
    double d = 1.0 / b;
    double h = d;
    for (int i = 1; i < 1000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        d = std::fabs(d) < kTiny ? kTiny : d;
        c = b + an / c;
        c = std::fabs(c) < kTiny ? kTiny : c;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < 1e-15) {
            break;
        }
    }
    return std::exp(-x + a * std::log(x) - log_gamma(a)) * h;
}

}  // namespace

double chi_square_cdf(double x, double degrees) {
    if (!(x > 0.0) || !(degrees > 0.0)) {
        return 0.0;
    }
    if (std::isinf(x)) {
        return 1.0;
    }
    const double a = degrees / 2.0;
    const double half = x / 2.0;
    return half < a + 1.0 ? lower_gamma_series(a, half) : 1.0 - upper_gamma_fraction(a, half);
}

bool ChiSquareStop::satisfied(std::uint32_t count, double sample_variance) const {
    if (count < 2) {
        return false;
    }
    const double k = count;
    const double statistic = (k - 1.0) * sample_variance / (k * variance);
    return chi_square_cdf(statistic, k - 1.0) < probability;
}

void RunningStatistics::add(const Rgb& sample) {
    ++count_;
    for (int c = 0; c < 3; ++c) {
        const double delta = sample[c] - mean_[c];
        mean_[c] += delta / count_;
        squares_[c] += delta * (sample[c] - mean_[c]);
    }
}

double RunningStatistics::display_variance() const {
    if (count_ < 2) {
        return 0.0;
    }
    return max_component(squares_) / (count_ - 1) * (kDisplayLevels * kDisplayLevels);
}

std::uint32_t minimum_samples(std::uint32_t total) {
    return std::min(total, std::max<std::uint32_t>(2, (total + 3) / 4));
}

}  // namespace rt
