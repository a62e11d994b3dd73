// The four-box test of one node: which children the ray may hit something in, and how near each
// is, with the conservative margins of float_ray.cpp.
#pragma once

#include "rt/accel/bvh/bvh_layout.h"
#include "rt/accel/bvh/float4.h"
#include "rt/accel/bvh/float_ray.h"

namespace rt::bvh {

/// A FloatRay's box-test values, each repeated in four lanes once per ray rather than per node.
struct BoxRay {
    simd::Float4 origin[3];
    simd::Float4 inverse[3];
    simd::Float4 margin[3];
    simd::Float4 weight[3];
    simd::Float4 depth_margin;
    int near_plane[3];
    int far_plane[3];

    explicit BoxRay(const FloatRay& ray) {
        using simd::Float4;
        for (int k = 0; k < 3; ++k) {
            origin[k] = Float4::broadcast(ray.origin[k]);
            inverse[k] = Float4::broadcast(ray.inverse[k]);
            margin[k] = Float4::broadcast(ray.slab_margin[k]);
            weight[k] = Float4::broadcast(ray.depth_weight[k]);
            near_plane[k] = ray.near_plane[k];
            far_plane[k] = ray.far_plane[k];
        }
        depth_margin = Float4::broadcast(ray.depth_margin);
    }
};

struct BoxHits {
    int mask = 0;          ///< bit k: child k may hold a hit
    simd::Float4 entry;    ///< where the line enters each box (for front-to-back order)
    simd::Float4 nearest;  ///< the smallest depth in each box (safe to cull by)
};

/// Children whose box the ray's line meets, with a depth range reaching [t_min, t_max]
/// (scaled float t in all four lanes, both inclusive so that an equal-t hit in another box is
/// still compared).
inline BoxHits test_boxes(const Node& node, const BoxRay& ray, simd::Float4 t_min,
                          simd::Float4 t_max) {
    using simd::Float4;
    Float4 entry = Float4::broadcast(-HUGE_VALF);
    Float4 exit = Float4::broadcast(HUGE_VALF);
    Float4 nearest = Float4::broadcast(0.0f);
    Float4 farthest = Float4::broadcast(0.0f);
    for (int k = 0; k < 3; ++k) {
        // Offsets chosen once per ray: no branch on the direction's signs here.
        const Float4 near_side = Float4::load(node.lo[0] + ray.near_plane[k]) - ray.origin[k];
        const Float4 far_side = Float4::load(node.lo[0] + ray.far_plane[k]) - ray.origin[k];
        // max/min keep their second operand when the first is NaN: entry and exit never are.
        entry = max(near_side * ray.inverse[k] - ray.margin[k], entry);
        exit = min(far_side * ray.inverse[k] + ray.margin[k], exit);
        nearest = nearest + near_side * ray.weight[k];
        farthest = farthest + far_side * ray.weight[k];
    }
    const Float4 slack = Float4::broadcast(kRelativeSlack);
    entry = entry - abs(entry) * slack;
    exit = exit + abs(exit) * slack;
    nearest = nearest - ray.depth_margin;
    farthest = farthest + ray.depth_margin;
    const simd::Mask4 hit = (entry <= exit) & (nearest <= t_max) & (farthest >= t_min);
    return {hit.bits(), entry, nearest};
}

/// The eight-box test of a WideNode, as test_boxes does it for four: the same arithmetic in the
/// same order per lane, so each child's answer is the same as in a Node. Fills entry and nearest
/// for the children in the mask.
struct WideHits {
    int mask = 0;
    alignas(32) float entry[8];
    alignas(32) float nearest[8];
};

/// With SSE2 only: each half of the node as test_boxes does it.
inline void test_wide_boxes_sse2(const WideNode& node, const BoxRay& ray, simd::Float4 t_min,
                                 simd::Float4 t_max, WideHits& out) {
    using simd::Float4;
    out.mask = 0;
    for (int half = 0; half < 2; ++half) {
        const float* base = node.lo[0] + 4 * half;
        Float4 entry = Float4::broadcast(-HUGE_VALF);
        Float4 exit = Float4::broadcast(HUGE_VALF);
        Float4 nearest = Float4::broadcast(0.0f);
        Float4 farthest = Float4::broadcast(0.0f);
        for (int k = 0; k < 3; ++k) {
            const Float4 near_side = Float4::load(base + 2 * ray.near_plane[k]) - ray.origin[k];
            const Float4 far_side = Float4::load(base + 2 * ray.far_plane[k]) - ray.origin[k];
            entry = max(near_side * ray.inverse[k] - ray.margin[k], entry);
            exit = min(far_side * ray.inverse[k] + ray.margin[k], exit);
            nearest = nearest + near_side * ray.weight[k];
            farthest = farthest + far_side * ray.weight[k];
        }
        const Float4 slack = Float4::broadcast(kRelativeSlack);
        entry = entry - abs(entry) * slack;
        exit = exit + abs(exit) * slack;
        nearest = nearest - ray.depth_margin;
        farthest = farthest + ray.depth_margin;
        const simd::Mask4 hit = (entry <= exit) & (nearest <= t_max) & (farthest >= t_min);
        out.mask |= hit.bits() << (4 * half);
        entry.store(out.entry + 4 * half);
        nearest.store(out.nearest + 4 * half);
    }
}

}  // namespace rt::bvh
