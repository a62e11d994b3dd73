// The default fill: a node's polygons go to its children, and each child is finished (down to
// its leaves) before the next is started. Nodes come out in depth-first order, which is the
// layout both fills share.
//
// The top of the tree is split on this thread down to a frontier of subtrees, which worker
// threads then fill, each into an array of its own; the subtrees are then spliced in depth-first
// order. Each subtree's nodes and polygon ids are exactly the ones the one-thread fill would have
// put there, only offset, so the arrays are the same bit for bit whatever the number of threads.
#include <algorithm>
#include <array>
#include <exception>
#include <memory>
#include <thread>
#include <vector>

#include "rt/accel/octree/octree_split.h"
#include "rt/accel/parallel_parts.h"
#include "rt/core/error.h"

namespace rt {

namespace {

// Children's polygon lists, one set per level: the fill works on one node per level at a time,
// so these buffers are reused from node to node instead of being allocated for each.
using ChildLists = std::array<std::vector<std::uint32_t>, 8>;

void fill(const OctreeFill& fill_state, OctreeTree& tree, std::uint32_t index,
          const OctreeCell& cell, const std::vector<std::uint32_t>& polygons,
          std::vector<ChildLists>& scratch) {
    if (!fill_state.splits(cell.level, polygons.size())) {
        fill_state.make_leaf(tree, index, polygons);
        return;
    }
    const std::uint32_t first = fill_state.allocate_children(tree);
    tree.nodes[index] = {first, OctreeNode::kInterior};
    ChildLists& children = scratch[static_cast<std::size_t>(cell.level)];
    fill_state.split(cell, polygons, children);
    for (int c = 0; c < 8; ++c) {
        fill(fill_state, tree, first + c, cell.child(c), children[c], scratch);
    }
}

// A node of the top of the tree: split here, or a subtree left to a worker (`task` >= 0).
struct TopNode {
    OctreeCell cell;
    std::vector<std::uint32_t> polygons;  ///< a task's polygons (emptied once it is filled)
    int task = -1;
    std::array<std::unique_ptr<TopNode>, 8> children;
};

void split_top(const OctreeFill& fill_state, TopNode& node, int frontier,
               std::vector<TopNode*>& tasks) {
    if (node.cell.level >= frontier || !fill_state.splits(node.cell.level, node.polygons.size())) {
        node.task = static_cast<int>(tasks.size());
        tasks.push_back(&node);
        return;
    }
    ChildLists lists;
    fill_state.split(node.cell, node.polygons, lists);
    node.polygons = {};
    for (int c = 0; c < 8; ++c) {
        node.children[c] = std::make_unique<TopNode>();
        node.children[c]->cell = node.cell.child(c);
        node.children[c]->polygons = std::move(lists[c]);
        split_top(fill_state, *node.children[c], frontier, tasks);
    }
}

// Puts a subtree filled apart (its root at local index 0) at `index` of `out`, its other nodes
// at the end of out's nodes, exactly where the one-thread fill would have allocated them.
void splice(const OctreeTree& part, std::uint32_t index, OctreeTree& out) {
    const auto node_base = static_cast<std::uint32_t>(out.nodes.size());
    const auto polygon_base = static_cast<std::uint32_t>(out.polygons.size());
    const auto moved = [&](OctreeNode node) {
        // Interior nodes' children are never at local index 0, the subtree's root.
        return node.is_leaf() ? OctreeNode{node.first + polygon_base, node.count}
                              : OctreeNode{node.first - 1 + node_base, node.count};
    };
    out.nodes[index] = moved(part.nodes[0]);
    for (std::size_t i = 1; i < part.nodes.size(); ++i) {
        out.nodes.push_back(moved(part.nodes[i]));
    }
    out.polygons.insert(out.polygons.end(), part.polygons.begin(), part.polygons.end());
}

void place(const TopNode& node, std::uint32_t index, const std::vector<OctreeTree>& parts,
           OctreeTree& out) {
    if (node.task >= 0) {
        splice(parts[static_cast<std::size_t>(node.task)], index, out);
        return;
    }
    const auto first = static_cast<std::uint32_t>(out.nodes.size());
    out.nodes.resize(out.nodes.size() + 8);
    out.nodes[index] = {first, OctreeNode::kInterior};
    for (std::uint32_t c = 0; c < 8; ++c) {
        place(*node.children[c], first + c, parts, out);
    }
}

unsigned build_threads(unsigned asked) {
    return std::clamp(asked != 0 ? asked : std::thread::hardware_concurrency(), 1u, 64u);
}

}  // namespace

OctreeTree build_octree_depth_first(const Scene& scene, const OctreeBuildSettings& settings,
                                    bool no_fudge) {
    OctreeFill fill_state(scene, settings, no_fudge);
    OctreeTree& tree = fill_state.tree();
    OctreeCell root_cell;
    root_cell.size = std::int64_t{1} << tree.depth;
    const unsigned threads = build_threads(settings.threads);
    if (threads <= 1) {
        std::vector<ChildLists> scratch(static_cast<std::size_t>(tree.depth) + 1);
        fill(fill_state, tree, 0, root_cell, fill_state.all_polygons(), scratch);
    } else {
        // Split the top until there are at least four subtrees a thread, so that uneven ones
        // still share out well.
        int frontier = 0;
        for (std::size_t n = 1; n < 4 * std::size_t{threads}; n *= 8) {
            ++frontier;
        }
        TopNode root;
        root.cell = root_cell;
        root.polygons = fill_state.all_polygons();
        std::vector<TopNode*> tasks;
        split_top(fill_state, root, frontier, tasks);

        std::vector<OctreeTree> parts(tasks.size());
        std::vector<std::exception_ptr> errors(tasks.size());
        std::vector<std::vector<ChildLists>> scratch(
            threads, std::vector<ChildLists>(static_cast<std::size_t>(tree.depth) + 1));
        share_out(tasks.size(), static_cast<int>(threads), [&](std::size_t t, int thread) {
            try {
                parts[t].nodes.emplace_back();
                fill(fill_state, parts[t], 0, tasks[t]->cell, tasks[t]->polygons,
                     scratch[static_cast<std::size_t>(thread)]);
            } catch (...) {
                errors[t] = std::current_exception();
            }
            tasks[t]->polygons = {};
        });
        for (const std::exception_ptr& error : errors) {
            if (error) {
                std::rethrow_exception(error);
            }
        }
        // The one-thread fill fails when the pool outgrows -ol or the references 2^32; so does
        // this one, once it knows the totals.
        // The top's split nodes: a tree with k of them, each with 8 children, has 7k + 1 leaves.
        std::size_t nodes = (tasks.size() - 1) / 7;
        std::size_t references = 0;
        for (const OctreeTree& part : parts) {
            nodes += part.nodes.size();
            references += part.polygons.size();
        }
        fill_state.check_node_count(nodes);
        if (references >= OctreeNode::kInterior) {
            throw SettingError("octree depth",
                               "the octree holds more than 2^32 polygon references: lower the "
                               "octree depth");
        }
        tree.nodes.clear();
        tree.nodes.shrink_to_fit();
        tree.nodes.reserve(nodes);
        tree.nodes.emplace_back();
        tree.polygons.reserve(references);
        place(root, 0, parts, tree);
    }
    // The pool grew by doubling; give back the slack so memory_bytes() is what the tree needs.
    tree.nodes.shrink_to_fit();
    tree.polygons.shrink_to_fit();
    return std::move(tree);
}

}  // namespace rt
