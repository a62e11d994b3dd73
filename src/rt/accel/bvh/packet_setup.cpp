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

float lane_scaled_down(const PacketValues& v, int lane, double t) {
    return float_below(t * v.scale_t[lane]);
}

float lane_scaled_up(const PacketValues& v, int lane, double t) {
    return float_above(t * v.scale_t[lane]);
}

#ifdef RT_PACKET_SETUP_AVX2

namespace {

// next_float_up and next_float_down (float_ray.h) for four floats that are finite (the only ones
// that can have been rounded the wrong way).
__attribute__((target("avx2"))) __m128 step_up(__m128 f, __m128 apply) {
    const __m128i bits = _mm_castps_si128(f);
    const __m128 zero = _mm_setzero_ps();
    const __m128i one = _mm_set1_epi32(1);
    __m128i stepped = _mm_castps_si128(_mm_blendv_ps(_mm_castsi128_ps(_mm_add_epi32(bits, one)),
                                                     _mm_castsi128_ps(_mm_sub_epi32(bits, one)),
                                                     _mm_cmplt_ps(f, zero)));
    // next_float_up(+-0) is the smallest denormal.
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

}  // namespace

__attribute__((target("avx2"))) std::uint32_t set_up_packet(const RayPacket& packet,
                                                            double scene_scale, PacketValues& v) {
    std::uint32_t x_low = 0;
    std::uint32_t y_low = 0;
    std::uint32_t x_high = 0;
    std::uint32_t y_high = 0;
    const std::uint32_t lanes = (set_up_four(packet, 0, scene_scale, v, x_low, y_low) |
                                 set_up_four(packet, 4, scene_scale, v, x_high, y_high)) &
                                packet.active & 0xffu;
    // Every set-up lane in the same axes: kz is 0 for all or none of them, and 1 for all or none.
    const auto all_or_none = [lanes](std::uint32_t bits) {
        const std::uint32_t in = bits & lanes;
        return in == 0 || in == lanes;
    };
    v.same_axes = all_or_none(x_low | x_high) && all_or_none(y_low | y_high);
    return lanes;
}

#else

std::uint32_t set_up_packet(const RayPacket& /*packet*/, double /*scene_scale*/,
                            PacketValues& /*v*/) {
    return 0;
}

#endif

}  // namespace rt::bvh
