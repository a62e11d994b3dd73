// The eight-box test of a wide node: which children the ray may hit something in, and where its
// line enters each, with the conservative margins of float_ray.cpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "rt/accel/bvh/bvh_layout.h"
#include "rt/accel/bvh/float4.h"
#include "rt/accel/float_prefilter/float_ray.h"

namespace rt::bvh {

/// Where the planes a line enters and leaves a node's boxes through lie (BoxRay::near_plane and
/// far_plane), for each pattern of direction signs (FloatRay::negative): lo[k] for a positive
/// component, hi[k] for a negative one. Node stores lo[3][4] then hi[3][4].
struct PlaneOffsets {
    std::array<int, 3> near_plane;
    std::array<int, 3> far_plane;
};
inline constexpr std::array<PlaneOffsets, 8> kPlaneOffsets = [] {
    std::array<PlaneOffsets, 8> table{};
    for (std::uint32_t signs = 0; signs < 8; ++signs) {
        for (int k = 0; k < 3; ++k) {
            const int negative = static_cast<int>((signs >> k) & 1U);
            table[signs].near_plane[static_cast<std::size_t>(k)] = 4 * k + 12 * negative;
            table[signs].far_plane[static_cast<std::size_t>(k)] = 12 + 4 * k - 12 * negative;
        }
    }
    return table;
}();

/// A FloatRay's box-test values, each repeated in four lanes once per ray rather than per node.
/// A plane p's t is p * inverse - offset, two operations: the origin's product with the inverse
/// and the margin are folded into the offsets once a ray (float_ray.cpp, part 2, argues the
/// bound).
struct BoxRay {
    simd::Float4 inverse[3]{};
    /// origin * inverse + margin: subtracted from a near plane's product, so the entry is early.
    simd::Float4 near_offset[3]{};
    /// origin * inverse - margin: subtracted from a far plane's product, so the exit is late.
    simd::Float4 far_offset[3]{};
    /// Where, from Node::lo[0] (or WideNode::lo[0], in pairs of four), the planes the ray enters
    /// (leaves) through on each axis are (kPlaneOffsets).
    int near_plane[3]{};
    int far_plane[3]{};

    explicit BoxRay(const FloatRay& ray) {
        using simd::Float4;
        for (int k = 0; k < 3; ++k) {
            inverse[k] = Float4::broadcast(ray.inverse[k]);
            const Float4 product = Float4::broadcast(ray.origin[k]) * inverse[k];
            const Float4 margin = Float4::broadcast(ray.slab_margin[k]);
            near_offset[k] = product + margin;
            far_offset[k] = product - margin;
        }
        // The planes looked up by the direction's sign bits: as a choice on the inverse's sign,
        // GCC made the first axis's a branch, a coin toss for rays in random directions
        // (docs/accelerators.md, "Set-up without coin tosses"); worked out by arithmetic, they
        // cost 29 instructions a ray.
        const PlaneOffsets& planes = kPlaneOffsets[ray.negative & 7U];
        std::copy(planes.near_plane.begin(), planes.near_plane.end(), near_plane);
        std::copy(planes.far_plane.begin(), planes.far_plane.end(), far_plane);
    }
};

/// Children whose box the ray's line meets within [t_min, t_max] (scaled float t, both inclusive
/// so that an equal-t hit in another box is still compared), and where the line enters each:
/// the front-to-back order, and the depth a pushed child is culled by once a nearer hit is found.
struct WideHits {
    int mask = 0;
    alignas(32) float entry[8]{};
};

/// With SSE2 only: each half of the node in one register per plane. The AVX2 form in
/// bvh_traversal.cpp does the same operations in the same order per lane.
inline void test_wide_boxes_sse2(const WideNode& node, const BoxRay& ray, simd::Float4 t_min,
                                 simd::Float4 t_max, WideHits& out) {
    using simd::Float4;
    out.mask = 0;
    for (int half = 0; half < 2; ++half) {
        const float* base = node.lo[0] + std::ptrdiff_t{4} * half;
        // Which planes are near and far was chosen once a ray: no branch on the signs here.
        const auto near_t = [&](int k) {
            return Float4::load(base + std::ptrdiff_t{2} * ray.near_plane[k]) * ray.inverse[k] -
                   ray.near_offset[k];
        };
        const auto far_t = [&](int k) {
            return Float4::load(base + std::ptrdiff_t{2} * ray.far_plane[k]) * ray.inverse[k] -
                   ray.far_offset[k];
        };
        // None of these is ever NaN: a plane is finite or an empty slot's infinity, the origin
        // finite, the inverse finite and nonzero (FloatRay). So the first axis's values can start
        // entry and exit, where max(x, -inf) and min(x, +inf) would only give them back.
        Float4 entry = near_t(0);
        Float4 exit = far_t(0);
        for (int k = 1; k < 3; ++k) {
            entry = max(near_t(k), entry);
            exit = min(far_t(k), exit);
        }
        // No relative widening: a plane's t is at most m |inverse| in size, so its relative
        // rounding is inside slab_margin already (float_ray.cpp, part 2).
        const simd::Mask4 hit = (entry <= exit) & (entry <= t_max) & (exit >= t_min);
        out.mask |= hit.bits() << (4 * half);
        entry.store(out.entry + std::ptrdiff_t{4} * half);
    }
}

}  // namespace rt::bvh
