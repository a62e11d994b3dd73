#include "rt/shading/shadow_feeler.h"

namespace rt {

namespace {

// A feeler crosses at most this many transparent polygons; beyond, the light is taken as lost.
constexpr int kMaxTransparentLayers = 64;

}  // namespace

Rgb feel_light(const Scene& scene, const Accelerator& accel, const ShadingSettings& settings,
               const Vec3& from, const PointLight& light, double epsilon, TraceCounters& counters) {
    const Vec3 to_light = light.position - from;
    const double distance = length(to_light);
    if (!(distance > epsilon)) {
        return {};
    }
    // t runs from 0 at the point to 1 at the light; stop just short of the light itself.
    const Ray feeler{from, to_light};
    Interval span{epsilon / distance, 1.0 - epsilon / distance};
    Rgb filter{1.0, 1.0, 1.0};
    for (int layer = 0; layer <= kMaxTransparentLayers; ++layer) {
        const std::optional<Hit> hit = accel.closest_hit(feeler, span, counters);
        if (!hit || hit->polygon == light.polygon) {
            const double fall_off =
                settings.attenuate_feelers ? settings.attenuation(distance) : 1.0;
            return light.intensity * filter * fall_off;
        }
        const Attribute& a = scene.attribute_of(scene.polygons[hit->polygon]);
        const bool forced_opaque =
            settings.smooth_shaded_opaque && scene.polygons[hit->polygon].smooth;
        if (a.is_opaque() || forced_opaque || settings.feelers_stop_at_transparent) {
            return {};
        }
        filter = filter * a.color * a.transmission;
        span.min = hit->t;
    }
    return {};
}

}  // namespace rt
