// The builder's last pass: turns the leaves it found into triangle packets. The split passes read
// only the references; a leaf's packets read the scene's polygons, corner lists and positions, a
// chain of three dependent cache misses per polygon at places scattered over the scene. Done in
// one pass over every leaf, those reads can be asked for several leaves ahead, and the pass splits
// across threads by leaves.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "rt/accel/bvh/bvh_layout.h"
#include "rt/accel/bvh/polygon_references.h"

namespace rt::bvh {

/// A leaf the builder found: references [begin, end), to be written into child word `slot` of
/// node `node` (kNoChild: the leaf is the whole tree, its word is the root).
struct PendingLeaf {
    std::uint32_t node = kNoChild;
    std::uint32_t slot = 0;
    std::uint32_t begin = 0;
    std::uint32_t end = 0;
};

/// Sizes tree.packets to the leaves' packets and writes them in the order given, and points each
/// leaf's child word (or tree.root) at its first packet. `threads` splits the leaves into that many
/// runs.
void fill_leaves(const Scene& scene, std::span<const PolygonReference> refs,
                 std::span<const PendingLeaf> leaves, Hierarchy& tree, unsigned threads);

}  // namespace rt::bvh
