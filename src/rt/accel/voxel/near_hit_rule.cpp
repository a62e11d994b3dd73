#include "rt/accel/voxel/near_hit_rule.h"

namespace rt {

WalkRules WalkRules::from(const AccelSettings& settings) {
    WalkRules rules;
    rules.accept_near_hits = settings.accept_near_hits;
    rules.no_fudge = settings.no_fudge;
    if (settings.terminate_after_voxels && *settings.terminate_after_voxels > 0) {
        rules.fruitless_voxel_limit = static_cast<std::uint64_t>(*settings.terminate_after_voxels);
    }
    return rules;
}

}  // namespace rt
