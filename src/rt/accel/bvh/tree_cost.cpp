#include "rt/accel/bvh/tree_cost.h"

#include <cstdint>

#include "rt/accel/bvh/polygon_references.h"

namespace rt::bvh {

namespace {

// Child `c`'s box: bvh::Box's half_area is the SAH's own.
Box child_box(const WideNode& node, int c) {
    Box box;
    for (int k = 0; k < 3; ++k) {
        box.lo[k] = node.lo[k][c];
        box.hi[k] = node.hi[k][c];
    }
    return box;
}

// The pair tests the walk makes of a leaf of `packets` packets: the integer division rounds up on
// purpose.
double pair_tests(std::size_t packets) {
    const std::size_t pairs = (packets + 1) / 2;
    return static_cast<double>(pairs);
}

std::size_t packets_of_leaf(const PacketArray& packets, std::uint32_t leaf) {
    std::size_t count = 0;
    for (std::uint32_t index = leaf & ~kLeafBit;; ++index) {
        ++count;
        if ((packets[index].polygon[3] & kLastPacketBit) != 0) {
            return count;
        }
    }
}

// The half area of the root's box, its children's union, for a tree whose root is a node.
double root_half_area(const Hierarchy& tree) {
    const WideNode& root = tree.wide[tree.root];
    Box root_box;
    for (int c = 0; c < 8; ++c) {
        if (root.child[c] != kNoChild) {
            root_box.grow(child_box(root, c));
        }
    }
    return root_box.half_area();
}

}  // namespace

double leaves_a_line_crosses(const Hierarchy& tree) {
    if (tree.root == kNoChild || is_leaf(tree.root)) {
        return tree.root == kNoChild ? 0.0 : 1.0;
    }
    const double whole = root_half_area(tree);
    if (!(whole > 0.0)) {
        return 0.0;
    }
    double leaves = 0.0;
    for (const WideNode& node : tree.wide) {
        for (int c = 0; c < 8; ++c) {
            if (node.child[c] != kNoChild && is_leaf(node.child[c])) {
                leaves += child_box(node, c).half_area() / whole;
            }
        }
    }
    return leaves;
}

TreeCost tree_cost(const Hierarchy& tree) {
    TreeCost cost;
    if (tree.root == kNoChild) {
        return cost;
    }
    if (is_leaf(tree.root)) {
        const std::size_t packets = packets_of_leaf(tree.packets, tree.root);
        cost.leaves = static_cast<double>(packets);
        cost.leaf_pairs = pair_tests(packets);
        cost.leaf_count = 1;
        return cost;
    }
    const double whole = root_half_area(tree);
    if (!(whole > 0.0)) {
        return cost;  // a flat or degenerate scene: no shares to take
    }
    cost.nodes = 1.0;
    std::size_t slots = 0;
    for (const WideNode& node : tree.wide) {
        for (int c = 0; c < 8; ++c) {
            const std::uint32_t child = node.child[c];
            if (child == kNoChild) {
                continue;
            }
            ++slots;
            const double share = child_box(node, c).half_area() / whole;
            if (!is_leaf(child)) {
                cost.nodes += share;
                continue;
            }
            ++cost.leaf_count;
            const std::size_t packets = packets_of_leaf(tree.packets, child);
            cost.leaves += share * static_cast<double>(packets);
            cost.leaf_pairs += share * pair_tests(packets);
        }
    }
    cost.fill = static_cast<double>(slots) / (8.0 * static_cast<double>(tree.wide.size()));
    return cost;
}

}  // namespace rt::bvh
