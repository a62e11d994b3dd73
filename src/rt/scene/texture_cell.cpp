#include "rt/scene/texture_cell.h"

#include <cmath>

namespace rt {

double element_slope(double k, double rho) {
    const double sine = std::fabs(k) * rho;
    if (sine < kMaxElementTiltSine) {
        return k / std::sqrt(1.0 - sine * sine);
    }
    // Beyond the edge: the tangent of the steepest tilt, spread over this distance.
    const double steepest =
        kMaxElementTiltSine / std::sqrt(1.0 - kMaxElementTiltSine * kMaxElementTiltSine);
    return std::copysign(steepest / rho, k);
}

Vec3 element_normal(const TextureCell& cell, const Vec3& normal, const Vec3& point) {
    if (cell.flat()) {
        return normal;
    }
    // Height h(x, y) of the element over the cell's plane, the sum of a sphere's and a
    // cylinder's; the normal of that surface is normal - grad h, and grad h of a convex sphere
    // points back toward its centre.
    const Vec3 offset = point - cell.optical_centre;
    Vec3 slope;
    if (cell.sphere != 0.0) {
        const Vec3 in_plane = cell.tangent_u * dot(offset, cell.tangent_u) +
                              cell.tangent_v * dot(offset, cell.tangent_v);
        slope += in_plane * element_slope(cell.sphere, length(in_plane));
    }
    if (cell.cylinder != 0.0) {
        const double across = dot(offset, cell.across_axis);
        slope += cell.across_axis * (across * element_slope(cell.cylinder, std::fabs(across)));
    }
    return normalize(normal + slope);
}

}  // namespace rt
