// Error against cost: the points a family of sampling plans reaches, and what a cost buys or an
// error costs between them (interpolated on log-log axes, where such curves are near straight).
#pragma once

#include <optional>
#include <vector>

namespace rt::bench {

struct CurvePoint {
    double cost = 0.0;   ///< rays (or samples) spent
    double error = 0.0;  ///< RMS error, display levels
};

/// The points no cheaper point beats, by cost: each has a lower error than every cheaper one.
std::vector<CurvePoint> lower_envelope(std::vector<CurvePoint> points);

/// The error the envelope reaches at `cost`; none outside its range of costs.
std::optional<double> error_at_cost(const std::vector<CurvePoint>& envelope, double cost);

/// The cost at which the envelope reaches `error`; none outside its range of errors.
std::optional<double> cost_for_error(const std::vector<CurvePoint>& envelope, double error);

}  // namespace rt::bench
