#include "rt/sampling/strata.h"

#include <algorithm>

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
    : nx_(std::max(1, nx)), ny_(std::max(1, ny)), nx_real_(nx_), ny_real_(ny_) {
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
        order_.push_back({static_cast<double>(stratum % static_cast<std::uint32_t>(nx_)),
                          static_cast<double>(stratum / static_cast<std::uint32_t>(nx_))});
    }
}

void ProgressiveStrata::point(std::uint32_t index, double u1, double u2, double& x,
                              double& y) const {
    const Corner& corner = order_[index < order_.size() ? index : index % order_.size()];
    x = (corner.i + u1) / nx_real_;
    y = (corner.j + u2) / ny_real_;
}

}  // namespace rt
