// Stratified, jittered sampling of a unit square in a progressive order: the pixel's n x n strata
// (manual 2.2, "sample resolution") and the strata of distributed rays are visited so that every
// prefix is spread over the whole square, which is what lets adaptive sampling stop early.
#pragma once

#include <cstdint>
#include <vector>

namespace rt {

class ProgressiveStrata {
public:
    /// nx x ny strata, both at least 1.
    ProgressiveStrata(int nx, int ny);

    std::uint32_t size() const { return static_cast<std::uint32_t>(order_.size()); }
    /// The point of the index-th stratum (in progressive order) jittered by (u1, u2) in [0, 1).
    /// Inline, and a product where n is a power of two (the same bits as the quotient): every
    /// eye sample and distributed ray waits for its point before its ray can start.
    void point(std::uint32_t index, double u1, double u2, double& x, double& y) const {
        const Corner& corner = order_[index < order_.size() ? index : index % order_.size()];
        if (powers_of_two_) {
            x = (corner.i + u1) * inverse_nx_;
            y = (corner.j + u2) * inverse_ny_;
        } else {
            x = (corner.i + u1) / nx_real_;
            y = (corner.j + u2) / ny_real_;
        }
    }

private:
    /// A stratum's column and row, as the doubles point() adds to: no division per sample.
    struct Corner {
        double i;
        double j;
    };
    int nx_;
    int ny_;
    double nx_real_;
    double ny_real_;
    double inverse_nx_;
    double inverse_ny_;
    bool powers_of_two_;         ///< nx and ny: then 1 / n is exact, and so is the product
    std::vector<Corner> order_;  ///< the strata in visiting order
};

}  // namespace rt
