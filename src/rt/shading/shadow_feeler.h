// Shadow feelers (manual 1.3, 2.2): how much of a point light reaches a point.
#pragma once

#include <cstdint>
#include <optional>

#include "rt/accel/accelerator.h"
#include "rt/core/rgb.h"
#include "rt/sampling/sample_stream.h"
#include "rt/scene/scene.h"
#include "rt/shading/lights.h"
#include "rt/shading/shading_settings.h"
#include "rt/shading/surface_point.h"

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

/// Where a feeler toward a light goes: feel_light's steps before it traces.
struct FeelerAim {
    Vec3 target;            ///< the light's position, or a warn light's displaced source (-Wt)
    double distance = 0.0;  ///< from the point to the light's position (the -A fall-off)
    /// |target - point|: `distance` itself unless a warn light moved the target. Shading takes
    /// it from here rather than measuring the feeler again: a square root and a division less a
    /// feeler, on the path every feeler waits on (cornell rendered 13 % slower without).
    double target_distance = 0.0;
    double warn = 1.0;  ///< the warn light's weight (-W), 1 without
};

/// Where a feeler from `from` toward `light` goes, into `aim`; false when no light can arrive:
/// the light is within epsilon, the point is behind a one-sided emitter (-Db off), or a warn
/// light gives it no weight. (Filled in place: returned in an optional, its copy through the
/// stack stalled every feeler on loads that straddle two stores.)
inline bool aim_feeler(const FeelerContext& context, const Vec3& from, const PointLight& light,
                       FeelerAim& aim);

/// The first closest_hit query of a feeler along from + t * span.
struct FeelerQuery {
    Ray ray;
    Interval along;
};

/// The interval a feeler of length `distance` asks over: its point of departure and the light
/// itself left out, by epsilon each.
inline Interval feeler_interval(const FeelerContext& context, double distance) {
    return {context.epsilon / distance, 1.0 - context.epsilon / distance};
}

/// The query for a span of length `distance`, or nothing for one too short to meet anything.
inline std::optional<FeelerQuery> first_feeler_query(const FeelerContext& context, const Vec3& from,
                                                     const Vec3& span, double distance) {
    if (!(distance > context.epsilon)) {
        return std::nullopt;
    }
    return FeelerQuery{Ray{from, span, context.leaves}, feeler_interval(context, distance)};
}

/// How a point stands toward a light: the unit direction to it, whether it is on the viewer's
/// side of the surface, and whether local_illumination sends a feeler to it.
struct LightSide {
    Vec3 to_light;
    bool viewer_side = false;
    bool feels = false;
};

/// For `light` seen from `surface`, lit with highlights or not (as local_illumination is):
/// feelers go to lights on the viewer's side, and with -T's far-side feelers to those behind a
/// non-opaque surface; an emitter does not light itself.
inline LightSide light_side(const ShadingSettings& settings, const SurfacePoint& surface,
                            const PointLight& light, bool highlights) {
    if (light.polygon == surface.polygon) {
        return {};  // an emitter does not light itself
    }
    LightSide side;
    side.to_light = normalize(light.position - surface.position);
    side.viewer_side = dot(side.to_light, surface.facing_normal) > 0.0;
    side.feels =
        side.viewer_side || (highlights && settings.far_side_feelers && surface.transmission > 0.0);
    return side;
}

/// The feeler from one point toward one light, planned and asked beforehand: the renderer plans
/// the feelers from eye hits by the very steps shading takes (light_side, aim_feeler,
/// first_feeler_query) and asks them eight at a time (RayTracer::eye_feelers), since feelers from
/// neighbouring hits toward one light point are coherent rays; the packet walk's answer is the
/// single ray's. Shading then takes the plan and the first answer from here; a later layer
/// through non-opaque polygons is asked as usual.
struct FeelerAnswer {
    enum class State : std::uint8_t {
        NotFound,  ///< not planned beforehand: shading plans and asks itself
        Dark,      ///< no feeler goes, or none can bring light (side.feels may say which)
        Misses,    ///< the feeler's first query meets nothing
        Hits,      ///< its nearest hit is `hit`
    };
    State state = State::NotFound;
    LightSide side;
    FeelerAim aim;   ///< for Misses and Hits
    Interval along;  ///< the first query's interval, for Misses and Hits
    Hit hit;         ///< for Hits
    /// Whether the first query's answer is here.
    bool answered() const { return state == State::Misses || state == State::Hits; }
};

/// The light from `light` arriving at `from`: its intensity, attenuated with distance (unless
/// -Dl), filtered by every non-opaque polygon on the way (colour times transmission weight), and
/// nothing if an opaque polygon (or, with -Dt, any polygon) stands between. With -F the feeler
/// is distributed: several feelers, each turned at random by up to distangle from the light's
/// direction, and the light is shared among them.
Rgb feel_light(const FeelerContext& context, const Vec3& from, const PointLight& light,
               TraceCounters& counters);

/// feel_light for a feeler planned and asked beforehand (`known` not NotFound; without -F):
/// the same light, the first query not asked again.
Rgb feel_light_planned(const FeelerContext& context, const Vec3& from, const PointLight& light,
                       const FeelerAnswer& known, TraceCounters& counters);

/// The fraction of light (per channel) passing along from + t * span, 0 < t < 1, the emitter
/// `light_polygon` excepted: 1 for a clear path, filtered by non-opaque polygons, 0 if blocked.
Rgb feeler_transmittance(const FeelerContext& context, const Vec3& from, const Vec3& span,
                         std::uint32_t light_polygon, TraceCounters& counters);

/// aim_feeler's part for warn lights (-W): where the feeler goes and the light's weight.
bool aim_warn_feeler(const FeelerContext& context, const Vec3& from, const PointLight& light,
                     FeelerAim& aim);

// Inline, as is the rest of a feeler's plan: every shading point asks it once a light.
inline bool aim_feeler(const FeelerContext& context, const Vec3& from, const PointLight& light,
                       FeelerAim& aim) {
    const double distance = length(light.position - from);
    if (!(distance > context.epsilon)) {
        return false;
    }
    // -Db: "only the 'outside' surface of emissive polygons emits light" (manual Appendix). A
    // point behind a one-sided emitter gets none of its light, as a diffuse ray (-Ds) from there
    // would see no emission.
    const Polygon& emitter_polygon = context.scene.polygons[light.polygon];
    if (!context.settings.both_sides_emit &&
        dot(from - light.position, emitter_polygon.normal) <= 0.0) {
        return false;
    }
    aim.target = light.position;
    aim.distance = distance;
    aim.target_distance = distance;
    aim.warn = 1.0;
    return context.settings.warn.mode == WarnMode::None ||
           aim_warn_feeler(context, from, light, aim);
}

}  // namespace rt
