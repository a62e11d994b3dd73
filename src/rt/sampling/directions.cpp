#include "rt/sampling/directions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace rt {

namespace {

// cos^(n+1) of the cone's edge: the distribution of c = cos(angle) over the cone has the
// cumulative (1 - c^(n+1)) / (1 - edge), so inverting it is one power.
double edge_power(const CosPowerCone& cone) {
    const double half_angle = std::clamp(cone.half_angle, 0.0, std::numbers::pi / 2);
    return std::pow(std::cos(half_angle), cone.exponent + 1.0);
}

Vec3 around(const Vec3& axis, const Vec3& tangent, const Vec3& bitangent, double cos_theta,
            double cos_phi, double sin_phi) {
    const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
    return tangent * (sin_theta * cos_phi) + bitangent * (sin_theta * sin_phi) + axis * cos_theta;
}

Vec3 around(const Vec3& axis, const Vec3& tangent, const Vec3& bitangent, double cos_theta,
            double phi) {
    return around(axis, tangent, bitangent, cos_theta, std::cos(phi), std::sin(phi));
}

// The angles of the rim's four quarters, as operator() computes them for u2 = q / 4.
struct QuarterAngles {
    std::array<double, 4> cosine;
    std::array<double, 4> sine;
    QuarterAngles() : cosine(), sine() {
        for (int q = 0; q < 4; ++q) {
            const double phi = 2.0 * std::numbers::pi * (q / 4.0);
            cosine[static_cast<std::size_t>(q)] = std::cos(phi);
            sine[static_cast<std::size_t>(q)] = std::sin(phi);
        }
    }
};

}  // namespace

void orthonormal_basis(const Vec3& axis, Vec3& tangent, Vec3& bitangent) {
    const double sign = std::copysign(1.0, axis.z);
    const double a = -1.0 / (sign + axis.z);
    const double b = axis.x * axis.y * a;
    tangent = {1.0 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x};
    bitangent = {b, sign + axis.y * axis.y * a, -axis.y};
}

Vec3 sample_cone(const CosPowerCone& cone, const Vec3& axis, double u1, double u2) {
    return ConeSampler(cone, axis)(u1, u2);
}

ConeShape::ConeShape(const CosPowerCone& cone)
    : below_edge(1.0 - edge_power(cone)), inverse_power(1.0 / (cone.exponent + 1.0)) {}

ConeSampler::ConeSampler(const CosPowerCone& cone, const Vec3& axis)
    : ConeSampler(ConeShape(cone), axis) {}

ConeSampler::ConeSampler(const ConeShape& shape, const Vec3& axis) : axis_(axis), shape_(shape) {
    orthonormal_basis(axis, tangent_, bitangent_);
}

Vec3 ConeSampler::operator()(double u1, double u2) const {
    const double cos_theta = std::pow(1.0 - u1 * shape_.below_edge, shape_.inverse_power);
    return around(axis_, tangent_, bitangent_, cos_theta, 2.0 * std::numbers::pi * u2);
}

std::array<Vec3, 4> ConeSampler::rim() const {
    static const QuarterAngles quarters;
    const double cos_theta = std::pow(1.0 - shape_.below_edge, shape_.inverse_power);  // u1 = 1
    std::array<Vec3, 4> directions;
    for (std::size_t q = 0; q < 4; ++q) {
        directions[q] =
            around(axis_, tangent_, bitangent_, cos_theta, quarters.cosine[q], quarters.sine[q]);
    }
    return directions;
}

double mean_cosine(const CosPowerCone& cone) {
    // E[c] = (n+1)/(n+2) * (1 - c0^(n+2)) / (1 - c0^(n+1)) with c0 the edge's cosine.
    const double n = cone.exponent;
    const double c0 = std::cos(std::clamp(cone.half_angle, 0.0, std::numbers::pi / 2));
    const double lower = 1.0 - std::pow(c0, n + 1.0);
    if (!(lower > 0.0)) {
        return 1.0;  // a cone of no width
    }
    return (n + 1.0) / (n + 2.0) * (1.0 - std::pow(c0, n + 2.0)) / lower;
}

Vec3 sample_cosine_hemisphere(const Vec3& normal, double u1, double u2) {
    return CosineHemisphereSampler(normal)(u1, u2);
}

CosineHemisphereSampler::CosineHemisphereSampler(const Vec3& normal) : normal_(normal) {
    orthonormal_basis(normal, tangent_, bitangent_);
}

Vec3 CosineHemisphereSampler::operator()(double u1, double u2) const {
    return around(normal_, tangent_, bitangent_, std::sqrt(1.0 - u1), 2.0 * std::numbers::pi * u2);
}

}  // namespace rt
