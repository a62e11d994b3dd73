// Each step mirrors FloatRay::FloatRay (float_ray.cpp) operation for operation, in the same
// order, so that the results are bit for bit the same (tests/accel/bvh/bvh_packet_test.cpp
// checks it); a change there must be made here too.
#include "rt/accel/bvh/packet_setup.h"

#include <bit>
#include <cmath>
#include <limits>

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#define RT_PACKET_SETUP_AVX2 1
#endif

namespace rt::bvh {

namespace {

float next_up(float f) {
    if (!(f < HUGE_VALF)) {
        return f;
    }
    if (f == 0.0f) {
        return std::numeric_limits<float>::denorm_min();
    }
    const auto bits = std::bit_cast<std::uint32_t>(f);
    return std::bit_cast<float>(f > 0.0f ? bits + 1 : bits - 1);
}

float next_down(float f) {
    return -next_up(-f);
}

}  // namespace

float lane_scaled_down(const PacketValues& v, int lane, double t) {
    const double x = t * v.scale_t[lane];
    const auto f = static_cast<float>(x);
    return static_cast<double>(f) > x ? next_down(f) : f;
}

float lane_scaled_up(const PacketValues& v, int lane, double t) {
    const double x = t * v.scale_t[lane];
    const auto f = static_cast<float>(x);
    return static_cast<double>(f) < x ? next_up(f) : f;
}

#ifdef RT_PACKET_SETUP_AVX2

namespace {

// Four lanes, starting at `first`, of FloatRay's box values; returns the lanes (bits) that are
// usable and of ordinary exponent.
__attribute__((target("avx2"))) std::uint32_t set_up_four(const RayPacket& packet, int first,
                                                          double scene_scale, PacketValues& v,
                                                          double (*scaled)[8], double (*inverse)[8],
                                                          double* size) {
    alignas(32) double o[3][4];
    alignas(32) double d[3][4];
    for (int i = 0; i < 4; ++i) {
        const Ray& r = packet.rays[first + i];
        for (int k = 0; k < 3; ++k) {
            o[k][i] = r.origin[k];
            d[k][i] = r.direction[k];
        }
    }
    const __m256d sign = _mm256_set1_pd(-0.0);
    const __m256d infinity = _mm256_set1_pd(HUGE_VAL);
    __m256d a[3];
    __m256d finite = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
    __m256d origin_size = _mm256_setzero_pd();
    for (int k = 0; k < 3; ++k) {
        a[k] = _mm256_andnot_pd(sign, _mm256_load_pd(d[k]));
        const __m256d ao = _mm256_andnot_pd(sign, _mm256_load_pd(o[k]));
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
    for (int k = 0; k < 3; ++k) {
        const __m256d s = _mm256_mul_pd(_mm256_load_pd(d[k]), shrink);
        __m256d inv = _mm256_div_pd(_mm256_set1_pd(1.0), s);
        const __m256d limit = _mm256_set1_pd(0x1p60);
        const __m256d within = _mm256_cmp_pd(_mm256_andnot_pd(sign, inv), limit, _CMP_LE_OQ);
        inv = _mm256_blendv_pd(_mm256_or_pd(limit, _mm256_and_pd(sign, s)), inv, within);
        _mm256_storeu_pd(scaled[k] + first, s);
        _mm256_storeu_pd(inverse[k] + first, inv);
        _mm_storeu_ps(v.origin[k] + first, _mm256_cvtpd_ps(_mm256_load_pd(o[k])));
        _mm_storeu_ps(v.inverse[k] + first, _mm256_cvtpd_ps(inv));
        const __m256d margin =
            _mm256_mul_pd(_mm256_mul_pd(eps, _mm256_andnot_pd(sign, inv)), slack);
        _mm_storeu_ps(v.margin[k] + first, _mm256_cvtpd_ps(margin));
    }
    const __m256d eight_eps = _mm256_mul_pd(_mm256_set1_pd(8.0), eps);
    _mm_storeu_ps(v.edge_linear + first, _mm256_cvtpd_ps(_mm256_mul_pd(eight_eps, slack)));
    _mm_storeu_ps(v.edge_constant + first,
                  _mm256_cvtpd_ps(_mm256_mul_pd(_mm256_mul_pd(eight_eps, eps), slack)));
    for (int k = 0; k < 3; ++k) {
        _mm256_storeu_pd(size + 4 * k, a[k]);
    }
    return lanes << first;
}

}  // namespace

__attribute__((target("avx2"))) std::uint32_t set_up_packet(const RayPacket& packet,
                                                            double scene_scale, PacketValues& v) {
    double scaled[3][8];
    double inverse[3][8];
    double size[2][12];  // |direction| [axis * 4 + lane] of each half
    std::uint32_t lanes = set_up_four(packet, 0, scene_scale, v, scaled, inverse, size[0]) |
                          set_up_four(packet, 4, scene_scale, v, scaled, inverse, size[1]);
    lanes &= packet.active & 0xffu;
    v.same_axes = true;
    int common = -1;
    for (int lane = 0; lane < kPacketSize; ++lane) {
        const double* a = size[lane >> 2] + (lane & 3);
        const double ax = a[0];
        const double ay = a[4];
        const double az = a[8];
        const int kz = (ax > ay) ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        const int kx = (kz + 1) % 3;
        const int ky = (kx + 1) % 3;
        v.kx[lane] = kx;
        v.ky[lane] = ky;
        v.kz[lane] = kz;
        v.shear_x[lane] = static_cast<float>(scaled[kx][lane] * inverse[kz][lane]);
        v.shear_y[lane] = static_cast<float>(scaled[ky][lane] * inverse[kz][lane]);
        if (((lanes >> lane) & 1u) != 0) {
            v.same_axes = v.same_axes && (common < 0 || common == kz);
            common = kz;
            v.t_min[lane] = lane_scaled_down(v, lane, packet.t[lane].min);
            v.t_max[lane] = lane_scaled_up(v, lane, packet.t[lane].max);
        }
    }
    return lanes;
}

#else

std::uint32_t set_up_packet(const RayPacket& /*packet*/, double /*scene_scale*/,
                            PacketValues& /*v*/) {
    return 0;
}

#endif

}  // namespace rt::bvh
