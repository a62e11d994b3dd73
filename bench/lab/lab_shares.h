// Each method's rates as shares of Embree's, taken within one round (the same rays, measured
// minutes apart at most), then summed up over the rounds as a median and a range: issue 15's
// rule that a figure counts only from a run in which Embree ran too, with its spread.
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "lab_measure.h"

namespace rt::lab {

/// The median of some values and the lowest and highest of them; empty when there were none.
struct Spread {
    double median = 0.0;
    double lowest = 0.0;
    double highest = 0.0;
    std::size_t count = 0;
};

/// The median (the mean of the middle two for an even count), lowest and highest of `values`,
/// leaving out values that are not finite (a rate of 0 against 0).
Spread spread_of(std::vector<double> values);

/// One method's shares of Embree's figures on one mesh, over the rounds.
struct Shares {
    std::string mesh;
    std::uint64_t triangles = 0;
    std::string accel;
    Spread build;              ///< build time over Embree's (below 1: faster)
    Spread primary;            ///< camera rays, one thread, over Embree's rtcIntersect1
    Spread random;             ///< random rays, one thread, over Embree's rtcIntersect1
    Spread primary_packets;    ///< camera rays in packets over Embree's rtcIntersect1
    Spread primary_packets_8;  ///< camera rays in packets over Embree's rtcIntersect8
    Spread random_packets_8;   ///< random rays in packets over Embree's rtcIntersect8
};

/// Every method but Embree on every mesh where Embree was measured in the same round, in the
/// order the methods were first measured. Empty when Embree never ran.
std::vector<Shares> shares_of_embree(const std::vector<Measurement>& results);

/// The measurements with every figure the median over the rounds of the same mesh and method
/// (for the plots, which draw one point each).
std::vector<Measurement> median_over_rounds(const std::vector<Measurement>& results);

/// The shares as a table: "0.91 (0.85-0.95)" a cell, or the one figure for one round.
void print_shares(std::ostream& out, const std::vector<Shares>& shares, unsigned rounds);

}  // namespace rt::lab
