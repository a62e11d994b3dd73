#include "error_curve.h"

#include <algorithm>
#include <cmath>

namespace rt::bench {

namespace {

// y at x on the line through (x0, y0) and (x1, y1), all in logarithms.
double log_log(double x, double x0, double y0, double x1, double y1) {
    if (x0 == x1) {
        return y0;
    }
    const double t = (std::log(x) - std::log(x0)) / (std::log(x1) - std::log(x0));
    return std::exp(std::log(y0) + t * (std::log(y1) - std::log(y0)));
}

}  // namespace

std::vector<CurvePoint> lower_envelope(std::vector<CurvePoint> points) {
    std::sort(points.begin(), points.end(),
              [](const CurvePoint& a, const CurvePoint& b) { return a.cost < b.cost; });
    std::vector<CurvePoint> out;
    for (const CurvePoint& p : points) {
        if (p.error > 0.0 && (out.empty() || p.error < out.back().error)) {
            out.push_back(p);
        }
    }
    return out;
}

std::optional<double> error_at_cost(const std::vector<CurvePoint>& envelope, double cost) {
    for (std::size_t i = 0; i + 1 < envelope.size(); ++i) {
        const CurvePoint& a = envelope[i];
        const CurvePoint& b = envelope[i + 1];
        if (a.cost <= cost && cost <= b.cost) {
            return log_log(cost, a.cost, a.error, b.cost, b.error);
        }
    }
    return std::nullopt;
}

std::optional<double> cost_for_error(const std::vector<CurvePoint>& envelope, double error) {
    for (std::size_t i = 0; i + 1 < envelope.size(); ++i) {
        const CurvePoint& a = envelope[i];
        const CurvePoint& b = envelope[i + 1];
        if (b.error <= error && error <= a.error) {
            return log_log(error, a.error, a.cost, b.error, b.cost);
        }
    }
    return std::nullopt;
}

}  // namespace rt::bench
