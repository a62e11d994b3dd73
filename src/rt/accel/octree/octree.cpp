#include "rt/accel/octree/octree.h"

#include "rt/accel/octree/octree_ddda.h"
#include "rt/accel/voxel/voxel_hit_search.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace rt {

OctreeBuildSettings octree_build_settings(const AccelSettings& settings) {
    OctreeBuildSettings build;
    build.depth = settings.octree_depth;
    build.octlist_power = settings.octlist_power;
    build.seed_size_power = settings.seed_size_power;
    build.no_fudge = settings.no_fudge;
    build.fill_trace = settings.fill_trace;
    return build;
}

Octree::Octree(const Scene& scene, const AccelSettings& settings)
    : scene_(scene),
      tree_(settings.new_fillplane
                ? build_octree_level_order(scene, octree_build_settings(settings))
                : build_octree_depth_first(scene, octree_build_settings(settings))),
      rules_(WalkRules::from(settings)),
      boxes_(scene, voxel_fudge(tree_.world, false)) {
    add_leaf_bounds(scene, tree_);
}

// Both queries clip the ray to the world before anything else: a ray that misses it (about
// half of random rays starting outside) then costs no ray-space or search setup. Invalid rays
// answer "no hit" either way.
std::optional<Hit> Octree::closest_hit(const Ray& ray, Interval t, TraceCounters& counters) const {
    const double slack = rounding_slack(ray, tree_.world, rules_);
    Interval inside;
    if (!clip_to_box(ray, tree_.world, walk_interval(t, slack), inside)) {
        return std::nullopt;
    }
    const RaySpace space(ray);
    if (!space.valid()) {
        return std::nullopt;
    }
    NearestHitSearch search(scene_, boxes_, space, t, counters);
    NearHitRule rule(rules_, slack);
    walk_octree_inside(
        tree_, ray, inside,
        [&](std::span<const std::uint32_t> polygons, double t_exit, const OctreeLeafAt&) {
            if (voxel_may_hold_hit(polygons, tree_.bounds_slots, search.line())) {
                search.test(polygons);
            }
            return rule.ends_walk(search.nearest(), t_exit, counters);
        });
    return search.nearest();
}

bool Octree::occluded(const Ray& ray, Interval t, TraceCounters& counters) const {
    Interval inside;
    if (!clip_to_box(ray, tree_.world, walk_interval(t, rounding_slack(ray, tree_.world, rules_)),
                     inside)) {
        return false;
    }
    const RaySpace space(ray);
    if (!space.valid()) {
        return false;
    }
    AnyHitSearch search(scene_, boxes_, space, t, counters);
    bool hit = false;
    walk_octree_inside(tree_, ray, inside,
                       [&](std::span<const std::uint32_t> polygons, double, const OctreeLeafAt&) {
                           ++counters.voxels_stepped;
                           hit = voxel_may_hold_hit(polygons, tree_.bounds_slots, search.line()) &&
                                 search.test(polygons);
                           return hit;
                       });
    return hit;
}

std::string Octree::describe_walk(const Ray& ray, Interval t) const {
    std::string lines;
    walk_octree(
        tree_, ray, t,
        [&](std::span<const std::uint32_t> polygons, double t_exit, const OctreeLeafAt& leaf) {
            lines +=
                fmt::format("  oct at lattice ({}, {}, {}) side {} leaves at t {}: polygons {}\n",
                            leaf.origin[0], leaf.origin[1], leaf.origin[2], leaf.size, t_exit,
                            fmt::join(polygons, " "));
            return false;
        });
    return lines;
}

std::unique_ptr<Accelerator> make_octree(const Scene& scene, const AccelSettings& settings) {
    return std::make_unique<Octree>(scene, settings);
}

}  // namespace rt
