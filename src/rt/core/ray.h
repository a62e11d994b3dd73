// A ray: origin plus direction (not necessarily unit length); points are origin + t * direction.
#pragma once

#include "rt/core/vec3.h"

namespace rt {

struct Ray {
    Vec3 origin;
    Vec3 direction;

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
