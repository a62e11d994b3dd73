// Random directions for distributed ray tracing (Cook, Porter and Carpenter 1984; manual 1.3 and
// 2.3): a specularly reflected or refracted ray is "distributed in a cone with an angle theta and
// according to a cosine to the power n law".
#pragma once

#include <array>

#include "rt/core/vec3.h"

namespace rt {

/// Two unit vectors completing the unit axis to a right-handed orthonormal basis (Duff et al.,
/// "Building an orthonormal basis, revisited", JCGT 2017).
void orthonormal_basis(const Vec3& axis, Vec3& tangent, Vec3& bitangent);

/// The cone of a distributed ray: directions within `half_angle` radians of the axis, with
/// density proportional to cos^exponent of the angle to the axis (per unit solid angle).
struct CosPowerCone {
    double half_angle = 0.0;  ///< (0, pi/2]: wider cones are clamped to the hemisphere
    double exponent = 0.0;    ///< >= 0; 0 is uniform over the cone's solid angle
};

/// A direction of the cone around the unit axis from two uniform numbers in [0, 1): the angle
/// to the axis by inverting the cone's distribution exactly, the turn around it uniformly.
Vec3 sample_cone(const CosPowerCone& cone, const Vec3& axis, double u1, double u2);

/// What sampling a cone needs besides its axis: the same for every lobe of one material, so
/// the ray tracer works it out once for each (a cosine and a power, which took 0.8 % of a
/// render's instructions when every lobe worked them out again).
struct ConeShape {
    explicit ConeShape(const CosPowerCone& cone);
    double below_edge;     ///< 1 - cos^(n+1) of the edge
    double inverse_power;  ///< 1 / (n + 1)
};

/// sample_cone for many directions of one cone around one axis (the rays of one lobe): the
/// axis's basis and the cone's edge, a cosine and a power, are worked out once instead of for
/// every ray. It gives sample_cone's directions bit for bit.
class ConeSampler {
public:
    ConeSampler(const CosPowerCone& cone, const Vec3& axis);
    ConeSampler(const ConeShape& shape, const Vec3& axis);
    Vec3 operator()(double u1, double u2) const;
    /// The four directions on the cone's rim, operator()(1.0, q / 4.0) for q = 0..3 bit for
    /// bit, with one power for the four and the quarters' sines and cosines kept (the adaptive
    /// rule probes them for every lobe it may stop early).
    std::array<Vec3, 4> rim() const;

private:
    Vec3 axis_;
    Vec3 tangent_;
    Vec3 bitangent_;
    ConeShape shape_;
};

/// The mean of cos(angle to the axis) over the cone's distribution (for tests and for -K).
double mean_cosine(const CosPowerCone& cone);

/// A cosine-weighted direction of the hemisphere around the unit normal (diffuse rays of -Ds).
Vec3 sample_cosine_hemisphere(const Vec3& normal, double u1, double u2);

/// sample_cosine_hemisphere for many directions around one normal, its basis worked out once;
/// the same directions bit for bit.
class CosineHemisphereSampler {
public:
    explicit CosineHemisphereSampler(const Vec3& normal);
    Vec3 operator()(double u1, double u2) const;

private:
    Vec3 normal_;
    Vec3 tangent_;
    Vec3 bitangent_;
};

}  // namespace rt
