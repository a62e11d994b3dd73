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

/// Asks for what the exact tests of a packet's four triangles read first: each lane's polygon
/// record (its normal) and, for a triangle lane, the positions of its first `corners` corners (the
/// plane's point is corner 0). They are scattered through the scene, and a test would otherwise
/// wait for them once the pre-filter had named its triangle; asked for before the pre-filter,
/// they come while it runs.
inline void prefetch_exact_data(const Scene& scene, const TrianglePacket& packet, int corners) {
    for (int lane = 0; lane < 4; ++lane) {
        prefetch(&scene.polygons[packet.polygon[lane] & ~kLastPacketBit].normal);
        if (packet.position.is_triangle(lane)) {
            for (int c = 0; c < corners; ++c) {
                prefetch(&scene.positions[packet.position.corner(c, lane)]);
            }
        }
    }
}

/// prefetch_exact_data for the first two packets of `leaf` (a child word with kLeafBit), the
/// normals and first corners that the sure crossing's plane reads. The single ray asks it for
/// the first leaf it enters: on a closed mesh that leaf usually holds the hit
/// (docs/lab/leaf-records-2026-12-07.md). Not for every leaf: on a soup most leaves hold no
/// candidate, and their records' lines cost more than they save. (The packet walk asks for every
/// packet, all three corners: there a packet's data serve eight rays.)
inline void prefetch_leaf_polygons(const Hierarchy& tree, const Scene& scene, std::uint32_t leaf) {
    const TrianglePacket* packet = &tree.packets[leaf & ~kLeafBit];
    prefetch_exact_data(scene, packet[0], 1);
    if ((packet->polygon[3] & kLastPacketBit) == 0) {
        prefetch_exact_data(scene, packet[1], 1);
    }
}

}  // namespace rt::bvh
