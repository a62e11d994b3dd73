#include "rt/accel/voxel/voxel_hit_search.h"

namespace rt {

void NearestHitSearch::test(std::span<const std::uint32_t> polygons) {
    // Every box this voxel needs, and every polygon record, asked for at once: their cache
    // misses then overlap instead of each waiting for the one before.
    for (const std::uint32_t id : polygons) {
        boxes_.prefetch(id);
        __builtin_prefetch(scene_.polygons.data() + id);
    }
    for (const std::uint32_t id : polygons) {
        if (tested_.seen(id) || !boxes_.line_may_meet(line_, id) ||
            !boxes_.triangle_may_be_hit(triangle_, id)) {
            continue;
        }
        ++counters_.polygon_tests;
        // Polygons arrive in voxel order, not id order: the tie rule picks among equal t.
        if (const std::optional<double> t =
                intersect_polygon(space_, scene_.polygon_view(id), nearest_.search_interval())) {
            nearest_.offer(*t, id);
        }
    }
}

bool AnyHitSearch::test(std::span<const std::uint32_t> polygons) {
    for (const std::uint32_t id : polygons) {
        boxes_.prefetch(id);
        __builtin_prefetch(scene_.polygons.data() + id);
    }
    for (const std::uint32_t id : polygons) {
        if (tested_.seen(id) || !boxes_.line_may_meet(line_, id) ||
            !boxes_.triangle_may_be_hit(triangle_, id)) {
            continue;
        }
        ++counters_.polygon_tests;
        if (intersect_polygon(space_, scene_.polygon_view(id), t_)) {
            return true;
        }
    }
    return false;
}

}  // namespace rt
