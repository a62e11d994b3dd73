// Turns a leaf's polygons into packets of four fan triangles for the float pre-filter.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "rt/accel/bvh/bvh_layout.h"
#include "rt/accel/bvh/polygon_references.h"

namespace rt::bvh {

/// Appends the fan triangles (v0, v_i, v_i+1) of every referenced polygon, four to a packet, and
/// marks the last packet. Returns the index of the first. `refs` must not be empty (each
/// reference has at least one triangle).
std::uint32_t append_leaf_packets(const Scene& scene, std::span<const PolygonReference> refs,
                                  std::vector<TrianglePacket>& packets);

}  // namespace rt::bvh
