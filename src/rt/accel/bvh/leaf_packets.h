// Turns a leaf's polygons into packets of four fan triangles for the float pre-filter.
#pragma once

#include <cstdint>
#include <span>

#include "rt/accel/bvh/bvh_layout.h"
#include "rt/accel/bvh/polygon_references.h"

namespace rt::bvh {

/// How many packets write_leaf_packets makes of `refs`: their fan triangles, four to a packet.
std::uint32_t leaf_packet_count(std::span<const PolygonReference> refs);

/// Writes the fan triangles (v0, v_i, v_i+1) of every referenced polygon, four to a packet, into
/// the leaf_packet_count(refs) packets at `out`, and marks the last; returns that count. `refs`
/// must not be empty (each reference has at least one triangle).
std::uint32_t write_leaf_packets(const Scene& scene, std::span<const PolygonReference> refs,
                                 TrianglePacket* out);

}  // namespace rt::bvh
