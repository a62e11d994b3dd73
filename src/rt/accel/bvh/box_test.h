// The four-box test of one node: which children the ray may hit something in, and how near each
// is, with the conservative margins of float_ray.cpp.
#pragma once

#include "rt/accel/bvh/bvh_layout.h"
#include "rt/accel/bvh/float4.h"
#include "rt/accel/bvh/float_ray.h"

namespace rt::bvh {

struct BoxHits {
    int mask = 0;           ///< bit k: child k may hold a hit
    float entry[4] = {};    ///< where the line enters each box (for front-to-back order)
    float nearest[4] = {};  ///< the smallest depth in each box (safe to cull by)
};

/// Children whose box the ray's line meets, with a depth range reaching [t_min, t_max]
/// (scaled float t, both inclusive so that an equal-t hit in another box is still compared).
inline BoxHits test_boxes(const Node& node, const FloatRay& ray, float t_min, float t_max) {
    using simd::Float4;
    Float4 entry = Float4::broadcast(-HUGE_VALF);
    Float4 exit = Float4::broadcast(HUGE_VALF);
    Float4 nearest = Float4::broadcast(0.0f);
    Float4 farthest = Float4::broadcast(0.0f);
    for (int k = 0; k < 3; ++k) {
        const Float4 o = Float4::broadcast(ray.origin[k]);
        const Float4 near_side = Float4::load(ray.near_is_lo[k] ? node.lo[k] : node.hi[k]) - o;
        const Float4 far_side = Float4::load(ray.near_is_lo[k] ? node.hi[k] : node.lo[k]) - o;
        const Float4 inverse = Float4::broadcast(ray.inverse[k]);
        const Float4 margin = Float4::broadcast(ray.slab_margin[k]);
        // max/min keep their second operand when the first is NaN: entry and exit never are.
        entry = max(near_side * inverse - margin, entry);
        exit = min(far_side * inverse + margin, exit);
        const Float4 weight = Float4::broadcast(ray.depth_weight[k]);
        nearest = nearest + near_side * weight;
        farthest = farthest + far_side * weight;
    }
    const Float4 slack = Float4::broadcast(kRelativeSlack);
    entry = entry - abs(entry) * slack;
    exit = exit + abs(exit) * slack;
    const Float4 depth_margin = Float4::broadcast(ray.depth_margin);
    nearest = nearest - depth_margin;
    farthest = farthest + depth_margin;
    const simd::Mask4 hit = (entry <= exit) & (nearest <= Float4::broadcast(t_max)) &
                            (farthest >= Float4::broadcast(t_min));
    BoxHits result;
    result.mask = hit.bits();
    entry.store(result.entry);
    nearest.store(result.nearest);
    return result;
}

}  // namespace rt::bvh
