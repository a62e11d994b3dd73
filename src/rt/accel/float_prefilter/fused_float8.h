// Multiply-and-add steps of the eight-lane float pre-filters (the BVH's box and triangle tests,
// the voxel methods' cell packets), fused into one instruction where the build has FMA (CMake's
// RT_AVX2, cmake/RtCpu.cmake) and two operations otherwise. A fused step rounds once where the
// two round twice, so every error bound of float_ray.cpp holds either way: those bounds count one
// rounding per operation, and a fused step's single rounding is within them. The pre-filters only
// reject what the exact test could not hit, and the exact test (double, never fused: the
// project builds with -ffp-contract=off) decides every hit, so the pictures do not depend on it.
// The BVH's single rays gain 3-20 % from it (docs/accelerators.md, "Fused steps in the float
// pre-filters").
#pragma once

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))

#include <immintrin.h>

namespace rt::fused {

/// a * b - c.
__attribute__((target("avx2"), always_inline)) inline __m256 mul_sub(__m256 a, __m256 b, __m256 c) {
#ifdef __FMA__
    return _mm256_fmsub_ps(a, b, c);
#else
    return _mm256_sub_ps(_mm256_mul_ps(a, b), c);
#endif
}

/// a * b + c.
__attribute__((target("avx2"), always_inline)) inline __m256 mul_add(__m256 a, __m256 b, __m256 c) {
#ifdef __FMA__
    return _mm256_fmadd_ps(a, b, c);
#else
    return _mm256_add_ps(_mm256_mul_ps(a, b), c);
#endif
}

/// c - a * b.
__attribute__((target("avx2"), always_inline)) inline __m256 sub_mul(__m256 c, __m256 a, __m256 b) {
#ifdef __FMA__
    return _mm256_fnmadd_ps(a, b, c);
#else
    return _mm256_sub_ps(c, _mm256_mul_ps(a, b));
#endif
}

}  // namespace rt::fused

#endif
