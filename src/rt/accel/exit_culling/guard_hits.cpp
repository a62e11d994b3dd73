#include "rt/accel/exit_culling/guard_hits.h"

#include "rt/accel/lane_exact_hit.h"
#include "rt/geometry/ray_polygon.h"

namespace rt {

std::optional<Hit> closest_hit_among(const Scene& scene, const Ray& ray, Interval t,
                                     std::span<const std::uint32_t> polygons,
                                     TraceCounters& counters) {
    const RaySpace space(ray);
    if (!space.valid()) {
        return std::nullopt;  // as brute force answers such a ray
    }
    ClosestHitSoFar nearest(t);
    for (const std::uint32_t id : polygons) {
        offer_exact_hit(scene, space, id, nearest, counters.polygon_tests);
    }
    return nearest.best();
}

bool any_hit_among(const Scene& scene, const Ray& ray, Interval t,
                   std::span<const std::uint32_t> polygons, TraceCounters& counters) {
    const RaySpace space(ray);
    if (!space.valid()) {
        return false;
    }
    for (const std::uint32_t id : polygons) {
        if (leaves_polygon(ray, id)) {
            continue;
        }
        ++counters.polygon_tests;
        if (intersect_polygon(space, scene.polygon_view(id), t)) {
            return true;
        }
    }
    return false;
}

}  // namespace rt
