#include "rt/accel/octree/octree_listing.h"

#include "rt/accel/debug/describe_walk.h"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

namespace rt {

namespace {

struct Place {
    std::int64_t origin[3];
    std::int64_t size;
    int level;
};

void list_node(const OctreeTree& tree, std::uint32_t index, const Place& at, std::ostream& out) {
    const OctreeNode& node = tree.nodes[index];
    const std::string indent(2 * static_cast<std::size_t>(at.level), ' ');
    const std::string where =
        fmt::format("node {} level {} lattice ({}, {}, {}) side {}", index, at.level, at.origin[0],
                    at.origin[1], at.origin[2], at.size);
    if (node.is_leaf()) {
        fmt::print(out, "{}{}: leaf, {} polygons: {}\n", indent, where, node.count,
                   fmt::join(tree.leaf_polygons(node), " "));
        return;
    }
    fmt::print(out, "{}{}: children {} to {}\n", indent, where, node.first, node.first + 7);
    for (std::uint32_t c = 0; c < 8; ++c) {
        Place child{{}, at.size / 2, at.level + 1};
        for (int a = 0; a < 3; ++a) {
            child.origin[a] = at.origin[a] + (((c >> a) & 1) != 0 ? child.size : 0);
        }
        list_node(tree, node.first + c, child, out);
    }
}

}  // namespace

void write_octree_listing(const OctreeTree& tree, std::ostream& out) {
    fmt::print(out,
               "# octree: depth {}, world {} to {}, lattice step {}, {} nodes, {} polygon "
               "references\n",
               tree.depth, describe_vector(tree.world.lo), describe_vector(tree.world.hi),
               describe_vector(tree.step), tree.nodes.size(), tree.polygons.size());
    list_node(tree, 0, Place{{0, 0, 0}, std::int64_t{1} << tree.depth, 0}, out);
}

}  // namespace rt
