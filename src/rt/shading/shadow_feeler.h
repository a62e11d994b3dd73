// Shadow feelers (manual 1.3, 2.2): how much of a point light reaches a point.
#pragma once

#include "rt/accel/accelerator.h"
#include "rt/core/rgb.h"
#include "rt/sampling/sample_stream.h"
#include "rt/scene/scene.h"
#include "rt/shading/lights.h"
#include "rt/shading/shading_settings.h"

namespace rt {

/// What a feeler needs besides the light: where it starts and how to draw random numbers.
struct FeelerContext {
    const Scene& scene;
    const Accelerator& accel;
    const ShadingSettings& settings;
    double epsilon = 0.0;            ///< hits nearer `from` than this are the surface itself
    SampleStream* stream = nullptr;  ///< for -F; may be null when -F is off
    /// The polygon the feelers start on (Ray::leaves), which they never meet.
    std::uint32_t leaves = kLeavesNoPolygon;
};

/// The light from `light` arriving at `from`: its intensity, attenuated with distance (unless
/// -Dl), filtered by every non-opaque polygon on the way (colour times transmission weight), and
/// nothing if an opaque polygon (or, with -Dt, any polygon) stands between. With -F the feeler
/// is distributed: several feelers, each turned at random by up to distangle from the light's
/// direction, and the light is shared among them.
Rgb feel_light(const FeelerContext& context, const Vec3& from, const PointLight& light,
               TraceCounters& counters);

/// The fraction of light (per channel) passing along from + t * span, 0 < t < 1, the emitter
/// `light_polygon` excepted: 1 for a clear path, filtered by non-opaque polygons, 0 if blocked.
Rgb feeler_transmittance(const FeelerContext& context, const Vec3& from, const Vec3& span,
                         std::uint32_t light_polygon, TraceCounters& counters);

}  // namespace rt
