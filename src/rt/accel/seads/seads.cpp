#include "rt/accel/seads/seads.h"

#include <limits>

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

// -tv counts every fruitless voxel, so it needs the walk to visit each one.
EmptySpace Seads::empty_space() const {
    return rules_.fruitless_voxel_limit == std::numeric_limits<std::uint64_t>::max()
               ? EmptySpace::Leap
               : EmptySpace::VisitEach;
}

// Both queries clip the ray to the world before anything else, as the octree does: a ray that
// misses it (about half of random rays starting outside) then costs no further setup.
std::optional<Hit> Seads::closest_hit(const Ray& ray, Interval t, TraceCounters& counters) const {
    const double slack = rounding_slack(ray, grid_.world, rules_);
    Interval inside;
    if (!clip_to_box(ray, grid_.world, walk_interval(t, slack), inside)) {
        return std::nullopt;
    }
    const RaySpace space(ray);
    if (!space.valid()) {
        return std::nullopt;
    }
    NearestHitSearch search(scene_, boxes_, space, t, counters);
    NearHitRule rule(rules_, slack);
    walk_seads_inside(
        grid_, ray, inside,
        [&](std::span<const std::uint32_t> polygons, double t_exit, const int*) {
            if (voxel_may_hold_hit(polygons, grid_.bounds_slots, search.line())) {
                search.test(polygons);
            }
            return rule.ends_walk(search.nearest(), t_exit, counters);
        },
        empty_space());
    return search.nearest();
}

bool Seads::occluded(const Ray& ray, Interval t, TraceCounters& counters) const {
    Interval inside;
    if (!clip_to_box(ray, grid_.world, walk_interval(t, rounding_slack(ray, grid_.world, rules_)),
                     inside)) {
        return false;
    }
    const RaySpace space(ray);
    if (!space.valid()) {
        return false;
    }
    AnyHitSearch search(scene_, boxes_, space, t, counters);
    bool hit = false;
    walk_seads_inside(
        grid_, ray, inside,
        [&](std::span<const std::uint32_t> polygons, double, const int*) {
            ++counters.voxels_stepped;
            hit = voxel_may_hold_hit(polygons, grid_.bounds_slots, search.line()) &&
                  search.test(polygons);
            return hit;
        },
        empty_space());
    return hit;
}

std::string Seads::describe_walk(const Ray& ray, Interval t) const {
    std::string lines;
    walk_seads(
        grid_, ray, t,
        [&](std::span<const std::uint32_t> polygons, double t_exit, const int* voxel) {
            lines += fmt::format("  voxel ({}, {}, {}) leaves at t {}: polygons {}\n", voxel[0],
                                 voxel[1], voxel[2], t_exit, fmt::join(polygons, " "));
            return false;
        },
        EmptySpace::VisitEach);
    return lines;
}

std::unique_ptr<Accelerator> make_seads(const Scene& scene, const AccelSettings& settings) {
    return std::make_unique<Seads>(scene, settings);
}

}  // namespace rt
