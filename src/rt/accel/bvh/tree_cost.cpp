#include "rt/accel/bvh/tree_cost.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace rt::bvh {

namespace {

// Half the surface of a box (x y + y z + z x), in double from its float bounds; zero when empty.
double half_area(double lx, double ly, double lz, double hx, double hy, double hz) {
    const double x = std::max(hx - lx, 0.0);
    const double y = std::max(hy - ly, 0.0);
    const double z = std::max(hz - lz, 0.0);
    return x * y + y * z + z * x;
}

double child_half_area(const WideNode& node, int c) {
    return half_area(node.lo[0][c], node.lo[1][c], node.lo[2][c], node.hi[0][c], node.hi[1][c],
                     node.hi[2][c]);
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

}  // namespace

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
    // The root's box is its children's union.
    const WideNode& root = tree.wide[tree.root];
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    double hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (int c = 0; c < 8; ++c) {
        if (root.child[c] == kNoChild) {
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], static_cast<double>(root.lo[k][c]));
            hi[k] = std::max(hi[k], static_cast<double>(root.hi[k][c]));
        }
    }
    const double whole = half_area(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
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
            const double share = child_half_area(node, c) / whole;
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
