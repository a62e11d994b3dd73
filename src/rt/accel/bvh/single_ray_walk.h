// The single ray's walk from a node below the root, for a packet's lane that goes on alone
// (bvh_packet_traversal.cpp): in a subtree entered by one or two rays of a packet, the packet's
// eight-lane tests cost several times the single ray's, for the same candidates.
#pragma once

#include <cstdint>

#include "rt/accel/accelerator.h"
#include "rt/accel/bvh/bvh_layout.h"
#include "rt/accel/bvh/packet_lane.h"
#include "rt/accel/float_prefilter/float_ray.h"
#include "rt/accel/hit.h"
#include "rt/geometry/ray_polygon.h"
#include "rt/scene/scene.h"

namespace rt::bvh {

/// Offers `lane` (its nearest hit so far over t, its exact form made on its first exact test)
/// every polygon of the subtree at `start` that the single ray's walk from the root would offer
/// there. `fray` is the ray's usable float form: a packet's lane has it already (lane_float_ray,
/// packet_setup.h), bit for bit the single ray's.
void nearest_below(const Hierarchy& tree, const Scene& scene, std::uint32_t start,
                   const FloatRay& fray, Interval t, PacketLane& lane, TraceCounters& counters);

}  // namespace rt::bvh
