// The float pre-filter of two consecutive packets of four fan triangles at once, with AVX2:
// eight triangles per instruction. Lane for lane the operations of fan_candidates
// (packet_prefilter.h), in the same order, each multiply-and-add step fused into one where the
// build has FMA as it is there (fused_float8.h), so every lane gets the four-wide test's answer.
// Shared by the BVH's leaf packets and the voxel methods' cell packets, which lay their corners out
// alike.
#pragma once

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define RT_PACKET_PAIR_AVX2 1

#include "rt/accel/bvh/packet_prefilter.h"
#include "rt/accel/float_prefilter/float_ray.h"
#include "rt/accel/float_prefilter/fused_float8.h"

#include <immintrin.h>

namespace rt::bvh {

using FanCorners = float[3][3][4];  ///< [vertex][axis][lane]

__attribute__((target("avx2"))) inline __m256 load_fan_pair(const FanCorners& first,
                                                            const FanCorners& second, int v,
                                                            int axis) {
    return _mm256_set_m128(_mm_loadu_ps(second[v][axis]), _mm_loadu_ps(first[v][axis]));
}

/// The last step of every eight-wide fan-triangle pre-filter, from the corners in the ray's sheared
/// 2D space (x, y) and their largest coordinate (size): the three edge functions, the margin
/// (size * (linear + size * slack) + constant) and the all-positive or all-negative test, lane
/// for lane fan_candidates' operations; the sure verdicts ask the same beyond the margin, and only
/// when some lane may be hit.
__attribute__((target("avx2"))) inline FanVerdicts fan_edge_verdicts(const __m256 (&x)[3],
                                                                     const __m256 (&y)[3],
                                                                     __m256 size,
                                                                     __m256 edge_linear,
                                                                     __m256 edge_constant) {
    const __m256 e0 = fused::mul_sub(x[1], y[2], _mm256_mul_ps(y[1], x[2]));
    const __m256 e1 = fused::mul_sub(x[2], y[0], _mm256_mul_ps(y[2], x[0]));
    const __m256 e2 = fused::mul_sub(x[0], y[1], _mm256_mul_ps(y[0], x[1]));
    const __m256 margin = fused::mul_add(
        size, fused::mul_add(size, _mm256_set1_ps(kRelativeSlack), edge_linear), edge_constant);
    const __m256 negative_margin = _mm256_sub_ps(_mm256_setzero_ps(), margin);
    const __m256 all_positive =
        _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(e0, negative_margin, _CMP_GE_OQ),
                                    _mm256_cmp_ps(e1, negative_margin, _CMP_GE_OQ)),
                      _mm256_cmp_ps(e2, negative_margin, _CMP_GE_OQ));
    const __m256 all_negative = _mm256_and_ps(
        _mm256_and_ps(_mm256_cmp_ps(e0, margin, _CMP_LE_OQ), _mm256_cmp_ps(e1, margin, _CMP_LE_OQ)),
        _mm256_cmp_ps(e2, margin, _CMP_LE_OQ));
    FanVerdicts verdicts{
        static_cast<unsigned>(_mm256_movemask_ps(_mm256_or_ps(all_positive, all_negative))), 0u};
    if (verdicts.maybe != 0) {
        const __m256 surely_positive =
            _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(e0, margin, _CMP_GT_OQ),
                                        _mm256_cmp_ps(e1, margin, _CMP_GT_OQ)),
                          _mm256_cmp_ps(e2, margin, _CMP_GT_OQ));
        const __m256 surely_negative =
            _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(e0, negative_margin, _CMP_LT_OQ),
                                        _mm256_cmp_ps(e1, negative_margin, _CMP_LT_OQ)),
                          _mm256_cmp_ps(e2, negative_margin, _CMP_LT_OQ));
        verdicts.sure = static_cast<unsigned>(
            _mm256_movemask_ps(_mm256_or_ps(surely_positive, surely_negative)));
    }
    return verdicts;
}

/// fan_edge_verdicts' `maybe` alone.
__attribute__((target("avx2"))) inline unsigned fan_edge_candidates(const __m256 (&x)[3],
                                                                    const __m256 (&y)[3],
                                                                    __m256 size, __m256 edge_linear,
                                                                    __m256 edge_constant) {
    return fan_edge_verdicts(x, y, size, edge_linear, edge_constant).maybe;
}

/// Bits 0-3: fan_verdicts(first, ray); bits 4-7: fan_verdicts(second, ray).
__attribute__((target("avx2"))) inline FanVerdicts fan_pair_verdicts(const FanCorners& first,
                                                                     const FanCorners& second,
                                                                     const FloatRay& ray) {
    const __m256 ox = _mm256_set1_ps(ray.origin[ray.kx]);
    const __m256 oy = _mm256_set1_ps(ray.origin[ray.ky]);
    const __m256 oz = _mm256_set1_ps(ray.origin[ray.kz]);
    const __m256 sx = _mm256_set1_ps(ray.shear_x);
    const __m256 sy = _mm256_set1_ps(ray.shear_y);
    const __m256 sign = _mm256_set1_ps(-0.0f);
    __m256 x[3];
    __m256 y[3];
    __m256 size = _mm256_setzero_ps();
    for (int v = 0; v < 3; ++v) {
        const __m256 az = _mm256_sub_ps(load_fan_pair(first, second, v, ray.kz), oz);
        x[v] = fused::sub_mul(_mm256_sub_ps(load_fan_pair(first, second, v, ray.kx), ox), sx, az);
        y[v] = fused::sub_mul(_mm256_sub_ps(load_fan_pair(first, second, v, ray.ky), oy), sy, az);
        size = _mm256_max_ps(
            size, _mm256_max_ps(_mm256_andnot_ps(sign, x[v]), _mm256_andnot_ps(sign, y[v])));
    }
    return fan_edge_verdicts(x, y, size, _mm256_set1_ps(ray.edge_margin_linear),
                             _mm256_set1_ps(ray.edge_margin_constant));
}

/// fan_pair_verdicts' `maybe` alone: bits 0-3 fan_candidates(first, ray), bits 4-7
/// fan_candidates(second, ray).
__attribute__((target("avx2"))) inline unsigned fan_pair_candidates(const FanCorners& first,
                                                                    const FanCorners& second,
                                                                    const FloatRay& ray) {
    return fan_pair_verdicts(first, second, ray).maybe;
}

}  // namespace rt::bvh
#endif
