#include "rt/accel/seads/seads.h"

#include "rt/accel/seads/seads_walk.h"
#include "rt/accel/voxel/voxel_hit_search.h"

namespace rt {

Seads::Seads(const Scene& scene, const AccelSettings& settings)
    : scene_(scene),
      grid_(build_seads_grid(scene, settings.seads_resolution, settings.no_fudge)),
      rules_(WalkRules::from(settings)),
      boxes_(scene, voxel_fudge(grid_.world, false)) {}

std::optional<Hit> Seads::closest_hit(const Ray& ray, Interval t, TraceCounters& counters) const {
    const RaySpace space(ray);
    if (!space.valid()) {
        return std::nullopt;
    }
    NearestHitSearch search(scene_, boxes_, space, t, counters);
    NearHitRule rule(rules_);
    walk_seads(grid_, ray, t, [&](std::span<const std::uint32_t> polygons, double t_exit) {
        search.test(polygons);
        return rule.ends_walk(search.nearest(), t_exit, counters);
    });
    return search.nearest();
}

bool Seads::occluded(const Ray& ray, Interval t, TraceCounters& counters) const {
    const RaySpace space(ray);
    if (!space.valid()) {
        return false;
    }
    AnyHitSearch search(scene_, boxes_, space, t, counters);
    bool hit = false;
    walk_seads(grid_, ray, t, [&](std::span<const std::uint32_t> polygons, double) {
        ++counters.voxels_stepped;
        hit = search.test(polygons);
        return hit;
    });
    return hit;
}

std::unique_ptr<Accelerator> make_seads(const Scene& scene, const AccelSettings& settings) {
    return std::make_unique<Seads>(scene, settings);
}

}  // namespace rt
