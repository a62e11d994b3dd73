// -op, the "new fill-plane routines" (manual, Appendix). The 1988 code is lost; ours fills one
// whole level of the tree (one "plane" of its level structure) at a time, breadth first, so each
// pass runs over all the polygon references of one level and nothing of the levels above it is
// kept. It then lays its nodes out depth first, so both fills give the very same arrays.
#include <array>
#include <utility>
#include <vector>

#include "rt/accel/octree/octree_split.h"

#include <fmt/format.h>

namespace rt {

namespace {

struct PendingNode {
    std::uint32_t index = 0;
    OctreeCell cell;
    std::vector<std::uint32_t> polygons;
};

// Copies the subtree at `from` into `out` in depth-first order: the children of a node are
// allocated when it is reached, then filled one after another.
void copy_depth_first(const OctreeTree& in, std::uint32_t from, std::uint32_t to, OctreeTree& out) {
    const OctreeNode node = in.nodes[from];
    if (node.is_leaf()) {
        const auto polygons = in.leaf_polygons(node);
        out.nodes[to] = {static_cast<std::uint32_t>(out.polygons.size()), node.count};
        out.polygons.insert(out.polygons.end(), polygons.begin(), polygons.end());
        return;
    }
    const auto first = static_cast<std::uint32_t>(out.nodes.size());
    out.nodes.resize(out.nodes.size() + 8);
    out.nodes[to] = {first, OctreeNode::kInterior};
    for (std::uint32_t c = 0; c < 8; ++c) {
        copy_depth_first(in, node.first + c, first + c, out);
    }
}

OctreeTree laid_out_depth_first(const OctreeTree& in) {
    OctreeTree out;
    out.world = in.world;
    out.depth = in.depth;
    out.step = in.step;
    out.per_step = in.per_step;
    out.nodes.reserve(in.nodes.size());
    out.polygons.reserve(in.polygons.size());
    out.nodes.emplace_back();
    copy_depth_first(in, 0, 0, out);
    return out;
}

}  // namespace

OctreeTree build_octree_level_order(const Scene& scene, const OctreeBuildSettings& settings,
                                    bool no_fudge) {
    OctreeFill fill_state(scene, settings, no_fudge);
    std::vector<PendingNode> level(1);
    level[0].cell.size = std::int64_t{1} << fill_state.tree().depth;
    level[0].polygons = fill_state.all_polygons();
    std::array<std::vector<std::uint32_t>, 8> children;
    for (int depth = 0; !level.empty(); ++depth) {
        std::vector<PendingNode> next;
        std::size_t references = 0;
        std::size_t leaves = 0;
        for (PendingNode& node : level) {
            references += node.polygons.size();
            if (!fill_state.splits(node.cell.level, node.polygons.size())) {
                ++leaves;
                fill_state.make_leaf(node.index, node.polygons);
                continue;
            }
            const std::uint32_t first = fill_state.allocate_children();
            fill_state.tree().nodes[node.index] = {first, OctreeNode::kInterior};
            fill_state.split(node.cell, node.polygons, children);
            node.polygons = {};  // this level's references are no longer needed
            for (int c = 0; c < 8; ++c) {
                next.push_back({first + static_cast<std::uint32_t>(c), node.cell.child(c),
                                std::move(children[c])});
            }
        }
        if (settings.fill_trace) {
            settings.fill_trace(fmt::format(
                "fill-plane level {}: {} nodes, {} polygon references, {} leaves, {} split", depth,
                level.size(), references, leaves, level.size() - leaves));
        }
        level = std::move(next);
    }
    return laid_out_depth_first(fill_state.tree());
}

}  // namespace rt
