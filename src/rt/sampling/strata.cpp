#include "rt/sampling/strata.h"

#include <algorithm>
#include <bit>

namespace rt {

namespace {

// Interleaves the bits of i and j (Morton order) and reverses the result: consecutive indices
// then land in different halves, quarters, ... of the square, like a 2D van der Corput sequence.
std::uint64_t spread_key(std::uint32_t i, std::uint32_t j) {
    std::uint64_t morton = 0;
    for (int bit = 0; bit < 16; ++bit) {
        morton |= static_cast<std::uint64_t>((i >> bit) & 1U) << (2 * bit);
        morton |= static_cast<std::uint64_t>((j >> bit) & 1U) << (2 * bit + 1);
    }
    std::uint64_t reversed = 0;
    for (int bit = 0; bit < 32; ++bit) {
        reversed |= ((morton >> bit) & 1U) << (31 - bit);
    }
    return reversed;
}

}  // namespace

ProgressiveStrata::ProgressiveStrata(int nx, int ny)
    : nx_(std::max(1, nx)),
      ny_(std::max(1, ny)),
      nx_real_(nx_),
      ny_real_(ny_),
      inverse_nx_(1.0 / nx_real_),
      inverse_ny_(1.0 / ny_real_),
      powers_of_two_(std::has_single_bit(static_cast<unsigned>(nx_)) &&
                     std::has_single_bit(static_cast<unsigned>(ny_))) {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
    for (int j = 0; j < ny_; ++j) {
        for (int i = 0; i < nx_; ++i) {
            keyed.emplace_back(
                spread_key(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)),
                static_cast<std::uint32_t>(j * nx_ + i));
        }
    }
    std::sort(keyed.begin(), keyed.end());
    order_.reserve(keyed.size());
    for (const auto& entry : keyed) {
        const std::uint32_t stratum = entry.second;
        const std::uint32_t column = stratum % static_cast<std::uint32_t>(nx_);
        const std::uint32_t row = stratum / static_cast<std::uint32_t>(nx_);  // whole rows
        order_.push_back({static_cast<double>(column), static_cast<double>(row)});
    }
}

}  // namespace rt
