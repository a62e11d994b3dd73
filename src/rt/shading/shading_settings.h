// The illumination switches as plain settings (manual Appendix: -A -Da -Dl -Ds -Dr -Dt -Db -T -Po).
#pragma once

namespace rt {

struct ShadingSettings {
    double attenuation_distance = 200.0;   ///< -A d,c: intensity divided by dist/d + c
    double attenuation_constant = 1.0;
    bool attenuate_rays = true;            ///< off with -Da
    bool attenuate_feelers = true;         ///< off with -Dl
    bool shadow_feelers = true;            ///< off with -Ds (and when lghtick is 0)
    bool feelers_stop_at_transparent = false;  ///< -Dt
    bool reflection = true;                ///< off with -Dr
    bool both_sides_emit = true;           ///< off with -Db
    bool far_side_feelers = false;         ///< -T
    bool smooth_shaded_opaque = false;     ///< -Po: smooth-shaded polygons are opaque
    double ambient_light = 1.0;            ///< white ambient light the ambient weight reflects

    /// The manual's attenuation factor 1 / (dist/d + c).
    double attenuation(double distance) const {
        return 1.0 / (distance / attenuation_distance + attenuation_constant);
    }
};

}  // namespace rt
