#include "rt/accel/voxel/voxel_hit_search.h"

namespace rt {

void NearestHitSearch::test(std::span<const std::uint32_t> polygons) {
    test_each(polygons, [&](std::uint32_t id) {
        // Polygons arrive in voxel order, not id order: the tie rule picks among equal t.
        if (const std::optional<double> t =
                intersect_polygon(space_, scene_.polygon_view(id), nearest_.search_interval())) {
            nearest_.offer(*t, id);
        }
        return false;
    });
}

bool AnyHitSearch::test(std::span<const std::uint32_t> polygons) {
    return test_each(polygons, [&](std::uint32_t id) {
        return intersect_polygon(space_, scene_.polygon_view(id), t_);
    });
}

}  // namespace rt
