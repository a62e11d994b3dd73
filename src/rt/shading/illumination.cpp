#include "rt/shading/illumination.h"

#include <cmath>
#include <cstddef>
#include <optional>

#include "rt/shading/optics.h"
#include "rt/shading/shadow_feeler.h"
#include "rt/shading/specular_model.h"

namespace rt {

namespace {

double cos_power(double cosine, double exponent) {
    return cosine > 0.0 ? std::pow(cosine, exponent) : 0.0;
}

// Diffuse and specular reflection of one light on the viewer's side of the polygon.
Rgb reflected_light(const ShadingSettings& settings, const SurfacePoint& s, const Vec3& view,
                    const Vec3& to_light, const Rgb& received, bool highlights) {
    const Attribute& a = *s.attribute;
    const double lambert = std::fmax(0.0, dot(s.shading_normal, to_light));
    Rgb result = received * s.color * (a.diffuse * lambert);
    if (highlights) {
        result += received * specular_highlight(settings.specular, a, s.color, s.shading_normal,
                                                to_light, view);
    }
    return result;
}

// -T: a light behind a non-opaque polygon shines through it, in a cos^tpow lobe around the
// refracted continuation of the viewing ray.
Rgb transmitted_light(const SurfacePoint& s, const Vec3& view, const Vec3& to_light,
                      const Rgb& received) {
    const Attribute& a = *s.attribute;
    const double n_out = a.refraction_index.g;
    const double n1 = s.front ? 1.0 : n_out;
    const double n2 = s.front ? n_out : 1.0;
    const std::optional<Vec3> through = refract(-view, s.shading_normal, n1, n2);
    if (!through) {
        return {};
    }
    const double lobe = cos_power(dot(normalize(*through), to_light), a.transmit_exponent);
    return received * s.color * (s.transmission * lobe);
}

}  // namespace

Rgb local_illumination(const IlluminationContext& context, const SurfacePoint& s, const Vec3& view,
                       bool highlights, TraceCounters& counters) {
    const Attribute& a = *s.attribute;
    const ShadingSettings& settings = context.settings;
    Rgb result = s.color * (a.ambient * settings.ambient_light);
    if (s.front || settings.both_sides_emit) {
        result += s.color * a.emission;
    }
    const FeelerContext feeler{context.scene,   context.accel,  settings,
                               context.epsilon, context.stream, s.polygon};
    for (std::size_t i = 0; i < context.lights.size(); ++i) {
        const PointLight& light = context.lights[i];
        const FeelerAnswer* known =
            i < context.known_feelers.size() &&
                    context.known_feelers[i].state != FeelerAnswer::State::NotFound
                ? &context.known_feelers[i]
                : nullptr;
        const LightSide side =
            known != nullptr ? known->side : light_side(settings, s, light, highlights);
        if (!side.feels) {
            continue;
        }
        const Rgb received = known != nullptr
                                 ? feel_light_planned(feeler, s.position, light, *known, counters)
                                 : feel_light(feeler, s.position, light, counters);
        if (max_component(received) <= 0.0) {
            continue;
        }
        result += side.viewer_side
                      ? reflected_light(settings, s, view, side.to_light, received, highlights)
                      : transmitted_light(s, view, side.to_light, received);
    }
    return result;
}

}  // namespace rt
