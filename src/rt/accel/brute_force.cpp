#include "rt/accel/brute_force.h"

#include "rt/accel/lane_exact_hit.h"
#include "rt/geometry/ray_polygon.h"

namespace rt {

std::optional<Hit> BruteForce::closest_hit(const Ray& ray, Interval t,
                                           TraceCounters& counters) const {
    const RaySpace space(ray);
    if (!space.valid()) {
        return std::nullopt;
    }
    std::optional<Hit> nearest;
    const auto count = static_cast<std::uint32_t>(scene_.polygons.size());
    std::uint32_t tested = 0;
    for (std::uint32_t id = 0; id < count; ++id) {
        if (leaves_polygon(ray, id)) {
            continue;
        }
        ++tested;
        // The interval shrinks to the nearest hit so far, open at both ends: a later polygon at
        // the same t is not nearer, so ties go to the lowest id.
        if (const std::optional<double> hit =
                intersect_polygon(space, scene_.polygon_view(id), t)) {
            nearest = Hit{*hit, id};
            t.max = *hit;
        }
    }
    counters.polygon_tests += tested;
    return nearest;
}

bool BruteForce::occluded(const Ray& ray, Interval t, TraceCounters& counters) const {
    const RaySpace space(ray);
    if (!space.valid()) {
        return false;
    }
    const auto count = static_cast<std::uint32_t>(scene_.polygons.size());
    for (std::uint32_t id = 0; id < count; ++id) {
        if (leaves_polygon(ray, id)) {
            continue;
        }
        ++counters.polygon_tests;
        if (intersect_polygon(space, scene_.polygon_view(id), t)) {
            return true;
        }
    }
    return false;
}

std::unique_ptr<Accelerator> make_brute_force(const Scene& scene) {
    return std::make_unique<BruteForce>(scene);
}

}  // namespace rt
