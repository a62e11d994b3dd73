#include "rt/accel/octree/octree_top_table.h"

#include <algorithm>

namespace rt {

namespace {

constexpr int kTopTableLevel = 5;
constexpr int kLowestTableLevel = 3;

}  // namespace

OctreeTopTable make_top_table(const OctreeTree& tree) {
    OctreeTopTable table;
    // No more cells than the tree has nodes: a small tree's descents are short and cached.
    table.level = std::min(tree.depth, kTopTableLevel);
    while (table.level > 0 && (std::size_t{1} << (3 * table.level)) > tree.nodes.size()) {
        --table.level;
    }
    if (table.level < kLowestTableLevel) {
        table.level = 0;
        return table;
    }
    const std::uint32_t side = 1u << table.level;
    table.entry.resize(std::size_t{side} * side * side);
    for (std::uint32_t z = 0; z < side; ++z) {
        for (std::uint32_t y = 0; y < side; ++y) {
            for (std::uint32_t x = 0; x < side; ++x) {
                // Down from the root along the cell's bits, to the table's level or a leaf.
                std::uint32_t node = 0;
                std::uint32_t level = 0;
                while (static_cast<int>(level) < table.level && !tree.nodes[node].is_leaf()) {
                    const int shift = table.level - 1 - static_cast<int>(level);
                    node =
                        tree.nodes[node].first + (((x >> shift) & 1u) | (((y >> shift) & 1u) << 1) |
                                                  (((z >> shift) & 1u) << 2));
                    ++level;
                }
                table.entry[x | (y << table.level) | (z << (2 * table.level))] = {node, level};
            }
        }
    }
    return table;
}

}  // namespace rt
