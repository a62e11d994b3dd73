// The expected cost of a tree by the surface area heuristic, in Embree's own measure (its
// BVHNStatistics, printed with the device configuration "verbose=2"), so that our trees and
// Embree's can be compared without timing: the number a tree's quality is judged by, free of the
// noise a shared machine puts into rates.
#pragma once

#include <cstddef>

#include "rt/accel/bvh/bvh_layout.h"

namespace rt::bvh {

/// Each box's surface over the root's: for a line through the root's box in a uniformly random
/// direction and place, the chance that it also crosses that box.
struct TreeCost {
    /// Expected wide nodes tested: one for the root, and each inner child's share.
    double nodes = 0.0;
    /// Expected packets tested: each leaf's share times its packets (Embree: its blocks of four).
    double leaves = 0.0;
    /// The same counted as the walk built for AVX2 tests a leaf: two packets at once, so each
    /// leaf's share times its packets halved, rounded up.
    double leaf_pairs = 0.0;
    std::size_t leaf_count = 0;
    /// Of the wide nodes' eight slots, the share that holds a child.
    double fill = 0.0;

    double total() const { return nodes + leaves; }
    /// With the leaves counted in pairs: our walk's own expected tests.
    double total_in_pairs() const { return nodes + leaf_pairs; }
};

/// Of the collapsed tree (`tree.wide`); zero for an empty tree. A tree that is one leaf costs
/// its packets.
TreeCost tree_cost(const Hierarchy& tree);

/// Of the collapsed tree: how many leaves a line through the root's box, in a uniformly random
/// direction and place, crosses on average (each leaf's box surface over the root's). About two
/// or three on a closed surface, dozens in a soup of long overlapping triangles. Reads the wide
/// nodes alone, not the packets. Zero for an empty or flat tree, one for a tree that is one leaf.
double leaves_a_line_crosses(const Hierarchy& tree);

}  // namespace rt::bvh
