// The local illumination model of this release (manual 1.3, 2.3): emission, ambient, and for each
// point light reached by a shadow feeler, Lambert diffuse and Phong specular reflection (plus, with
// -T, a cos^tpow highlight through non-opaque polygons). Reflected and refracted rays are the ray
// tracer's business.
#pragma once

#include <optional>
#include <span>

#include "rt/accel/accelerator.h"
#include "rt/core/rgb.h"
#include "rt/sampling/sample_stream.h"
#include "rt/scene/scene.h"
#include "rt/shading/lights.h"
#include "rt/shading/shading_settings.h"
#include "rt/shading/shadow_feeler.h"
#include "rt/shading/surface_point.h"

namespace rt {

struct IlluminationContext {
    const Scene& scene;
    const Accelerator& accel;
    const ShadingSettings& settings;
    std::span<const PointLight> lights;  ///< empty when shadow feeling is off
    double epsilon;                      ///< self-intersection distance
    SampleStream* stream = nullptr;      ///< the sample's random numbers (fuzzy feelers)
    /// By light (as `lights`), the feeler toward it planned and asked beforehand (an eye hit's:
    /// RayTracer::eye_feelers); empty for none.
    std::span<const FeelerAnswer> known_feelers = {};
};

/// Light leaving the surface toward `view` (unit, pointing from the surface to the viewer).
/// Without `highlights` (a distributed ray's hit, unless -I) only emission, ambient and diffuse.
Rgb local_illumination(const IlluminationContext& context, const SurfacePoint& surface,
                       const Vec3& view, bool highlights, TraceCounters& counters);

}  // namespace rt
