#include "rt/accel/brute_force.h"

#include "rt/geometry/ray_polygon.h"

namespace rt {

std::optional<Hit> BruteForce::closest_hit(const Ray& ray, Interval t,
                                           TraceCounters& counters) const {
    const RaySpace space(ray);
    std::optional<Hit> nearest;
    const auto count = static_cast<std::uint32_t>(scene_.polygons.size());
    for (std::uint32_t id = 0; id < count; ++id) {
        // A hit at the same t as the nearest so far is not nearer: ties go to the lowest id.
        const std::optional<double> hit = intersect_polygon(space, scene_, id, t);
        if (hit) {
            nearest = Hit{*hit, id};
            t.max = *hit;
        }
    }
    counters.polygon_tests += count;
    return nearest;
}

bool BruteForce::occluded(const Ray& ray, Interval t, TraceCounters& counters) const {
    const RaySpace space(ray);
    const auto count = static_cast<std::uint32_t>(scene_.polygons.size());
    for (std::uint32_t id = 0; id < count; ++id) {
        ++counters.polygon_tests;
        if (intersect_polygon(space, scene_, id, t)) {
            return true;
        }
    }
    return false;
}

std::unique_ptr<Accelerator> make_brute_force(const Scene& scene) {
    return std::make_unique<BruteForce>(scene);
}

}  // namespace rt
