// -r: random rays for profiling the intersection method (manual Appendix: "Fire random rays ...
// only useful with the -p option"). No picture.
#pragma once

#include <cstdint>

#include "rt/accel/accelerator.h"
#include "rt/render/ray_kinds.h"
#include "rt/scene/scene.h"

namespace rt {

/// Fires `count` rays with origins uniform in the scene's bounding box doubled about its centre
/// and directions uniform over the sphere, each ray a pure function of (seed, index), on
/// `threads` threads (0: every core). Returns the counters (kind Random).
KindCounters fire_random_rays(const Scene& scene, const Accelerator& accel, std::uint64_t count,
                              std::uint64_t seed, int threads);

}  // namespace rt
