// The packet walk's leaf tests (bvh_packet_traversal.cpp): one fan triangle of a leaf packet
// against the eight rays at once, or against one lane in its own axes; lane for lane the single
// ray's pre-filter (triangle_prefilter.h). AVX2 functions, for x86 compilers that take target
// attributes.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "rt/accel/bvh/bvh_layout.h"
#include "rt/accel/bvh/packet_pair_prefilter.h"
#include "rt/accel/bvh/packet_setup.h"
#include "rt/accel/float_prefilter/float_ray.h"
#include "rt/accel/float_prefilter/fused_float8.h"
#include "rt/accel/float_prefilter/triangle_prefilter.h"

#include <immintrin.h>

namespace rt::bvh::packet {

// One fan triangle (lane `t` of `packet`) against the eight rays, in their common axes: lane for
// lane triangle_candidate's operations (triangle_prefilter.h). Bit k of `maybe`: lane k may hit
// it; of `sure`: lane k's line surely crosses it (float_ray.cpp, part 4).
__attribute__((target("avx2"))) inline FanVerdicts triangle_rays(const TrianglePacket& packet,
                                                                 int t, const PacketValues& v) {
    const int kx = v.kx[0];
    const int ky = v.ky[0];
    const int kz = v.kz[0];
    const __m256 ox = _mm256_load_ps(v.origin[kx]);
    const __m256 oy = _mm256_load_ps(v.origin[ky]);
    const __m256 oz = _mm256_load_ps(v.origin[kz]);
    const __m256 sx = _mm256_load_ps(v.shear_x);
    const __m256 sy = _mm256_load_ps(v.shear_y);
    const __m256 sign = _mm256_set1_ps(-0.0f);
    __m256 x[3];
    __m256 y[3];
    __m256 size = _mm256_setzero_ps();
    for (int c = 0; c < 3; ++c) {
        const __m256 az = _mm256_sub_ps(_mm256_set1_ps(packet.corner[c][kz][t]), oz);
        x[c] = fused::sub_mul(_mm256_sub_ps(_mm256_set1_ps(packet.corner[c][kx][t]), ox), sx, az);
        y[c] = fused::sub_mul(_mm256_sub_ps(_mm256_set1_ps(packet.corner[c][ky][t]), oy), sy, az);
        size = _mm256_max_ps(
            size, _mm256_max_ps(_mm256_andnot_ps(sign, x[c]), _mm256_andnot_ps(sign, y[c])));
    }
    return fan_edge_verdicts(x, y, size, _mm256_load_ps(v.edge_linear),
                             _mm256_load_ps(v.edge_constant));
}

// triangle_rays for one lane in its own axes: triangle_candidate's operations
// (triangle_prefilter.h), the corners read from the packet.
inline bool lane_triangle_candidate(const TrianglePacket& packet, int t, const PacketValues& v,
                                    int lane) {
    const int kx = v.kx[lane];
    const int ky = v.ky[lane];
    const int kz = v.kz[lane];
    const float ox = v.origin[kx][lane];
    const float oy = v.origin[ky][lane];
    const float oz = v.origin[kz][lane];
    float x[3];
    float y[3];
    float size = 0.0f;
    for (int c = 0; c < 3; ++c) {
        const float az = packet.corner[c][kz][t] - oz;
        x[c] = fused::sub_mul(packet.corner[c][kx][t] - ox, v.shear_x[lane], az);
        y[c] = fused::sub_mul(packet.corner[c][ky][t] - oy, v.shear_y[lane], az);
        size = std::max(size, std::max(std::fabs(x[c]), std::fabs(y[c])));
    }
    const float e0 = fused::mul_sub(x[1], y[2], y[1] * x[2]);
    const float e1 = fused::mul_sub(x[2], y[0], y[2] * x[0]);
    const float e2 = fused::mul_sub(x[0], y[1], y[0] * x[1]);
    const float margin = fused::mul_add(
        size, fused::mul_add(size, rt::kRelativeSlack, v.edge_linear[lane]), v.edge_constant[lane]);
    const bool all_positive = e0 >= -margin && e1 >= -margin && e2 >= -margin;
    const bool all_negative = e0 <= margin && e1 <= margin && e2 <= margin;
    return all_positive || all_negative;
}

}  // namespace rt::bvh::packet
