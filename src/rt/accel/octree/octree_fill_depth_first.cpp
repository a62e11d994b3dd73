// The default fill: a node's polygons go to its children, and each child is finished (down to
// its leaves) before the next is started. Nodes come out in depth-first order, which is the
// layout both fills share.
#include <array>
#include <vector>

#include "rt/accel/octree/octree_split.h"

namespace rt {

namespace {

// Children's polygon lists, one set per level: the fill works on one node per level at a time,
// so these buffers are reused from node to node instead of being allocated for each.
using ChildLists = std::array<std::vector<std::uint32_t>, 8>;

void fill(OctreeFill& fill_state, std::uint32_t index, const OctreeCell& cell,
          const std::vector<std::uint32_t>& polygons, std::vector<ChildLists>& scratch) {
    if (!fill_state.splits(cell.level, polygons.size())) {
        fill_state.make_leaf(index, polygons);
        return;
    }
    const std::uint32_t first = fill_state.allocate_children();
    fill_state.tree().nodes[index] = {first, OctreeNode::kInterior};
    ChildLists& children = scratch[static_cast<std::size_t>(cell.level)];
    fill_state.split(cell, polygons, children);
    for (int c = 0; c < 8; ++c) {
        fill(fill_state, first + c, cell.child(c), children[c], scratch);
    }
}

}  // namespace

OctreeTree build_octree_depth_first(const Scene& scene, const OctreeBuildSettings& settings) {
    OctreeFill fill_state(scene, settings);
    OctreeCell root;
    root.size = std::int64_t{1} << settings.depth;
    std::vector<ChildLists> scratch(static_cast<std::size_t>(settings.depth) + 1);
    fill(fill_state, 0, root, fill_state.all_polygons(), scratch);
    // The pool grew by doubling; give back the slack so memory_bytes() is what the tree needs.
    OctreeTree& tree = fill_state.tree();
    tree.nodes.shrink_to_fit();
    tree.polygons.shrink_to_fit();
    return std::move(tree);
}

}  // namespace rt
