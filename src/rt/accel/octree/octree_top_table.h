// A shortcut into the top of the octree for the walk. Each step of the DDDA climbs to the lowest
// ancestor holding both the old and the new point and descends from there, one dependent node
// load a level; a step across a boundary near the top of the tree (and every ray's first
// descent) loads a node at every level. The table holds, for every cell of one level near the
// top, the node there (or the leaf above that holds it), so such a descent starts at that level.
// The nodes reached, and so the leaves visited, are the same.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "rt/accel/octree/octree_tree.h"

namespace rt {

struct OctreeTopTable {
    struct Entry {
        std::uint32_t node = 0;   ///< index into the node array
        std::uint32_t level = 0;  ///< that node's level
    };
    int level = 0;             ///< the table's level; 0 means no table
    std::vector<Entry> entry;  ///< per cell, x + y 2^level + z 4^level

    /// The entry of the level-`level` cell holding lattice point `point` of a tree of `depth`.
    Entry at(const std::int64_t point[3], int depth) const {
        const int shift = depth - level;
        return entry[static_cast<std::size_t>(point[0] >> shift) |
                     (static_cast<std::size_t>(point[1] >> shift) << level) |
                     (static_cast<std::size_t>(point[2] >> shift) << (2 * level))];
    }
};

/// The table for `tree`, at level min(depth, 5) (at most 32768 cells, 256 KiB: level 6, at 2 MiB,
/// made random rays on big meshes slower), lowered until it has no more cells than the tree has
/// nodes; none below level 3, where descents are short anyway.
OctreeTopTable make_top_table(const OctreeTree& tree);

}  // namespace rt
