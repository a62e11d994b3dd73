// The illumination switches as plain settings (manual Appendix: -A -Da -Dl -Ds -Dr -Dt -Db -T -Po
// -F -S -C -W -Ot -Oi), carrying the sampling settings (rt/sampling/sampling_settings.h) along.
#pragma once

#include "rt/sampling/sampling_settings.h"
#include "rt/shading/specular_model.h"
#include "rt/shading/warn_light.h"

namespace rt {

/// -F distangle,distfac: distributed shadow feelers for fuzzy shadows. distfac is read as the
/// number of feelers per light (rounded up).
struct FuzzyFeelers {
    double angle = 0.0;  ///< distangle, radians: 0 is off
    int count = 1;
    bool enabled() const { return angle > 0.0; }
};

struct ShadingSettings {
    double attenuation_distance = 200.0;  ///< -A d,c: intensity divided by dist/d + c
    double attenuation_constant = 1.0;
    bool attenuate_rays = true;                ///< off with -Da
    bool attenuate_feelers = true;             ///< off with -Dl
    bool shadow_feelers = true;                ///< off with -Ds (and when lghtick is 0)
    bool feelers_stop_at_transparent = false;  ///< -Dt
    bool reflection = true;                    ///< off with -Dr
    bool both_sides_emit = true;               ///< off with -Db
    bool far_side_feelers = false;             ///< -T
    bool smooth_shaded_opaque = false;         ///< -Po: smooth-shaded polygons are opaque
    double ambient_light = 1.0;                ///< white ambient light the ambient weight reflects
    /// --cutoff: a secondary ray whose weight (the coefficients along its path multiplied) is
    /// below this is not traced; 0 traces every ray, as the manual's program did.
    double weight_cutoff = 0.0;
    SamplingSettings sampling;      ///< read by the renderer and the ray tree, not by shading
    FuzzyFeelers fuzzy;             ///< -F
    SpecularSettings specular;      ///< -S and -C: the highlight's law and colour
    WarnSettings warn;              ///< -Wr -Wc -Wt
    bool correct_smoothing = true;  ///< off with -Ot: smoothed normals may face away from the ray
    bool share_light_among_points = true;  ///< off with -Oi: every point source at full power

    /// The manual's attenuation factor 1 / (dist/d + c).
    double attenuation(double distance) const {
        return 1.0 / (distance / attenuation_distance + attenuation_constant);
    }
};

/// -Oi, the earliest version of the raytracer (docs/rendering.md): Whitted's model as first
/// written, before attenuation, transparent shadows and distribution were added, and with an
/// emitter's point sources each at its full power. `every_sample` (-O1) also takes every sample.
ShadingSettings earliest_version(ShadingSettings settings, bool every_sample);

}  // namespace rt
