#include "rt/accel/octree/octree.h"

#include "rt/accel/octree/octree_ddda.h"
#include "rt/accel/voxel/voxel_queries.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace rt {

Octree::Octree(const Scene& scene, const AccelSettings& settings)
    : scene_(scene),
      tree_(settings.octree.level_order
                ? build_octree_level_order(scene, settings.octree, settings.no_fudge)
                : build_octree_depth_first(scene, settings.octree, settings.no_fudge)),
      rules_(WalkRules::from(settings)),
      boxes_(scene, voxel_fudge(tree_.world, false)) {
    add_leaf_bounds(scene, tree_);
}

VoxelSearchParts Octree::search_parts() const {
    return {scene_, boxes_, tree_.world, tree_.bounds_slots, rules_};
}

std::optional<Hit> Octree::closest_hit(const Ray& ray, Interval t, TraceCounters& counters) const {
    return voxel_closest_hit(search_parts(), ray, t, counters, [&](Interval inside, auto&& visit) {
        walk_octree_inside(tree_, ray, inside, visit);
    });
}

bool Octree::occluded(const Ray& ray, Interval t, TraceCounters& counters) const {
    return voxel_occluded(search_parts(), ray, t, counters, [&](Interval inside, auto&& visit) {
        walk_octree_inside(tree_, ray, inside, visit);
    });
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
