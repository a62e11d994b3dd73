#include "rt/accel/octree/octree.h"

#include "rt/accel/octree/octree_ddda.h"
#include "rt/accel/voxel/voxel_queries.h"
#include "rt/core/huge_pages.h"

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

// The nodes of the queries' walk (Octree::walk_nodes_).
std::vector<OctreeNode> walk_nodes_of(const OctreeTree& tree, const CellPackets& packets) {
    std::vector<OctreeNode> nodes;
    reserve_huge(nodes, tree.nodes.size());
    nodes.assign(tree.nodes.begin(), tree.nodes.end());
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        if (nodes[n].is_leaf()) {
            nodes[n] = {packets.first_block(n), packets.block_count(n)};
        }
    }
    return nodes;
}

// A structure this small stays in the cache between rays (a core's L2 holds 512 KiB on the
// machines measured): finding the next leaf early to prefetch it buys nothing, and is wasted
// work when the visit ends the walk.
constexpr std::size_t kLookAheadBytes = std::size_t{256} * 1024;

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
    walk_nodes_ = walk_nodes_of(tree_, packets_);
    top_ = make_top_table(tree_);
    look_ahead_ = Octree::memory_bytes() > kLookAheadBytes;
}

// The queries' walk: visit(cell, t_exit) with each leaf's packets; for a structure too big to stay
// in the cache (look_ahead_), each next leaf's asked of the cache as soon as the walk knows it.
template <class Visit>
void Octree::walk(const Ray& ray, const Vec3& inverse, Interval inside, Visit& visit) const {
    const auto visit_leaf = [&](double t_exit, const OctreeLeafAt& leaf) {
        return visit(packets_.blocks(leaf.node->first, leaf.node->count), t_exit);
    };
    const auto prefetch_leaf = [&](const OctreeNode* node) {
        packets_.prefetch_blocks(node->first);
    };
    if (look_ahead_) {
        walk_octree_leaves<true>(tree_, walk_nodes_.data(), &top_, ray, inverse, inside, visit_leaf,
                                 prefetch_leaf);
    } else {
        walk_octree_leaves<false>(tree_, walk_nodes_.data(), &top_, ray, inverse, inside,
                                  visit_leaf, prefetch_leaf);
    }
}

VoxelSearchParts Octree::search_parts() const {
    return {scene_, boxes_, tree_.world, tree_.bounds_slots, rules_, packets_};
}

std::optional<Hit> Octree::closest_hit(const Ray& ray, Interval t, TraceCounters& counters) const {
    return voxel_closest_hit(search_parts(), ray, t, counters,
                             [&](Interval inside, const Vec3& inverse, auto&& visit) {
                                 walk(ray, inverse, inside, visit);
                             });
}

bool Octree::occluded(const Ray& ray, Interval t, TraceCounters& counters) const {
    return voxel_occluded(search_parts(), ray, t, counters,
                          [&](Interval inside, const Vec3& inverse, auto&& visit) {
                              walk(ray, inverse, inside, visit);
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
