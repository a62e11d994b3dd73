// One scene rendered again and again through the library at chosen sample resolutions, stop
// rules and seeds, keeping each picture in full precision and what it cost.
#pragma once

#include <cstdint>
#include <optional>

#include "rt/accel/accelerator.h"
#include "rt/accel/accelerator_stack.h"
#include "rt/app/options.h"
#include "rt/image/film.h"
#include "rt/render/renderer.h"
#include "rt/scene/scene.h"

namespace rt::bench {

/// How a render samples: its sample resolution (n x n pixel strata, and n x n strata of
/// distributed rays per lobe) and, if adaptive, the -Xp and -Xr rules (else -Dx).
struct SamplingPlan {
    int nx = 4;
    int ny = 4;
    bool adaptive = true;
    double pixel_variance = 0.2;  ///< -Xp's var
    double ray_variance = 0.2;    ///< -Xr's var
    double probability = 0.2;     ///< both rules' prob
};

/// What a render spent, from its ray counters.
struct Spent {
    std::uint64_t eye = 0;      ///< pixel samples
    std::uint64_t samples = 0;  ///< eye rays, the rays they spawn (distributed or not), probes
    std::uint64_t rays = 0;     ///< every ray traced, shadow feelers included
};

struct StudyRender {
    Film film;
    Spent spent;
};

class StudyScene {
public:
    /// Loads options.scene with its switches; `window` replaces the scene's output matrix.
    StudyScene(const Options& options, const std::optional<PixelRect>& window);

    StudyRender render(const SamplingPlan& plan, std::uint64_t seed);

    const PixelRect& window() const { return settings_.window; }

private:
    Scene scene_;
    RenderSettings settings_;
    std::optional<AcceleratorStack> accelerator_;
};

}  // namespace rt::bench
