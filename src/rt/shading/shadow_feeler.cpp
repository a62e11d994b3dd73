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

// What a hit on the feeler's way does to the light: false where it stops it; else the light
// is filtered by the polygon and the feeler goes on past it.
bool passes_through(const FeelerContext& context, const Ray& feeler, const Hit& hit, Rgb& filter,
                    Interval& along, TraceCounters& counters) {
    ++counters.hits;
    const Polygon& p = context.scene.polygons[hit.polygon];
    const Attribute& a = context.scene.attribute_of(p);
    const bool forced_opaque = context.settings.smooth_shaded_opaque && p.smooth;
    if (a.is_opaque() || forced_opaque || context.settings.feelers_stop_at_transparent) {
        return false;
    }
    const Rgb color = surface_color(context.scene, hit.polygon, feeler.at(hit.t));
    filter = filter * color * a.transmission;
    along.min = hit.t;
    return true;
}

// feeler_transmittance for a span of length `distance`. (The loop is written out twice, here and
// in answered_transmittance: one loop taking the first answer as an argument made every
// feeler's way slower, cornell's default render 3 % and more.)
Rgb transmittance(const FeelerContext& context, const Vec3& from, const Vec3& span, double distance,
                  std::uint32_t light_polygon, TraceCounters& counters) {
    if (!(distance > context.epsilon)) {
        return {};
    }
    const Ray feeler{from, span, context.leaves};
    Interval along = feeler_interval(context, distance);
    Rgb filter{1.0, 1.0, 1.0};
    for (int layer = 0; layer <= kMaxTransparentLayers; ++layer) {
        ++counters.rays;
        const std::optional<Hit> hit = context.accel.closest_hit(feeler, along, counters);
        if (!hit || hit->polygon == light_polygon) {
            return filter;
        }
        if (!passes_through(context, feeler, *hit, filter, along, counters)) {
            return {};
        }
    }
    return {};
}

// transmittance for a feeler whose first query was answered beforehand.
Rgb answered_transmittance(const FeelerContext& context, const Vec3& from, const Vec3& span,
                           const FeelerAnswer& known, std::uint32_t light_polygon,
                           TraceCounters& counters) {
    const Ray feeler{from, span, context.leaves};
    Interval along = known.along;
    std::optional<Hit> hit;
    if (known.state == FeelerAnswer::State::Hits) {
        hit = known.hit;
    }
    Rgb filter{1.0, 1.0, 1.0};
    for (int layer = 0; layer <= kMaxTransparentLayers; ++layer) {
        ++counters.rays;
        if (layer > 0) {
            hit = context.accel.closest_hit(feeler, along, counters);
        }
        if (!hit || hit->polygon == light_polygon) {
            return filter;
        }
        if (!passes_through(context, feeler, *hit, filter, along, counters)) {
            return {};
        }
    }
    return {};
}

// The light that arrives through a feeler's `passed` fraction.
Rgb arriving(const ShadingSettings& settings, const PointLight& light, const FeelerAim& aim,
             const Rgb& passed) {
    if (max_component(passed) <= 0.0) {
        return {};
    }
    const double fall_off = settings.attenuate_feelers ? settings.attenuation(aim.distance) : 1.0;
    return light.intensity * passed * (fall_off * aim.warn);
}

}  // namespace

Rgb feeler_transmittance(const FeelerContext& context, const Vec3& from, const Vec3& span,
                         std::uint32_t light_polygon, TraceCounters& counters) {
    return transmittance(context, from, span, length(span), light_polygon, counters);
}

bool aim_warn_feeler(const FeelerContext& context, const Vec3& from, const PointLight& light,
                     FeelerAim& aim) {
    // Warn lights aim the feeler (at a displaced source for -Wt) and weigh what it brings.
    const ShadingSettings& settings = context.settings;
    const Polygon& emitter_polygon = context.scene.polygons[light.polygon];
    const WarnEmitter emitter{emitter_polygon.normal,
                              context.scene.attribute_of(emitter_polygon).specular_exponent,
                              settings.both_sides_emit};
    aim.target = warn_feeler_target(settings.warn, emitter, light.position, from);
    aim.target_distance = length(aim.target - from);
    const bool crosses = settings.warn.mode == WarnMode::Thibadeau &&
                         intersect_polygon(Ray{from, aim.target - from},
                                           context.scene.polygon_view(light.polygon), {0.0, 1.0})
                             .has_value();
    aim.warn = warn_factor(settings.warn, emitter, normalize(from - aim.target), crosses);
    return aim.warn > 0.0;
}

Rgb feel_light(const FeelerContext& context, const Vec3& from, const PointLight& light,
               TraceCounters& counters) {
    const ShadingSettings& settings = context.settings;
    FeelerAim aim;
    if (!aim_feeler(context, from, light, aim)) {
        return {};
    }
    const Vec3 span = aim.target - from;
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
        passed = transmittance(context, from, span, aim.target_distance, light.polygon, counters);
    }
    return arriving(settings, light, aim, passed);
}

Rgb feel_light_planned(const FeelerContext& context, const Vec3& from, const PointLight& light,
                       const FeelerAnswer& known, TraceCounters& counters) {
    if (!known.answered()) {
        return {};
    }
    const Vec3 span = known.aim.target - from;
    return arriving(context.settings, light, known.aim,
                    answered_transmittance(context, from, span, known, light.polygon, counters));
}

}  // namespace rt
