// The float filter values of eight rays, one AVX2 lane each: FloatRay's values (float_ray_inl.h),
// computed for four rays at a time (eight with AVX-512) in double and rounded as FloatRay rounds
// them, so that every lane's filters are exactly the single ray's. Setting up rays one FloatRay
// at a time cost more than the packet's whole walk.
#pragma once

#include <cstdint>

#include "rt/accel/accelerator.h"
#include "rt/accel/float_prefilter/float_ray.h"

namespace rt::bvh {

struct alignas(32) PacketValues {
    float origin[3][8];
    float inverse[3][8];
    float margin[3][8];  ///< FloatRay::slab_margin
    float t_min[8];
    float t_max[8];
    // Triangle pre-filter, each lane in its own axes (kx, ky, kz).
    float shear_x[8];
    float shear_y[8];
    float edge_linear[8];
    float edge_constant[8];
    double scale_t[8];
    int kx[8];
    int ky[8];
    int kz[8];
    bool same_axes;  ///< every set-up lane has the same kz
};

/// A set-up lane's FloatRay: the same values FloatRay(ray, scene_scale) computes for its ray.
FloatRay lane_float_ray(const PacketValues& v, int lane);

/// FloatRay::scaled_down and scaled_up for a lane.
inline float lane_scaled_down(const PacketValues& v, int lane, double t) {
    return float_below(t * v.scale_t[lane]);
}
inline float lane_scaled_up(const PacketValues& v, int lane, double t) {
    return float_above(t * v.scale_t[lane]);
}

/// How set_up_packet works: four lanes at a time with AVX2, eight at a time with AVX-512, or
/// (Best) eight where the CPU has AVX-512 and four otherwise. Each gives the same values.
enum class SetUpPath { Best, FourLanes, EightLanes };

/// Whether this build and CPU can set packets up by `path`.
bool set_up_path_available(SetUpPath path);

/// Sets up the active lanes of `packet` whose FloatRay would be usable and whose direction is of
/// an ordinary size (all but extremes), with t_min from the packet's intervals and t_max from
/// their ends; returns them. The other active lanes need the single-ray path. Needs AVX2, and
/// for EightLanes AVX-512 (set_up_path_available).
std::uint32_t set_up_packet(const RayPacket& packet, double scene_scale, PacketValues& v,
                            SetUpPath path = SetUpPath::Best);

}  // namespace rt::bvh
