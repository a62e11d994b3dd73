// Four floats operated on at once: the BVH tests four boxes, or four triangles, per step. SSE2
// (which every x86-64 has) when the compiler targets it, else plain arrays with the same meaning,
// so the BVH builds and answers identically everywhere. No operation here may produce a NaN from
// finite inputs except 0 * inf and inf - inf, which the callers are written never to form.
#pragma once

#include <cstdint>
#include <cstring>

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define RT_FLOAT4_SSE2 1
#ifdef __FMA__
#include <immintrin.h>
#endif
#else
#include <algorithm>
#include <cmath>
#endif

namespace rt::simd {

#if RT_FLOAT4_SSE2

struct Float4 {
    __m128 v;
    static Float4 load(const float* p) { return {_mm_loadu_ps(p)}; }
    static Float4 broadcast(float x) { return {_mm_set1_ps(x)}; }
    void store(float* p) const { _mm_storeu_ps(p, v); }
};

/// Per lane: all bits set (true) or clear (false).
struct Mask4 {
    __m128 v;
    /// Bit k set when lane k is true.
    int bits() const { return _mm_movemask_ps(v); }
};

inline Float4 operator+(Float4 a, Float4 b) {
    return {_mm_add_ps(a.v, b.v)};
}
inline Float4 operator-(Float4 a, Float4 b) {
    return {_mm_sub_ps(a.v, b.v)};
}
inline Float4 operator*(Float4 a, Float4 b) {
    return {_mm_mul_ps(a.v, b.v)};
}
inline Float4 min(Float4 a, Float4 b) {
    return {_mm_min_ps(a.v, b.v)};
}
inline Float4 max(Float4 a, Float4 b) {
    return {_mm_max_ps(a.v, b.v)};
}
inline Float4 abs(Float4 a) {
    return {_mm_and_ps(a.v, _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff)))};
}
inline Mask4 operator<=(Float4 a, Float4 b) {
    return {_mm_cmple_ps(a.v, b.v)};
}
inline Mask4 operator>=(Float4 a, Float4 b) {
    return {_mm_cmpge_ps(a.v, b.v)};
}
inline Mask4 operator<(Float4 a, Float4 b) {
    return {_mm_cmplt_ps(a.v, b.v)};
}
inline Mask4 operator>(Float4 a, Float4 b) {
    return {_mm_cmpgt_ps(a.v, b.v)};
}
inline Mask4 operator&(Mask4 a, Mask4 b) {
    return {_mm_and_ps(a.v, b.v)};
}
inline Mask4 operator|(Mask4 a, Mask4 b) {
    return {_mm_or_ps(a.v, b.v)};
}

// a * b - c, c - a * b and a * b + c: one fused step where the build has FMA, as in the eight-lane
// pre-filters (accel/float_prefilter/fused_float8.h says why a pre-filter may fuse), so that the
// four-lane and eight-lane triangle tests answer alike.
inline Float4 mul_sub(Float4 a, Float4 b, Float4 c) {
#ifdef __FMA__
    return {_mm_fmsub_ps(a.v, b.v, c.v)};
#else
    return a * b - c;
#endif
}
inline Float4 sub_mul(Float4 c, Float4 a, Float4 b) {
#ifdef __FMA__
    return {_mm_fnmadd_ps(a.v, b.v, c.v)};
#else
    return c - a * b;
#endif
}
inline Float4 mul_add(Float4 a, Float4 b, Float4 c) {
#ifdef __FMA__
    return {_mm_fmadd_ps(a.v, b.v, c.v)};
#else
    return a * b + c;
#endif
}

#else

struct Float4 {
    float v[4];
    static Float4 load(const float* p) {
        Float4 r;
        std::memcpy(r.v, p, sizeof r.v);
        return r;
    }
    static Float4 broadcast(float x) { return {{x, x, x, x}}; }
    void store(float* p) const { std::memcpy(p, v, sizeof v); }
};

struct Mask4 {
    bool v[4];
    int bits() const { return v[0] | (v[1] << 1) | (v[2] << 2) | (v[3] << 3); }
};

template <class Op>
inline Float4 lanewise(Float4 a, Float4 b, Op op) {
    return {{op(a.v[0], b.v[0]), op(a.v[1], b.v[1]), op(a.v[2], b.v[2]), op(a.v[3], b.v[3])}};
}
template <class Op>
inline Mask4 compare(Float4 a, Float4 b, Op op) {
    return {{op(a.v[0], b.v[0]), op(a.v[1], b.v[1]), op(a.v[2], b.v[2]), op(a.v[3], b.v[3])}};
}
inline Float4 operator+(Float4 a, Float4 b) {
    return lanewise(a, b, [](float x, float y) { return x + y; });
}
inline Float4 operator-(Float4 a, Float4 b) {
    return lanewise(a, b, [](float x, float y) { return x - y; });
}
inline Float4 operator*(Float4 a, Float4 b) {
    return lanewise(a, b, [](float x, float y) { return x * y; });
}
// The SSE2 meaning: the second operand when the comparison fails (NaN included).
inline Float4 min(Float4 a, Float4 b) {
    return lanewise(a, b, [](float x, float y) { return x < y ? x : y; });
}
inline Float4 max(Float4 a, Float4 b) {
    return lanewise(a, b, [](float x, float y) { return x > y ? x : y; });
}
inline Float4 abs(Float4 a) {
    return {{std::fabs(a.v[0]), std::fabs(a.v[1]), std::fabs(a.v[2]), std::fabs(a.v[3])}};
}
inline Mask4 operator<=(Float4 a, Float4 b) {
    return compare(a, b, [](float x, float y) { return x <= y; });
}
inline Mask4 operator>=(Float4 a, Float4 b) {
    return compare(a, b, [](float x, float y) { return x >= y; });
}
inline Mask4 operator<(Float4 a, Float4 b) {
    return compare(a, b, [](float x, float y) { return x < y; });
}
inline Mask4 operator>(Float4 a, Float4 b) {
    return compare(a, b, [](float x, float y) { return x > y; });
}
inline Mask4 operator&(Mask4 a, Mask4 b) {
    return {{a.v[0] && b.v[0], a.v[1] && b.v[1], a.v[2] && b.v[2], a.v[3] && b.v[3]}};
}
inline Mask4 operator|(Mask4 a, Mask4 b) {
    return {{a.v[0] || b.v[0], a.v[1] || b.v[1], a.v[2] || b.v[2], a.v[3] || b.v[3]}};
}

// Plain arrays: never fused.
inline Float4 mul_sub(Float4 a, Float4 b, Float4 c) {
    return a * b - c;
}
inline Float4 sub_mul(Float4 c, Float4 a, Float4 b) {
    return c - a * b;
}
inline Float4 mul_add(Float4 a, Float4 b, Float4 c) {
    return a * b + c;
}

#endif

}  // namespace rt::simd
