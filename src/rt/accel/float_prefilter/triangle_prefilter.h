// The float pre-filter of one triangle (float_ray.cpp, part 3): it rejects the triangle only when
// the ray certainly misses it, and the exact test decides every other one. The voxel methods'
// triangle look (voxel/polygon_boxes.h); the BVH tests four or eight triangles at once with the
// same operations in the same order per lane (bvh/packet_prefilter.h, bvh_traversal.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "rt/accel/float_prefilter/float_ray.h"

namespace rt {

namespace fused {

// One lane's a * b - c, c - a * b and a * b + c: a fused step where the build has FMA, as in the
// four- and eight-lane forms (fused_float8.h says why a pre-filter may fuse), so that every form
// of the triangle test answers alike.
inline float mul_sub(float a, float b, float c) {
#ifdef __FMA__
    return std::fma(a, b, -c);
#else
    return a * b - c;
#endif
}
inline float sub_mul(float c, float a, float b) {
#ifdef __FMA__
    return std::fma(-a, b, c);
#else
    return c - a * b;
#endif
}
inline float mul_add(float a, float b, float c) {
#ifdef __FMA__
    return std::fma(a, b, c);
#else
    return a * b + c;
#endif
}

}  // namespace fused

/// One triangle, corners [vertex][axis] rounded to nearest: false only when the ray (usable)
/// certainly misses it.
inline bool triangle_candidate(const float* corner, const FloatRay& ray) {
    const float ox = ray.origin[ray.kx];
    const float oy = ray.origin[ray.ky];
    const float oz = ray.origin[ray.kz];
    float x[3];
    float y[3];
    float size = 0.0f;
    for (int v = 0; v < 3; ++v) {
        const float* c = corner + std::ptrdiff_t{3} * v;
        const float az = c[ray.kz] - oz;
        x[v] = fused::sub_mul(c[ray.kx] - ox, ray.shear_x, az);
        y[v] = fused::sub_mul(c[ray.ky] - oy, ray.shear_y, az);
        size = std::max(size, std::max(std::fabs(x[v]), std::fabs(y[v])));
    }
    const float e0 = fused::mul_sub(x[1], y[2], y[1] * x[2]);
    const float e1 = fused::mul_sub(x[2], y[0], y[2] * x[0]);
    const float e2 = fused::mul_sub(x[0], y[1], y[0] * x[1]);
    const float margin =
        fused::mul_add(size, fused::mul_add(size, kRelativeSlack, ray.edge_margin_linear),
                       ray.edge_margin_constant);
    const bool all_positive = e0 >= -margin && e1 >= -margin && e2 >= -margin;
    const bool all_negative = e0 <= margin && e1 <= margin && e2 <= margin;
    return all_positive || all_negative;
}

}  // namespace rt
