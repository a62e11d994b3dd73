#include "rt/accel/voxel/voxel_hit_search.h"

namespace rt {

void NearestHitSearch::test(std::span<const CellPacket> packets) {
    test_packets(packets, offer_to_nearest());
}

bool AnyHitSearch::test(std::span<const CellPacket> packets) {
    return test_packets(packets, hit_within());
}

}  // namespace rt
