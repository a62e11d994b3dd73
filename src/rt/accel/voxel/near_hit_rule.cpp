#include "rt/accel/voxel/near_hit_rule.h"

#include <algorithm>
#include <cmath>

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
    // Bounds that need no square root, each at least the length it stands for: the sum of
    // |components| for the distance, the largest |component| for the direction's length. A
    // larger slack only walks a little further; the answers stay exact.
    const Vec3 centre = (world.lo + world.hi) * 0.5;
    const Vec3 away = ray.origin - centre;
    const Vec3& d = ray.direction;
    const double distance = std::fabs(away.x) + std::fabs(away.y) + std::fabs(away.z);
    const double direction = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
    return 0x1p-29 * (distance + world.largest_extent()) / direction;
}

}  // namespace rt
