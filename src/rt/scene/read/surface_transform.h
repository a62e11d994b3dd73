// Placing an optical surface in the world (manual 2.2): scale first, then rotate about x, then y,
// then z (degrees, right-hand rule), then translate: world = T * Rz * Ry * Rx * S * p.
#pragma once

#include "rt/core/vec3.h"

namespace rt {

class SurfaceTransform {
public:
    /// scale must not be 0.
    SurfaceTransform(double scale, const Vec3& rotation_degrees, const Vec3& translation);

    Vec3 point(const Vec3& p) const { return rotate(p * scale_) + translation_; }
    /// An outward direction in the world: rotated, and reversed when the scale is negative (a
    /// mirror turns a solid inside out). Keeps the length.
    Vec3 normal(const Vec3& n) const { return scale_ < 0 ? -rotate(n) : rotate(n); }
    Vec3 rotate(const Vec3& v) const {
        return {dot(rows_[0], v), dot(rows_[1], v), dot(rows_[2], v)};
    }
    double scale() const { return scale_; }

private:
    double scale_;
    Vec3 rows_[3];
    Vec3 translation_;
};

/// sin and cos of an angle in degrees, exact at multiples of 90 so that right angles stay exact.
void sin_cos_degrees(double degrees, double& sine, double& cosine);

}  // namespace rt
