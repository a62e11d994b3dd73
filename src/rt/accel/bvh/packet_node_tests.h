// The packet walk's node tests (bvh_packet_traversal.cpp): a node's eight boxes against the
// whole packet at once (interval arithmetic over its lanes), then against each lane (the slab
// test's packet form, lane for lane). AVX2 functions, for x86 compilers that take target
// attributes.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "rt/accel/bvh/bvh_layout.h"
#include "rt/accel/bvh/packet_setup.h"
#include "rt/accel/float_prefilter/float_ray.h"

#include <immintrin.h>

namespace rt::bvh::packet {

// The node layout as the packet walk reads it; bvh_layout.h may change under these.
inline const WideNode& inner_node(const Hierarchy& tree, std::uint32_t child) {
    return tree.wide[child];
}
/// The eight children's lower (upper) planes on an axis, 32-byte aligned.
inline const float* lower_planes(const WideNode& node, int axis) {
    return node.lo[axis];
}
inline const float* upper_planes(const WideNode& node, int axis) {
    return node.hi[axis];
}
inline float child_lo(const WideNode& node, int axis, int k) {
    return node.lo[axis][k];
}
inline float child_hi(const WideNode& node, int axis, int k) {
    return node.hi[axis][k];
}
inline std::uint32_t child_word(const WideNode& node, int k) {
    return node.child[k];
}
constexpr int kNodeWidth = 8;
inline std::uint32_t first_packet(std::uint32_t leaf) {
    return leaf & ~kLeafBit;
}

// The packet as a whole, for a test of a node's eight boxes at once that rejects a child only
// when every lane's own test would (interval arithmetic over the lanes): on each axis the range
// of the lanes' origins and inverses (one sign for all, else `usable` is false), the largest
// margin, and the widest t interval.
struct alignas(32) PacketBounds {
    bool usable = false;
    bool negative[3]{};  ///< the lanes' common sign of the inverse on each axis
    float origin_lo[3]{};
    float origin_hi[3]{};
    float inverse_lo[3]{};
    float inverse_hi[3]{};
    float margin[3]{};
    float t_min = 0.0f;  ///< the smallest lane t_min
    float t_max = 0.0f;  ///< the largest lane t_max
};

// Smallest and largest of eight lanes.
__attribute__((target("avx2"))) inline float lanes_min(__m256 x) {
    x = _mm256_min_ps(x, _mm256_permute2f128_ps(x, x, 1));
    x = _mm256_min_ps(x, _mm256_shuffle_ps(x, x, _MM_SHUFFLE(1, 0, 3, 2)));
    x = _mm256_min_ps(x, _mm256_shuffle_ps(x, x, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm256_cvtss_f32(x);
}
__attribute__((target("avx2"))) inline float lanes_max(__m256 x) {
    x = _mm256_max_ps(x, _mm256_permute2f128_ps(x, x, 1));
    x = _mm256_max_ps(x, _mm256_shuffle_ps(x, x, _MM_SHUFFLE(1, 0, 3, 2)));
    x = _mm256_max_ps(x, _mm256_shuffle_ps(x, x, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm256_cvtss_f32(x);
}

// The bounds over every lane; inactive lanes hold copies of an active one (fill_inactive_lanes),
// so all eight count.
__attribute__((target("avx2"))) inline void bound_packet(const PacketValues& v, PacketBounds& b) {
    b.usable = true;
    for (int k = 0; k < 3; ++k) {
        const __m256 inverse = _mm256_load_ps(v.inverse[k]);
        const int signs = _mm256_movemask_ps(inverse);
        if (signs != 0 && signs != 0xff) {
            b.usable = false;
        }
        b.negative[k] = signs != 0;
        const __m256 origin = _mm256_load_ps(v.origin[k]);
        b.origin_lo[k] = lanes_min(origin);
        b.origin_hi[k] = lanes_max(origin);
        b.inverse_lo[k] = lanes_min(inverse);
        b.inverse_hi[k] = lanes_max(inverse);
        b.margin[k] = lanes_max(_mm256_load_ps(v.margin[k]));
    }
    b.t_min = lanes_min(_mm256_load_ps(v.t_min));
    b.t_max = lanes_max(_mm256_load_ps(v.t_max));
}

// The children some lane of the packet may meet: bit c clear only when every lane's own test
// (test_children) rejects child c. Each step of a lane's test is monotone in each operand
// (correctly rounded operations are), so its entry is at least this entry, taken with the
// operands' bounds, and its exit at most this exit. A NaN bound keeps the child.
__attribute__((target("avx2"))) inline std::uint32_t children_packet_may_meet(
    const WideNode& node, const PacketBounds& b) {
    __m256 entry = _mm256_set1_ps(-HUGE_VALF);
    __m256 exit = _mm256_set1_ps(HUGE_VALF);
    for (int k = 0; k < 3; ++k) {
        const __m256 lower = _mm256_load_ps(lower_planes(node, k));
        const __m256 upper = _mm256_load_ps(upper_planes(node, k));
        const __m256 near_plane = b.negative[k] ? upper : lower;
        const __m256 far_plane = b.negative[k] ? lower : upper;
        const __m256 o_lo = _mm256_set1_ps(b.origin_lo[k]);
        const __m256 o_hi = _mm256_set1_ps(b.origin_hi[k]);
        const __m256 i_lo = _mm256_set1_ps(b.inverse_lo[k]);
        const __m256 i_hi = _mm256_set1_ps(b.inverse_hi[k]);
        const __m256 margin = _mm256_set1_ps(b.margin[k]);
        const __m256 near_a = _mm256_sub_ps(near_plane, o_hi);
        const __m256 near_b = _mm256_sub_ps(near_plane, o_lo);
        const __m256 far_a = _mm256_sub_ps(far_plane, o_hi);
        const __m256 far_b = _mm256_sub_ps(far_plane, o_lo);
        const __m256 near_low =
            _mm256_min_ps(_mm256_min_ps(_mm256_mul_ps(near_a, i_lo), _mm256_mul_ps(near_a, i_hi)),
                          _mm256_min_ps(_mm256_mul_ps(near_b, i_lo), _mm256_mul_ps(near_b, i_hi)));
        const __m256 far_high =
            _mm256_max_ps(_mm256_max_ps(_mm256_mul_ps(far_a, i_lo), _mm256_mul_ps(far_a, i_hi)),
                          _mm256_max_ps(_mm256_mul_ps(far_b, i_lo), _mm256_mul_ps(far_b, i_hi)));
        entry = _mm256_max_ps(_mm256_sub_ps(near_low, margin), entry);
        exit = _mm256_min_ps(_mm256_add_ps(far_high, margin), exit);
    }
    const __m256 rejected =
        _mm256_or_ps(_mm256_or_ps(_mm256_cmp_ps(entry, exit, _CMP_GT_OQ),
                                  _mm256_cmp_ps(entry, _mm256_set1_ps(b.t_max), _CMP_GT_OQ)),
                     _mm256_cmp_ps(exit, _mm256_set1_ps(b.t_min), _CMP_LT_OQ));
    return ~static_cast<std::uint32_t>(_mm256_movemask_ps(rejected)) & 0xffu;
}

// entry is left uninitialised: test_children writes it for every child it returns.
struct alignas(32) ChildHits {  // NOLINT(cppcoreguidelines-pro-type-member-init)
    std::uint32_t child = 0;
    std::uint32_t rays = 0;  ///< lanes whose line meets the box within their interval
    float key = 0.0f;        ///< the nearest of those lanes' entries: the visiting order
    alignas(32) float entry[8];
};

// Each child's box against the eight rays: the slab test's packet form (float_ray.cpp, part 2),
// (p - o) * inverse with the margin, the form children_packet_may_meet bounds, with the near and
// far planes chosen per lane by the sign of its inverse, for the children in `children` (bits).
// The single ray's own form (box_test.h) saves an operation a plane, but here its offsets cost a
// packet's set-up more than that saves (docs/lab/levers-4-2026-12-05.md). Returns how many of
// the children some lane meets.
__attribute__((target("avx2"))) inline int test_children(const WideNode& node,
                                                         const PacketValues& v,
                                                         std::uint32_t active,
                                                         std::uint32_t children, ChildHits* out) {
    const __m256 t_min = _mm256_load_ps(v.t_min);
    const __m256 t_max = _mm256_load_ps(v.t_max);
    __m256 origin[3];
    __m256 inverse[3];
    __m256 margin[3];
    for (int k = 0; k < 3; ++k) {
        origin[k] = _mm256_load_ps(v.origin[k]);
        inverse[k] = _mm256_load_ps(v.inverse[k]);
        margin[k] = _mm256_load_ps(v.margin[k]);
    }
    int count = 0;
    for (; children != 0; children &= children - 1) {
        const int c = std::countr_zero(children);
        const std::uint32_t child = child_word(node, c);
        if (child == kNoChild) {
            continue;
        }
        __m256 entry = _mm256_set1_ps(-HUGE_VALF);
        __m256 exit = _mm256_set1_ps(HUGE_VALF);
        for (int k = 0; k < 3; ++k) {
            const __m256 lo = _mm256_set1_ps(child_lo(node, k, c));
            const __m256 hi = _mm256_set1_ps(child_hi(node, k, c));
            // blendv takes its second operand where the inverse's sign bit is set.
            const __m256 near_side = _mm256_sub_ps(_mm256_blendv_ps(lo, hi, inverse[k]), origin[k]);
            const __m256 far_side = _mm256_sub_ps(_mm256_blendv_ps(hi, lo, inverse[k]), origin[k]);
            entry = _mm256_max_ps(_mm256_sub_ps(_mm256_mul_ps(near_side, inverse[k]), margin[k]),
                                  entry);
            exit =
                _mm256_min_ps(_mm256_add_ps(_mm256_mul_ps(far_side, inverse[k]), margin[k]), exit);
        }
        const __m256 hit = _mm256_and_ps(_mm256_and_ps(_mm256_cmp_ps(entry, exit, _CMP_LE_OQ),
                                                       _mm256_cmp_ps(entry, t_max, _CMP_LE_OQ)),
                                         _mm256_cmp_ps(exit, t_min, _CMP_GE_OQ));
        const auto rays = static_cast<std::uint32_t>(_mm256_movemask_ps(hit)) & active;
        if (rays == 0) {
            continue;
        }
        ChildHits& h = out[count++];
        h.child = child;
        h.rays = rays;
        _mm256_store_ps(h.entry, entry);
        // The smallest entry among the lanes that meet the box.
        const __m256i lanes = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
        const __m256 met = _mm256_castsi256_ps(_mm256_cmpeq_epi32(
            _mm256_and_si256(_mm256_set1_epi32(static_cast<int>(rays)), lanes), lanes));
        __m256 m = _mm256_blendv_ps(_mm256_set1_ps(HUGE_VALF), entry, met);
        m = _mm256_min_ps(m, _mm256_permute2f128_ps(m, m, 1));
        m = _mm256_min_ps(m, _mm256_shuffle_ps(m, m, _MM_SHUFFLE(1, 0, 3, 2)));
        m = _mm256_min_ps(m, _mm256_shuffle_ps(m, m, _MM_SHUFFLE(2, 3, 0, 1)));
        h.key = _mm256_cvtss_f32(m);
    }
    return count;
}

}  // namespace rt::bvh::packet
