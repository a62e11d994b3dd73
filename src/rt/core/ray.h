// A ray: origin plus direction (not necessarily unit length); points are origin + t * direction.
#pragma once

#include "rt/core/vec3.h"

namespace rt {

struct Ray {
    Vec3 origin;
    Vec3 direction;

    Vec3 at(double t) const { return origin + direction * t; }
};

/// The open interval of t in which a hit counts.
struct Interval {
    double min = 0.0;
    double max = 1e300;
};

}  // namespace rt
