#include "rt/accel/octree/octree.h"

#include "rt/accel/octree/octree_ddda.h"
#include "rt/accel/voxel/voxel_queries.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace rt {

namespace {

// The fill's settings, on the threads the program was given.
OctreeBuildSettings fill_settings(const AccelSettings& settings) {
    OctreeBuildSettings fill = settings.octree;
    fill.threads = settings.build_threads;
    return fill;
}

// The queries' visit, told each leaf's node number (its packets).
template <class Visit>
auto numbered(Visit& visit, const OctreeTree& tree) {
    return
        [&visit, &tree](std::span<const std::uint32_t>, double t_exit, const OctreeLeafAt& leaf) {
            return visit(static_cast<std::size_t>(leaf.node - tree.nodes.data()), t_exit);
        };
}

}  // namespace

Octree::Octree(const Scene& scene, const AccelSettings& settings)
    : scene_(scene),
      tree_(settings.octree.level_order
                ? build_octree_level_order(scene, settings.octree, settings.no_fudge)
                : build_octree_depth_first(scene, fill_settings(settings), settings.no_fudge)),
      rules_(WalkRules::from(settings)),
      boxes_(scene, voxel_fudge(tree_.world, false)) {
    // Under -on, no bounds: they skip the leaves where most near hits would be found, and -on
    // is there to show the near hits the manual describes (3.1).
    if (!rules_.accept_near_hits) {
        add_leaf_bounds(scene, tree_);
    }
    packets_ = CellPackets(
        scene, tree_.nodes.size(), tree_.bounds_slots,
        [&](std::size_t n) {
            const OctreeNode& node = tree_.nodes[n];
            return node.is_leaf() ? tree_.leaf_polygons(node) : std::span<const std::uint32_t>{};
        },
        static_cast<int>(settings.build_threads));
}

// The walk's prefetch for the queries: the next leaf's packets.
auto Octree::prefetch_packets() const {
    return [this](const OctreeNode* node) {
        packets_.prefetch(static_cast<std::size_t>(node - tree_.nodes.data()));
    };
}

VoxelSearchParts Octree::search_parts() const {
    return {scene_, boxes_, tree_.world, tree_.bounds_slots, rules_, packets_};
}

std::optional<Hit> Octree::closest_hit(const Ray& ray, Interval t, TraceCounters& counters) const {
    return voxel_closest_hit(search_parts(), ray, t, counters,
                             [&](Interval inside, const Vec3& inverse, auto&& visit) {
                                 walk_octree_inside(tree_, ray, inverse, inside,
                                                    numbered(visit, tree_), prefetch_packets());
                             });
}

bool Octree::occluded(const Ray& ray, Interval t, TraceCounters& counters) const {
    return voxel_occluded(search_parts(), ray, t, counters,
                          [&](Interval inside, const Vec3& inverse, auto&& visit) {
                              walk_octree_inside(tree_, ray, inverse, inside,
                                                 numbered(visit, tree_), prefetch_packets());
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
