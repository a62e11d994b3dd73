#include "rt/accel/seads/seads.h"

#include "rt/accel/seads/seads_walk.h"
#include "rt/accel/voxel/voxel_hit_search.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

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
    const double slack = rounding_slack(ray, grid_.world, rules_);
    NearHitRule rule(rules_, slack);
    walk_seads(grid_, ray, walk_interval(t, slack),
               [&](std::span<const std::uint32_t> polygons, double t_exit, const int*) {
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
    walk_seads(grid_, ray, walk_interval(t, rounding_slack(ray, grid_.world, rules_)),
               [&](std::span<const std::uint32_t> polygons, double, const int*) {
                   ++counters.voxels_stepped;
                   hit = search.test(polygons);
                   return hit;
               });
    return hit;
}

std::string Seads::describe_walk(const Ray& ray, Interval t) const {
    std::string lines;
    walk_seads(grid_, ray, t,
               [&](std::span<const std::uint32_t> polygons, double t_exit, const int* voxel) {
                   lines +=
                       fmt::format("  voxel ({}, {}, {}) leaves at t {}: polygons {}\n", voxel[0],
                                   voxel[1], voxel[2], t_exit, fmt::join(polygons, " "));
                   return false;
               });
    return lines;
}

std::unique_ptr<Accelerator> make_seads(const Scene& scene, const AccelSettings& settings) {
    return std::make_unique<Seads>(scene, settings);
}

}  // namespace rt
