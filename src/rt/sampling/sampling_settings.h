// The sampling switches as plain settings (manual Appendix: --seed -Dd -Dx -Xp -Xr -I).
#pragma once

#include <cstdint>

#include "rt/sampling/chi_square.h"

namespace rt {

/// Distributed ray tracing and adaptive supersampling (manual 1.3, 2.2, -D d, -D x, -X, -I).
struct SamplingSettings {
    std::uint64_t seed = 0;               ///< --seed: the same seed, the same picture
    bool distribute = true;               ///< off with -Dd: one reflected, one refracted ray
    bool adaptive = true;                 ///< off with -Dx: always every sample
    ChiSquareStop pixel_stop;             ///< -Xp prob,var
    ChiSquareStop ray_stop;               ///< -Xr prob,var
    bool illuminate_distributed = false;  ///< -I: the full model at distributed rays' hits
};

}  // namespace rt
