#include "rt/shading/warn_light.h"

#include <algorithm>
#include <cmath>

namespace rt {

double warn_cosine(const WarnEmitter& emitter, const Vec3& light_to_point) {
    const double c = std::clamp(dot(emitter.normal, light_to_point), -1.0, 1.0);
    return emitter.both_sides_emit ? std::fabs(c) : c;
}

double rogers_factor(const WarnEmitter& emitter, const Vec3& light_to_point) {
    const double c = warn_cosine(emitter, light_to_point);
    return c > 0.0 ? std::pow(c, emitter.exponent) : 0.0;
}

Vec3 warn_feeler_target(const WarnSettings& settings, const WarnEmitter& emitter,
                        const Vec3& light_position, const Vec3& point) {
    if (settings.mode != WarnMode::Thibadeau) {
        return light_position;
    }
    const bool point_behind = dot(emitter.normal, point - light_position) < 0.0;
    const Vec3 facing = point_behind && emitter.both_sides_emit ? -emitter.normal : emitter.normal;
    return light_position - facing * settings.displacement;
}

double thibadeau_factor(const WarnEmitter& emitter, const Vec3& source_to_point,
                        bool crosses_emitter) {
    return crosses_emitter ? rogers_factor(emitter, source_to_point) : 0.0;
}

double warn_factor(const WarnSettings& settings, const WarnEmitter& emitter,
                   const Vec3& light_to_point, bool crosses_emitter) {
    switch (settings.mode) {
        case WarnMode::None:
            return 1.0;
        case WarnMode::Rogers:
            return rogers_factor(emitter, light_to_point);
        case WarnMode::Conical: {
            const double c = warn_cosine(emitter, light_to_point);
            return std::acos(c) > settings.cone_angle ? 0.0
                                                      : rogers_factor(emitter, light_to_point);
        }
        case WarnMode::Thibadeau:
            return thibadeau_factor(emitter, light_to_point, crosses_emitter);
    }
    return 1.0;
}

}  // namespace rt
