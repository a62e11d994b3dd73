// Shadow feelers (manual 1.3, 2.2): how much of a point light reaches a point.
#pragma once

#include "rt/accel/accelerator.h"
#include "rt/core/rgb.h"
#include "rt/scene/scene.h"
#include "rt/shading/lights.h"
#include "rt/shading/shading_settings.h"

namespace rt {

/// The light from `light` arriving at `from`: its intensity, attenuated with distance (unless
/// -Dl), filtered by every non-opaque polygon on the way (colour times transmission weight), and
/// nothing if an opaque polygon (or, with -Dt, any polygon) stands between. `epsilon` is the
/// distance below which hits near `from` count as the surface itself.
Rgb feel_light(const Scene& scene, const Accelerator& accel, const ShadingSettings& settings,
               const Vec3& from, const PointLight& light, double epsilon, TraceCounters& counters);

}  // namespace rt
