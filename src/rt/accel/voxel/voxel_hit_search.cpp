#include "rt/accel/voxel/voxel_hit_search.h"

namespace rt {

#ifdef RT_VOXEL_AVX2
bool cpu_has_avx2_for_cells() {
    static const bool has = __builtin_cpu_supports("avx2");
    return has;
}

namespace {
const bool avx2_for_cells = cpu_has_avx2_for_cells();
}  // namespace
#endif

void NearestHitSearch::test(std::span<const CellPacket> packets) {
#ifdef RT_VOXEL_AVX2
    if (avx2_for_cells) {
        test_packets_avx2(packets, offer_to_nearest());
        return;
    }
#endif
    test_packets(packets, offer_to_nearest());
}

bool AnyHitSearch::test(std::span<const CellPacket> packets) {
#ifdef RT_VOXEL_AVX2
    if (avx2_for_cells) {
        return test_packets_avx2(packets, hit_within());
    }
#endif
    return test_packets(packets, hit_within());
}

}  // namespace rt
