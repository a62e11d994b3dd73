// A ray: origin plus direction (not necessarily unit length); points are origin + t * direction.
#pragma once

#include <cstdint>

#include "rt/core/vec3.h"

namespace rt {

/// Ray::leaves of a ray that leaves no polygon (from the eye, or anywhere off the scene's
/// surfaces).
inline constexpr std::uint32_t kLeavesNoPolygon = 0xffffffffu;

struct Ray {
    Vec3 origin;
    Vec3 direction;
    /// The polygon the ray starts on (a reflected, refracted or diffuse ray, a rim probe or a
    /// shadow feeler from a hit on it), which it never meets: a ray leaving a planar polygon
    /// cannot meet it again, and every method, brute force included, skips it alike
    /// (accel/lane_exact_hit.h), where its exact test could only report the point the ray leaves
    /// (within rounding) or, seen edge-on, a depth within the polygon's own corners.
    std::uint32_t leaves = kLeavesNoPolygon;

    Vec3 at(double t) const { return origin + direction * t; }
};

/// The far end of an interval that has none: beyond any scene's distances, and finite.
inline constexpr double kBeyondAnyScene = 1e300;

/// The open interval of t in which a hit counts.
struct Interval {
    double min = 0.0;
    double max = kBeyondAnyScene;
};

}  // namespace rt
