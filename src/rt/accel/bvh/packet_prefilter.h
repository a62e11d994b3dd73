// The float pre-filter of a packet of four fan triangles: it rejects a triangle only when the
// ray certainly misses it (float_prefilter/float_ray.cpp, part 3); the exact test decides every
// other one. Lane for lane the operations of triangle_candidate (triangle_prefilter.h).
#pragma once

#include "rt/accel/bvh/bvh_layout.h"
#include "rt/accel/bvh/float4.h"
#include "rt/accel/float_prefilter/float_ray.h"

namespace rt::bvh {

/// A pre-filter's verdicts on four or eight triangles (lane k, bit k): `maybe`, the ray may hit
/// it and the exact test decides; `sure`, a subset, the ray's line surely crosses it
/// (float_ray.cpp, part 4), so that for a triangle polygon the exact winding number is nonzero.
struct FanVerdicts {
    unsigned maybe;
    unsigned sure;
};

/// The verdicts on lane k's triangle, corner[vertex][axis][lane].
inline FanVerdicts fan_verdicts(const float (&corner)[3][3][4], const FloatRay& ray) {
    using simd::Float4;
    const Float4 ox = Float4::broadcast(ray.origin[ray.kx]);
    const Float4 oy = Float4::broadcast(ray.origin[ray.ky]);
    const Float4 oz = Float4::broadcast(ray.origin[ray.kz]);
    const Float4 sx = Float4::broadcast(ray.shear_x);
    const Float4 sy = Float4::broadcast(ray.shear_y);
    Float4 x[3];
    Float4 y[3];
    Float4 size = Float4::broadcast(0.0f);
    for (int v = 0; v < 3; ++v) {
        const Float4 az = Float4::load(corner[v][ray.kz]) - oz;
        x[v] = sub_mul(Float4::load(corner[v][ray.kx]) - ox, sx, az);
        y[v] = sub_mul(Float4::load(corner[v][ray.ky]) - oy, sy, az);
        size = max(size, max(abs(x[v]), abs(y[v])));
    }
    const Float4 e0 = mul_sub(x[1], y[2], y[1] * x[2]);
    const Float4 e1 = mul_sub(x[2], y[0], y[2] * x[0]);
    const Float4 e2 = mul_sub(x[0], y[1], y[0] * x[1]);
    const Float4 margin = mul_add(
        size,
        mul_add(size, Float4::broadcast(kRelativeSlack), Float4::broadcast(ray.edge_margin_linear)),
        Float4::broadcast(ray.edge_margin_constant));
    const Float4 negative_margin = Float4::broadcast(0.0f) - margin;
    const simd::Mask4 all_positive =
        (e0 >= negative_margin) & (e1 >= negative_margin) & (e2 >= negative_margin);
    const simd::Mask4 all_negative = (e0 <= margin) & (e1 <= margin) & (e2 <= margin);
    FanVerdicts verdicts{static_cast<unsigned>((all_positive | all_negative).bits()), 0u};
    if (verdicts.maybe != 0) {
        const simd::Mask4 surely_positive = (e0 > margin) & (e1 > margin) & (e2 > margin);
        const simd::Mask4 surely_negative =
            (e0 < negative_margin) & (e1 < negative_margin) & (e2 < negative_margin);
        verdicts.sure = static_cast<unsigned>((surely_positive | surely_negative).bits());
    }
    return verdicts;
}

/// Bit k set: lane k's triangle, corner[vertex][axis][lane], may be hit (fan_verdicts' `maybe`).
/// Shared by the BVH's leaf packets and the voxel methods' cell packets (voxel/cell_packets.h),
/// which lay their corners out alike.
inline int fan_candidates(const float (&corner)[3][3][4], const FloatRay& ray) {
    return static_cast<int>(fan_verdicts(corner, ray).maybe);
}

/// Bit k set: lane k's triangle may be hit.
inline int packet_candidates(const TrianglePacket& packet, const FloatRay& ray) {
    return fan_candidates(packet.corner, ray);
}

inline FanVerdicts packet_verdicts(const TrianglePacket& packet, const FloatRay& ray) {
    return fan_verdicts(packet.corner, ray);
}

}  // namespace rt::bvh
