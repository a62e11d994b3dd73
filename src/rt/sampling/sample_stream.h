// The random numbers of one sample of one pixel: a pure function of (seed, pixel, sample,
// dimension). Everything random about that sample (its position in the pixel, the distributed
// rays of its ray tree, the fuzzy shadow feelers) is drawn from its stream in a fixed order.
#pragma once

#include <cstdint>

#include "rt/sampling/philox.h"

namespace rt {

class SampleStream {
public:
    SampleStream(std::uint64_t seed, int pixel_x, int pixel_y, std::uint32_t sample)
        : key_{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)},
          pixel_x_(static_cast<std::uint32_t>(pixel_x)),
          pixel_y_(static_cast<std::uint32_t>(pixel_y)),
          sample_(sample) {}

    /// Uniform in [0, 1), 53 random bits.
    double uniform() {
        if (!has_spare_) {
            const PhiloxCounter out =
                philox4x32_10({pixel_x_, pixel_y_, sample_, dimension_++}, key_);
            spare_ = to_unit(out[2], out[3]);
            has_spare_ = true;
            return to_unit(out[0], out[1]);
        }
        has_spare_ = false;
        return spare_;
    }

private:
    static double to_unit(std::uint32_t high, std::uint32_t low) {
        const std::uint64_t bits = (std::uint64_t{high} << 21) ^ (low >> 11);  // 53 bits
        return static_cast<double>(bits & ((std::uint64_t{1} << 53) - 1)) * 0x1p-53;
    }

    PhiloxKey key_;
    std::uint32_t pixel_x_;
    std::uint32_t pixel_y_;
    std::uint32_t sample_;
    std::uint32_t dimension_ = 0;
    double spare_ = 0.0;
    bool has_spare_ = false;
};

}  // namespace rt
