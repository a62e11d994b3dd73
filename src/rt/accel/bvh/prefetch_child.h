// The cache lines a walk asks for when it pushes or enters a child, shared by the single ray's and
// the packet's walks: a ray spends much of its time waiting for memory.
#pragma once

#include <cstddef>
#include <cstdint>

#include "rt/accel/bvh/bvh_layout.h"
#include "rt/core/prefetch.h"
#include "rt/scene/scene.h"

namespace rt::bvh {

constexpr std::ptrdiff_t kCacheLine = 64;
/// A wide node's lines: all of it, boxes and child words.
constexpr int kWideNodeLines = static_cast<int>(sizeof(WideNode) / kCacheLine);
/// A leaf's first two packets, which the AVX2 pre-filter reads at once; packets start on a line.
constexpr int kLeafLines = static_cast<int>(2 * sizeof(TrianglePacket) / kCacheLine);
static_assert(alignof(WideNode) == kCacheLine && alignof(TrianglePacket) == kCacheLine,
              "the counts above count on nodes and packets starting on a cache line");

/// Asks for the lines of child word `child` (a wide node, or a leaf's first packet).
inline void prefetch_child(const Hierarchy& tree, std::uint32_t child) {
    const bool leaf = is_leaf(child);
    const char* at = leaf ? reinterpret_cast<const char*>(&tree.packets[child & ~kLeafBit])
                          : reinterpret_cast<const char*>(&tree.wide[child]);
    const int lines = leaf ? kLeafLines : kWideNodeLines;
    for (int line = 0; line < lines; ++line) {
        prefetch(at + kCacheLine * line);
    }
}

/// Asks for the scene's record of each polygon in the first two packets of `leaf` (a child word
/// with kLeafBit), and for a triangle lane its first corner's position: the normal and the point
/// the exact test and the sure crossing's plane read first. Asked for the first leaf a single ray
/// enters, its pre-filter's work done while they come: on a closed mesh that leaf usually holds
/// the hit, whose record and corner otherwise missed the cache once the pre-filter had found it
/// (docs/lab/leaf-records-2026-12-07.md). Not for every leaf: on a soup most leaves hold no
/// candidate, and their records' lines cost more than they save.
inline void prefetch_leaf_polygons(const Hierarchy& tree, const Scene& scene, std::uint32_t leaf) {
    const TrianglePacket* packet = &tree.packets[leaf & ~kLeafBit];
    const int packets = (packet->polygon[3] & kLastPacketBit) != 0 ? 1 : 2;
    for (int p = 0; p < packets; ++p) {
        for (int lane = 0; lane < 4; ++lane) {
            prefetch(&scene.polygons[packet[p].polygon[lane] & ~kLastPacketBit].normal);
            const std::uint32_t first = packet[p].position.first[lane];
            if (first != kNotTriangle) {
                prefetch(&scene.positions[first]);
            }
        }
    }
}

}  // namespace rt::bvh
