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

double rounding_slack(const Ray& ray, const Box3& world, const WalkRules& rules) {
    if (rules.no_fudge) {
        return 0.0;
    }
    const Vec3 centre = (world.lo + world.hi) * 0.5;
    return 0x1p-29 * (length(ray.origin - centre) + world.largest_extent()) / length(ray.direction);
}

}  // namespace rt
