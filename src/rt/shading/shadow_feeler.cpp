#include "rt/shading/shadow_feeler.h"

#include <algorithm>
#include <cmath>

#include "rt/geometry/ray_polygon.h"
#include "rt/sampling/directions.h"
#include "rt/scene/textured_point.h"
#include "rt/shading/warn_light.h"

namespace rt {

namespace {

// A feeler crosses at most this many transparent polygons; beyond, the light is taken as lost.
constexpr int kMaxTransparentLayers = 64;

}  // namespace

Rgb feeler_transmittance(const FeelerContext& context, const Vec3& from, const Vec3& span,
                         std::uint32_t light_polygon, TraceCounters& counters) {
    const double distance = length(span);
    if (!(distance > context.epsilon)) {
        return {};
    }
    const Ray feeler{from, span, context.leaves};
    Interval along{context.epsilon / distance, 1.0 - context.epsilon / distance};
    Rgb filter{1.0, 1.0, 1.0};
    for (int layer = 0; layer <= kMaxTransparentLayers; ++layer) {
        ++counters.rays;
        const std::optional<Hit> hit = context.accel.closest_hit(feeler, along, counters);
        if (!hit || hit->polygon == light_polygon) {
            return filter;
        }
        ++counters.hits;
        const Polygon& p = context.scene.polygons[hit->polygon];
        const Attribute& a = context.scene.attribute_of(p);
        const bool forced_opaque = context.settings.smooth_shaded_opaque && p.smooth;
        if (a.is_opaque() || forced_opaque || context.settings.feelers_stop_at_transparent) {
            return {};
        }
        const Rgb color = surface_color(context.scene, hit->polygon, feeler.at(hit->t));
        filter = filter * color * a.transmission;
        along.min = hit->t;
    }
    return {};
}

Rgb feel_light(const FeelerContext& context, const Vec3& from, const PointLight& light,
               TraceCounters& counters) {
    const ShadingSettings& settings = context.settings;
    const double distance = length(light.position - from);
    if (!(distance > context.epsilon)) {
        return {};
    }
    // -Db: "only the 'outside' surface of emissive polygons emits light" (manual Appendix). A
    // point behind a one-sided emitter gets none of its light, as a diffuse ray (-Ds) from there
    // would see no emission.
    const Polygon& emitter_polygon = context.scene.polygons[light.polygon];
    if (!settings.both_sides_emit && dot(from - light.position, emitter_polygon.normal) <= 0.0) {
        return {};
    }
    // Warn lights aim the feeler (at a displaced source for -Wt) and weigh what it brings.
    double warn = 1.0;
    Vec3 target = light.position;
    if (settings.warn.mode != WarnMode::None) {
        const WarnEmitter emitter{emitter_polygon.normal,
                                  context.scene.attribute_of(emitter_polygon).specular_exponent,
                                  settings.both_sides_emit};
        target = warn_feeler_target(settings.warn, emitter, light.position, from);
        const bool crosses =
            settings.warn.mode == WarnMode::Thibadeau &&
            intersect_polygon(Ray{from, target - from}, context.scene.polygon_view(light.polygon),
                              {0.0, 1.0})
                .has_value();
        warn = warn_factor(settings.warn, emitter, normalize(from - target), crosses);
        if (!(warn > 0.0)) {
            return {};
        }
    }
    const Vec3 span = target - from;
    Rgb passed;
    const FuzzyFeelers& fuzzy = settings.fuzzy;
    if (fuzzy.enabled() && context.stream != nullptr) {
        // Each feeler turned at random within distangle of the light's direction (uniform over
        // the cone's solid angle), as long as the light is far.
        const CosPowerCone cone{fuzzy.angle, 0.0};
        const double length_to_target = length(span);
        const Vec3 axis = span / length_to_target;
        for (int k = 0; k < fuzzy.count; ++k) {
            const double u1 = context.stream->uniform();
            const double u2 = context.stream->uniform();
            const Vec3 turned = sample_cone(cone, axis, u1, u2) * length_to_target;
            passed += feeler_transmittance(context, from, turned, light.polygon, counters);
        }
        passed *= 1.0 / fuzzy.count;
    } else {
        passed = feeler_transmittance(context, from, span, light.polygon, counters);
    }
    if (max_component(passed) <= 0.0) {
        return {};
    }
    const double fall_off = settings.attenuate_feelers ? settings.attenuation(distance) : 1.0;
    return light.intensity * passed * (fall_off * warn);
}

}  // namespace rt
