// Mirror reflection and Snell refraction of unit directions.
#pragma once

#include <cmath>
#include <optional>

#include "rt/core/vec3.h"

namespace rt {

/// Reflects incoming direction d about the unit normal n.
inline Vec3 reflect(const Vec3& d, const Vec3& n) {
    return d - n * (2.0 * dot(d, n));
}

/// Refracts unit direction d through a surface with unit normal n facing against d
/// (dot(d, n) < 0), from index n1 into index n2. Nothing on total internal reflection.
inline std::optional<Vec3> refract(const Vec3& d, const Vec3& n, double n1, double n2) {
    const double eta = n1 / n2;
    const double cos_i = -dot(d, n);
    const double sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if (sin2_t > 1.0) {
        return std::nullopt;
    }
    const double cos_t = std::sqrt(1.0 - sin2_t);
    return d * eta + n * (eta * cos_i - cos_t);
}

}  // namespace rt
