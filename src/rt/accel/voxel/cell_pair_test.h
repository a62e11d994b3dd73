// The float test of two consecutive cell packets at once, with AVX2: eight fan triangles per
// instruction instead of four, by the BVH's pair test (bvh/packet_pair_prefilter.h), so every lane
// gets the same answer as the four-wide cell_packet_verdicts.
#pragma once

#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
#define RT_VOXEL_AVX2 1
#include "rt/accel/bvh/packet_pair_prefilter.h"
#include "rt/accel/voxel/cell_packets.h"

namespace rt {

/// Whether this CPU runs the AVX2 forms.
bool cpu_has_avx2_for_cells();

/// cell_packet_verdicts of packet[0] (bits 0-3) and packet[1] (bits 4-7).
__attribute__((target("avx2"))) inline bvh::FanVerdicts cell_pair_verdicts(const CellPacket* packet,
                                                                           const FloatRay& ray) {
    const unsigned always = always_lanes(packet[0]) | (always_lanes(packet[1]) << 4);
    const bvh::FanVerdicts verdicts =
        bvh::fan_pair_verdicts(packet[0].corner, packet[1].corner, ray);
    return {verdicts.maybe | always, verdicts.sure & ~always};
}

/// cell_pair_verdicts' `maybe` alone: cell_packet_candidates of packet[0] (bits 0-3) and
/// packet[1] (bits 4-7).
__attribute__((target("avx2"))) inline unsigned cell_pair_candidates(const CellPacket* packet,
                                                                     const FloatRay& ray) {
    return cell_pair_verdicts(packet, ray).maybe;
}

}  // namespace rt
#endif
