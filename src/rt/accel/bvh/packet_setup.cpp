// Each step mirrors FloatRay::FloatRay (float_ray_inl.h) operation for operation, in the same
// order, so that the results are bit for bit the same (tests/accel/bvh/bvh_packet_test.cpp
// checks it); a change there must be made here too.
#include "rt/accel/bvh/packet_setup.h"

#include <bit>
#include <cmath>
#include <cstdint>

#include "rt/accel/float_prefilter/float_ray.h"

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#define RT_PACKET_SETUP_AVX2 1
#endif

namespace rt::bvh {

FloatRay lane_float_ray(const PacketValues& v, int lane) {
    FloatRay ray;
    ray.usable = true;
    ray.scale_t = v.scale_t[lane];
    for (int k = 0; k < 3; ++k) {
        ray.origin[k] = v.origin[k][lane];
        ray.inverse[k] = v.inverse[k][lane];
        ray.slab_margin[k] = v.margin[k][lane];
        ray.negative |= (std::bit_cast<std::uint32_t>(ray.inverse[k]) >> 31U) << k;
    }
    ray.kx = v.kx[lane];
    ray.ky = v.ky[lane];
    ray.kz = v.kz[lane];
    ray.shear_x = v.shear_x[lane];
    ray.shear_y = v.shear_y[lane];
    ray.edge_margin_linear = v.edge_linear[lane];
    ray.edge_margin_constant = v.edge_constant[lane];
    return ray;
}

#ifdef RT_PACKET_SETUP_AVX2

namespace {

// next_up and next_down (core/next_up.h) for four floats that are finite (the only ones
// that can have been rounded the wrong way).
__attribute__((target("avx2"))) __m128 step_up(__m128 f, __m128 apply) {
    const __m128i bits = _mm_castps_si128(f);
    const __m128 zero = _mm_setzero_ps();
    const __m128i one = _mm_set1_epi32(1);
    __m128i stepped = _mm_castps_si128(_mm_blendv_ps(_mm_castsi128_ps(_mm_add_epi32(bits, one)),
                                                     _mm_castsi128_ps(_mm_sub_epi32(bits, one)),
                                                     _mm_cmplt_ps(f, zero)));
    // next_up(+-0) is the smallest denormal.
    stepped = _mm_castps_si128(
        _mm_blendv_ps(_mm_castsi128_ps(stepped), _mm_castsi128_ps(one), _mm_cmpeq_ps(f, zero)));
    return _mm_blendv_ps(f, _mm_castsi128_ps(stepped), apply);
}

// scaled_down (down = true) or scaled_up of four t, with the lanes' scale_t.
__attribute__((target("avx2"))) __m128 scaled_t(__m256d t, __m256d scale_t, bool down) {
    const __m256d x = _mm256_mul_pd(t, scale_t);
    const __m128 f = _mm256_cvtpd_ps(x);
    const __m256d back = _mm256_cvtps_pd(f);
    if (down) {
        const __m128 wrong = _mm256_cvtpd_ps(_mm256_cmp_pd(back, x, _CMP_GT_OQ));
        const __m128 negated = _mm_xor_ps(f, _mm_set1_ps(-0.0f));
        return _mm_xor_ps(step_up(negated, wrong), _mm_set1_ps(-0.0f));
    }
    return step_up(f, _mm256_cvtpd_ps(_mm256_cmp_pd(back, x, _CMP_LT_OQ)));
}

// Picks per lane: a where `first`, else b where `second`, else c.
__attribute__((target("avx2"))) inline __m256d pick(__m256d first, __m256d a, __m256d second,
                                                    __m256d b, __m256d c) {
    return _mm256_blendv_pd(_mm256_blendv_pd(c, b, second), a, first);
}

// The next axis of each 64-bit lane's k: k + 1, taking 3 off where that made 3. (Functions, not
// lambdas: a lambda does not take its enclosing function's target, so in a build for any x86-64
// CPU its AVX2 operations would not compile.)
__attribute__((target("avx2"))) inline __m256i next_axis(__m256i k) {
    const __m256i three = _mm256_set1_epi64x(3);
    const __m256i up = _mm256_add_epi64(k, _mm256_set1_epi64x(1));
    return _mm256_sub_epi64(up, _mm256_and_si256(_mm256_cmpeq_epi64(up, three), three));
}

// The low words of the four 64-bit lanes of k, stored as four ints at out.
__attribute__((target("avx2"))) inline void store_low_words(int* out, __m256i k) {
    const __m256i low_words = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out),
                     _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(k, low_words)));
}

// The four lanes' kx, ky and kz as set_up_four's masks pick kz (z0: x, z1: y, neither: z), and
// kx, ky after it, (kz + 1) % 3 and (kz + 2) % 3: in 64-bit lanes, stored as four ints each.
__attribute__((target("avx2"))) void store_axes(__m256d z0, __m256d z1, int first,
                                                PacketValues& v) {
    // The masks are -1 or 0 and never both -1: kz = 2 + 2 z0 + z1.
    const __m256i m0 = _mm256_castpd_si256(z0);
    const __m256i m1 = _mm256_castpd_si256(z1);
    const __m256i kz =
        _mm256_add_epi64(_mm256_set1_epi64x(2), _mm256_add_epi64(_mm256_add_epi64(m0, m0), m1));
    const __m256i kx = next_axis(kz);
    const __m256i ky = next_axis(kx);
    store_low_words(v.kz + first, kz);
    store_low_words(v.kx + first, kx);
    store_low_words(v.ky + first, ky);
}

// The four lanes' t.min and t.max: two loads of two Intervals each, regrouped.
__attribute__((target("avx2"))) void load_intervals(const Interval* t, __m256d& t_min,
                                                    __m256d& t_max) {
    static_assert(sizeof(Interval) == 2 * sizeof(double));
    const __m256d a = _mm256_loadu_pd(&t[0].min);  // min0 max0 min1 max1
    const __m256d b = _mm256_loadu_pd(&t[2].min);  // min2 max2 min3 max3
    t_min = _mm256_permute4x64_pd(_mm256_unpacklo_pd(a, b), 0xd8);
    t_max = _mm256_permute4x64_pd(_mm256_unpackhi_pd(a, b), 0xd8);
}

// Four lanes, starting at `first`, of FloatRay's values; returns the lanes (bits) that are
// usable and of ordinary exponent, and in `x_axis` and `y_axis` those whose kz is 0 and 1.
__attribute__((target("avx2"))) std::uint32_t set_up_four(const RayPacket& packet, int first,
                                                          double scene_scale, PacketValues& v,
                                                          std::uint32_t& x_axis,
                                                          std::uint32_t& y_axis) {
    const Ray* r = packet.rays.data() + first;
    __m256d o[3];
    __m256d d[3];
    for (int k = 0; k < 3; ++k) {
        o[k] = _mm256_setr_pd(r[0].origin[k], r[1].origin[k], r[2].origin[k], r[3].origin[k]);
        d[k] = _mm256_setr_pd(r[0].direction[k], r[1].direction[k], r[2].direction[k],
                              r[3].direction[k]);
    }
    const __m256d sign = _mm256_set1_pd(-0.0);
    const __m256d infinity = _mm256_set1_pd(HUGE_VAL);
    __m256d a[3];
    __m256d finite = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
    __m256d origin_size = _mm256_setzero_pd();
    for (int k = 0; k < 3; ++k) {
        a[k] = _mm256_andnot_pd(sign, d[k]);
        const __m256d ao = _mm256_andnot_pd(sign, o[k]);
        finite = _mm256_and_pd(finite, _mm256_and_pd(_mm256_cmp_pd(a[k], infinity, _CMP_LT_OQ),
                                                     _mm256_cmp_pd(ao, infinity, _CMP_LT_OQ)));
        // std::max keeps its first operand unless the second is larger (NaN lanes are unusable).
        origin_size =
            k == 0 ? ao
                   : _mm256_blendv_pd(origin_size, ao, _mm256_cmp_pd(origin_size, ao, _CMP_LT_OQ));
    }
    __m256d largest = a[0];
    largest = _mm256_blendv_pd(largest, a[1], _mm256_cmp_pd(largest, a[1], _CMP_LT_OQ));
    largest = _mm256_blendv_pd(largest, a[2], _mm256_cmp_pd(largest, a[2], _CMP_LT_OQ));
    const __m256d m = _mm256_add_pd(_mm256_set1_pd(scene_scale), origin_size);
    // The exponent of `largest`, and whether it lies within FloatRay's bit-work range.
    const __m256i bits = _mm256_castpd_si256(largest);
    const __m256i exponent =
        _mm256_sub_epi64(_mm256_and_si256(_mm256_srli_epi64(bits, 52), _mm256_set1_epi64x(0x7ff)),
                         _mm256_set1_epi64x(1023));
    const __m256i ordinary =
        _mm256_andnot_si256(_mm256_or_si256(_mm256_cmpgt_epi64(_mm256_set1_epi64x(-1000), exponent),
                                            _mm256_cmpgt_epi64(exponent, _mm256_set1_epi64x(1000))),
                            _mm256_set1_epi64x(-1));
    const __m256d usable = _mm256_and_pd(
        _mm256_and_pd(finite, _mm256_cmp_pd(largest, _mm256_setzero_pd(), _CMP_GT_OQ)),
        _mm256_and_pd(_mm256_cmp_pd(m, _mm256_set1_pd(0x1p-40), _CMP_GE_OQ),
                      _mm256_cmp_pd(m, _mm256_set1_pd(0x1p40), _CMP_LE_OQ)));
    const auto lanes = static_cast<std::uint32_t>(
        _mm256_movemask_pd(_mm256_and_pd(usable, _mm256_castsi256_pd(ordinary))));
    const __m256d shrink = _mm256_castsi256_pd(
        _mm256_slli_epi64(_mm256_sub_epi64(_mm256_set1_epi64x(1023), exponent), 52));
    const __m256d scale_t = _mm256_castsi256_pd(
        _mm256_slli_epi64(_mm256_add_epi64(_mm256_set1_epi64x(1023), exponent), 52));
    _mm256_storeu_pd(v.scale_t + first, scale_t);
    const __m256d slack = _mm256_set1_pd(1.0 + 0x1p-20);
    const __m256d eps = _mm256_mul_pd(_mm256_set1_pd(0x1p-20), m);
    __m256d scaled[3];
    __m256d inverse[3];
    for (int k = 0; k < 3; ++k) {
        scaled[k] = _mm256_mul_pd(d[k], shrink);
        __m256d inv = _mm256_div_pd(_mm256_set1_pd(1.0), scaled[k]);
        const __m256d limit = _mm256_set1_pd(0x1p60);
        const __m256d within = _mm256_cmp_pd(_mm256_andnot_pd(sign, inv), limit, _CMP_LE_OQ);
        inv = _mm256_blendv_pd(_mm256_or_pd(limit, _mm256_and_pd(sign, scaled[k])), inv, within);
        inverse[k] = inv;
        _mm_storeu_ps(v.origin[k] + first, _mm256_cvtpd_ps(o[k]));
        _mm_storeu_ps(v.inverse[k] + first, _mm256_cvtpd_ps(inv));
        const __m256d margin =
            _mm256_mul_pd(_mm256_mul_pd(eps, _mm256_andnot_pd(sign, inv)), slack);
        _mm_storeu_ps(v.margin[k] + first, _mm256_cvtpd_ps(margin));
    }
    const __m256d eight_eps = _mm256_mul_pd(_mm256_set1_pd(8.0), eps);
    _mm_storeu_ps(v.edge_linear + first, _mm256_cvtpd_ps(_mm256_mul_pd(eight_eps, slack)));
    _mm_storeu_ps(v.edge_constant + first,
                  _mm256_cvtpd_ps(_mm256_mul_pd(_mm256_mul_pd(eight_eps, eps), slack)));
    // kz = (ax > ay) ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2); kx, ky follow it.
    const __m256d x_over_y = _mm256_cmp_pd(a[0], a[1], _CMP_GT_OQ);
    const __m256d z0 = _mm256_and_pd(x_over_y, _mm256_cmp_pd(a[0], a[2], _CMP_GT_OQ));
    const __m256d z1 = _mm256_andnot_pd(x_over_y, _mm256_cmp_pd(a[1], a[2], _CMP_GT_OQ));
    const __m256d inverse_z = pick(z0, inverse[0], z1, inverse[1], inverse[2]);
    const __m256d scaled_x = pick(z0, scaled[1], z1, scaled[2], scaled[0]);
    const __m256d scaled_y = pick(z0, scaled[2], z1, scaled[0], scaled[1]);
    _mm_storeu_ps(v.shear_x + first, _mm256_cvtpd_ps(_mm256_mul_pd(scaled_x, inverse_z)));
    _mm_storeu_ps(v.shear_y + first, _mm256_cvtpd_ps(_mm256_mul_pd(scaled_y, inverse_z)));
    store_axes(z0, z1, first, v);
    x_axis = static_cast<std::uint32_t>(_mm256_movemask_pd(z0)) << first;
    y_axis = static_cast<std::uint32_t>(_mm256_movemask_pd(z1)) << first;
    __m256d t_min;
    __m256d t_max;
    load_intervals(packet.t.data() + first, t_min, t_max);
    _mm_storeu_ps(v.t_min + first, scaled_t(t_min, scale_t, true));
    _mm_storeu_ps(v.t_max + first, scaled_t(t_max, scale_t, false));
    return lanes << first;
}

// The AVX-512 form: set_up_four's steps for all eight lanes at once, in the same order per lane,
// with masks where set_up_four has all-ones lanes. About half the instructions; used where the CPU
// has AVX-512 (set_up_packet).
#define RT_AVX512_TARGET __attribute__((target("avx2,fma,avx512f,avx512dq")))
// GCC 12's AVX-512 intrinsics start their unused destinations as `__Y = __Y` (GCC bug 105593).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"

// step_up for eight floats, `apply` a lane mask.
RT_AVX512_TARGET __m256 step_up_eight(__m256 f, __mmask8 apply) {
    const __m256i bits = _mm256_castps_si256(f);
    const __m256 zero = _mm256_setzero_ps();
    const __m256i one = _mm256_set1_epi32(1);
    __m256i stepped = _mm256_castps_si256(_mm256_blendv_ps(
        _mm256_castsi256_ps(_mm256_add_epi32(bits, one)),
        _mm256_castsi256_ps(_mm256_sub_epi32(bits, one)), _mm256_cmp_ps(f, zero, _CMP_LT_OQ)));
    stepped =
        _mm256_castps_si256(_mm256_blendv_ps(_mm256_castsi256_ps(stepped), _mm256_castsi256_ps(one),
                                             _mm256_cmp_ps(f, zero, _CMP_EQ_OQ)));
    const __m256 where =
        _mm512_cvtpd_ps(_mm512_castsi512_pd(_mm512_maskz_mov_epi64(apply, _mm512_set1_epi64(-1))));
    return _mm256_blendv_ps(f, _mm256_castsi256_ps(stepped), where);
}

// scaled_t for eight t.
RT_AVX512_TARGET __m256 scaled_t_eight(__m512d t, __m512d scale_t, bool down) {
    const __m512d x = _mm512_mul_pd(t, scale_t);
    const __m256 f = _mm512_cvtpd_ps(x);
    const __m512d back = _mm512_cvtps_pd(f);
    if (down) {
        const __m256 sign = _mm256_set1_ps(-0.0f);
        return _mm256_xor_ps(
            step_up_eight(_mm256_xor_ps(f, sign), _mm512_cmp_pd_mask(back, x, _CMP_GT_OQ)), sign);
    }
    return step_up_eight(f, _mm512_cmp_pd_mask(back, x, _CMP_LT_OQ));
}

// pick for eight lanes: a where `first`, else b where `second`, else c.
RT_AVX512_TARGET inline __m512d pick_eight(__mmask8 first, __m512d a, __mmask8 second, __m512d b,
                                           __m512d c) {
    return _mm512_mask_blend_pd(first, _mm512_mask_blend_pd(second, c, b), a);
}

// An axis for each lane: a where `first`, else b where `second`, else c, stored as eight ints.
RT_AVX512_TARGET inline void store_axis_eight(int* out, __mmask8 first, int a, __mmask8 second,
                                              int b, int c) {
    const __m512i k = _mm512_mask_blend_epi64(
        first, _mm512_mask_blend_epi64(second, _mm512_set1_epi64(c), _mm512_set1_epi64(b)),
        _mm512_set1_epi64(a));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), _mm512_cvtepi64_epi32(k));
}

// The eight rays' origins, directions and the directions' absolute values, and the lanes whose
// FloatRay is usable and whose largest component is of ordinary exponent (set_up_four's first
// steps): that exponent, and the scene's scale plus the origin's largest |component|, in `m`.
RT_AVX512_TARGET std::uint32_t usable_eight(const RayPacket& packet, double scene_scale, __m512d* o,
                                            __m512d* d, __m512d* a, __m512i& exponent, __m512d& m) {
    const Ray* r = packet.rays.data();
    for (int k = 0; k < 3; ++k) {
        o[k] = _mm512_setr_pd(r[0].origin[k], r[1].origin[k], r[2].origin[k], r[3].origin[k],
                              r[4].origin[k], r[5].origin[k], r[6].origin[k], r[7].origin[k]);
        d[k] = _mm512_setr_pd(r[0].direction[k], r[1].direction[k], r[2].direction[k],
                              r[3].direction[k], r[4].direction[k], r[5].direction[k],
                              r[6].direction[k], r[7].direction[k]);
    }
    const __m512d infinity = _mm512_set1_pd(HUGE_VAL);
    __mmask8 finite = 0xff;
    __m512d origin_size = _mm512_setzero_pd();
    for (int k = 0; k < 3; ++k) {
        a[k] = _mm512_abs_pd(d[k]);
        const __m512d ao = _mm512_abs_pd(o[k]);
        finite &= _mm512_cmp_pd_mask(a[k], infinity, _CMP_LT_OQ) &
                  _mm512_cmp_pd_mask(ao, infinity, _CMP_LT_OQ);
        origin_size = k == 0 ? ao
                             : _mm512_mask_blend_pd(_mm512_cmp_pd_mask(origin_size, ao, _CMP_LT_OQ),
                                                    origin_size, ao);
    }
    __m512d largest = a[0];
    largest = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(largest, a[1], _CMP_LT_OQ), largest, a[1]);
    largest = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(largest, a[2], _CMP_LT_OQ), largest, a[2]);
    m = _mm512_add_pd(_mm512_set1_pd(scene_scale), origin_size);
    const __m512i bits = _mm512_castpd_si512(largest);
    exponent =
        _mm512_sub_epi64(_mm512_and_si512(_mm512_srli_epi64(bits, 52), _mm512_set1_epi64(0x7ff)),
                         _mm512_set1_epi64(1023));
    const __mmask8 ordinary =
        static_cast<__mmask8>(~(_mm512_cmpgt_epi64_mask(_mm512_set1_epi64(-1000), exponent) |
                                _mm512_cmpgt_epi64_mask(exponent, _mm512_set1_epi64(1000))));
    const __mmask8 usable = finite & _mm512_cmp_pd_mask(largest, _mm512_setzero_pd(), _CMP_GT_OQ) &
                            _mm512_cmp_pd_mask(m, _mm512_set1_pd(0x1p-40), _CMP_GE_OQ) &
                            _mm512_cmp_pd_mask(m, _mm512_set1_pd(0x1p40), _CMP_LE_OQ);
    return static_cast<std::uint32_t>(usable & ordinary);
}

// set_up_four for the eight lanes; returns the usable lanes of ordinary exponent, and in
// `x_axis` and `y_axis` those whose kz is 0 and 1.
RT_AVX512_TARGET std::uint32_t set_up_eight(const RayPacket& packet, double scene_scale,
                                            PacketValues& v, std::uint32_t& x_axis,
                                            std::uint32_t& y_axis) {
    __m512d o[3];
    __m512d d[3];
    __m512d a[3];
    __m512i exponent;
    __m512d m;
    const std::uint32_t lanes = usable_eight(packet, scene_scale, o, d, a, exponent, m);
    const __m512d shrink = _mm512_castsi512_pd(
        _mm512_slli_epi64(_mm512_sub_epi64(_mm512_set1_epi64(1023), exponent), 52));
    const __m512d scale_t = _mm512_castsi512_pd(
        _mm512_slli_epi64(_mm512_add_epi64(_mm512_set1_epi64(1023), exponent), 52));
    _mm512_storeu_pd(v.scale_t, scale_t);
    const __m512d slack = _mm512_set1_pd(1.0 + 0x1p-20);
    const __m512d eps = _mm512_mul_pd(_mm512_set1_pd(0x1p-20), m);
    const __m512i sign = _mm512_set1_epi64(static_cast<long long>(0x8000000000000000ULL));
    __m512d scaled[3];
    __m512d inverse[3];
    for (int k = 0; k < 3; ++k) {
        scaled[k] = _mm512_mul_pd(d[k], shrink);
        __m512d inv = _mm512_div_pd(_mm512_set1_pd(1.0), scaled[k]);
        const __m512d limit = _mm512_set1_pd(0x1p60);
        const __mmask8 within = _mm512_cmp_pd_mask(_mm512_abs_pd(inv), limit, _CMP_LE_OQ);
        const __m512d clamped = _mm512_castsi512_pd(_mm512_or_si512(
            _mm512_castpd_si512(limit), _mm512_and_si512(sign, _mm512_castpd_si512(scaled[k]))));
        inv = _mm512_mask_blend_pd(within, clamped, inv);
        inverse[k] = inv;
        _mm256_storeu_ps(v.origin[k], _mm512_cvtpd_ps(o[k]));
        _mm256_storeu_ps(v.inverse[k], _mm512_cvtpd_ps(inv));
        const __m512d margin = _mm512_mul_pd(_mm512_mul_pd(eps, _mm512_abs_pd(inv)), slack);
        _mm256_storeu_ps(v.margin[k], _mm512_cvtpd_ps(margin));
    }
    const __m512d eight_eps = _mm512_mul_pd(_mm512_set1_pd(8.0), eps);
    _mm256_storeu_ps(v.edge_linear, _mm512_cvtpd_ps(_mm512_mul_pd(eight_eps, slack)));
    _mm256_storeu_ps(v.edge_constant,
                     _mm512_cvtpd_ps(_mm512_mul_pd(_mm512_mul_pd(eight_eps, eps), slack)));
    const __mmask8 x_over_y = _mm512_cmp_pd_mask(a[0], a[1], _CMP_GT_OQ);
    const __mmask8 z0 = x_over_y & _mm512_cmp_pd_mask(a[0], a[2], _CMP_GT_OQ);
    const __mmask8 z1 =
        static_cast<__mmask8>(~x_over_y) & _mm512_cmp_pd_mask(a[1], a[2], _CMP_GT_OQ);
    const __m512d inverse_z = pick_eight(z0, inverse[0], z1, inverse[1], inverse[2]);
    const __m512d scaled_x = pick_eight(z0, scaled[1], z1, scaled[2], scaled[0]);
    const __m512d scaled_y = pick_eight(z0, scaled[2], z1, scaled[0], scaled[1]);
    _mm256_storeu_ps(v.shear_x, _mm512_cvtpd_ps(_mm512_mul_pd(scaled_x, inverse_z)));
    _mm256_storeu_ps(v.shear_y, _mm512_cvtpd_ps(_mm512_mul_pd(scaled_y, inverse_z)));
    // kz 0: kx 1, ky 2; kz 1: kx 2, ky 0; kz 2: kx 0, ky 1.
    store_axis_eight(v.kz, z0, 0, z1, 1, 2);
    store_axis_eight(v.kx, z0, 1, z1, 2, 0);
    store_axis_eight(v.ky, z0, 2, z1, 0, 1);
    x_axis = z0;
    y_axis = z1;
    // The intervals, min0 max0 min1 max1 ...: evens and odds.
    static_assert(sizeof(Interval) == 2 * sizeof(double));
    const __m512d low = _mm512_loadu_pd(&packet.t[0].min);
    const __m512d high = _mm512_loadu_pd(&packet.t[4].min);
    const __m512d t_min =
        _mm512_permutex2var_pd(low, _mm512_setr_epi64(0, 2, 4, 6, 8, 10, 12, 14), high);
    const __m512d t_max =
        _mm512_permutex2var_pd(low, _mm512_setr_epi64(1, 3, 5, 7, 9, 11, 13, 15), high);
    _mm256_storeu_ps(v.t_min, scaled_t_eight(t_min, scale_t, true));
    _mm256_storeu_ps(v.t_max, scaled_t_eight(t_max, scale_t, false));
    return lanes;
}

#pragma GCC diagnostic pop

const bool cpu_has_avx512 =
    __builtin_cpu_supports("avx512f") != 0 && __builtin_cpu_supports("avx512dq") != 0;

}  // namespace

bool set_up_path_available(SetUpPath path) {
    return path != SetUpPath::EightLanes || cpu_has_avx512;
}

__attribute__((target("avx2"))) std::uint32_t set_up_packet(const RayPacket& packet,
                                                            double scene_scale, PacketValues& v,
                                                            SetUpPath path) {
    std::uint32_t x_axis = 0;
    std::uint32_t y_axis = 0;
    std::uint32_t lanes = 0;
    if (path == SetUpPath::EightLanes || (path == SetUpPath::Best && cpu_has_avx512)) {
        lanes = set_up_eight(packet, scene_scale, v, x_axis, y_axis);
    } else {
        std::uint32_t x_high = 0;
        std::uint32_t y_high = 0;
        lanes = set_up_four(packet, 0, scene_scale, v, x_axis, y_axis) |
                set_up_four(packet, 4, scene_scale, v, x_high, y_high);
        x_axis |= x_high;
        y_axis |= y_high;
    }
    lanes &= packet.active & 0xffu;
    // Every set-up lane in the same axes: kz is 0 for all or none of them, and 1 for all or none.
    const auto all_or_none = [lanes](std::uint32_t bits) {
        const std::uint32_t in = bits & lanes;
        return in == 0 || in == lanes;
    };
    v.same_axes = all_or_none(x_axis) && all_or_none(y_axis);
    return lanes;
}

#else

bool set_up_path_available(SetUpPath path) {
    return path == SetUpPath::Best;
}

std::uint32_t set_up_packet(const RayPacket& /*packet*/, double /*scene_scale*/,
                            PacketValues& /*v*/, SetUpPath /*path*/) {
    return 0;
}

#endif

}  // namespace rt::bvh
