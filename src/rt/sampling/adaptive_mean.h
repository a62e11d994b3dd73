// The stopping loop of adaptive supersampling (docs/rendering.md, "Adaptive supersampling"),
// written once for a pixel's samples (-Xp) and for the distributed rays of a lobe (-Xr).
#pragma once

#include <algorithm>
#include <cstdint>
#include <type_traits>

#include "rt/core/rgb.h"
#include "rt/sampling/chi_square.h"

namespace rt {

/// One sample's value and what it saw. Samples that saw the same (==) are on one surface, and
/// only there may sampling stop early.
template <class Seen>
struct SeenSample {
    Rgb value;
    Seen seen;
};

/// The statistics of up to `total` samples, taken in order k = 0, 1, ... by take(k), which
/// returns a SeenSample. With `stop` null (-Dx) every sample is taken. Otherwise sampling stops
/// after sample k when at least minimum_samples(total) are taken, every sample so far saw the
/// same, the chi-square rule `stop` is met, and confirm(seen) agrees that nothing else is near
/// (the neighbours' centres, a cone's rim). confirm is asked once, the first time the rest holds;
/// if it disagrees, every sample is taken.
///
/// take may also be called as take(k, certain): samples k to certain - 1 will be taken whatever
/// they bring (the first minimum_samples, and all the rest once they cannot stop early), so a
/// caller can find their rays together (packets).
template <class Take, class Confirm>
RunningStatistics adaptive_mean(std::uint32_t total, const ChiSquareStop* stop, Take&& take,
                                Confirm&& confirm) {
    const std::uint32_t minimum = stop != nullptr ? minimum_samples(total) : total;
    RunningStatistics statistics;
    constexpr bool kTellsCertain = std::is_invocable_v<Take, std::uint32_t, std::uint32_t>;
    const auto take_one = [&](std::uint32_t k, std::uint32_t certain) {
        if constexpr (kTellsCertain) {
            return take(k, certain);
        } else {
            (void)certain;
            return take(k);
        }
    };
    decltype(take_one(0, 0).seen) seen{};
    bool one_surface = true;
    bool confirm_asked = false;
    for (std::uint32_t k = 0; k < total; ++k) {
        const auto sample = take_one(k, one_surface ? std::max(minimum, k + 1) : total);
        statistics.add(sample.value);
        one_surface = one_surface && (k == 0 || sample.seen == seen);
        seen = sample.seen;
        if (stop == nullptr || k + 1 < minimum || !one_surface ||
            !stop->satisfied(statistics.count(), statistics.display_variance())) {
            continue;
        }
        if (!confirm_asked) {
            confirm_asked = true;
            one_surface = confirm(seen);
        }
        if (one_surface) {
            break;
        }
    }
    return statistics;
}

}  // namespace rt
