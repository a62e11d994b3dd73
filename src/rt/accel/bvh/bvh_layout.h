// The BVH's memory layout: 4-wide nodes with their children's boxes as structure-of-arrays floats
// (one SSE register per plane), and leaves as packets of four fan triangles, also
// structure-of-arrays, that a float pre-filter tests at once before the exact test decides.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "rt/accel/lane_corners.h"
#include "rt/core/default_init_allocator.h"

namespace rt::bvh {

/// A child word: an inner node's index, or kLeafBit plus the index of the leaf's first packet.
constexpr std::uint32_t kLeafBit = 0x80000000u;
/// An unused child slot; its box is empty (lo = +inf, hi = -inf), so no ray ever enters it.
constexpr std::uint32_t kNoChild = 0xffffffffu;
/// Set in TrianglePacket::polygon[3] of the last packet of a leaf.
constexpr std::uint32_t kLastPacketBit = 0x80000000u;

inline bool is_leaf(std::uint32_t child) {
    return (child & kLeafBit) != 0;
}

/// A node of `Width` children's boxes and child words, on a 64-byte boundary. Boxes are rounded
/// outward from double, so each contains its polygons' corners.
template <int Width>
struct alignas(64) NodeOf {
    float lo[3][Width];  ///< [axis][child]
    float hi[3][Width];
    std::uint32_t child[Width];
};

/// 128 bytes: exactly two cache lines.
using Node = NodeOf<4>;
/// 256 bytes: the node traversal reads, two levels of Node collapsed into up to eight children
/// (collapse.cpp); the same conservative boxes, the same child words.
using WideNode = NodeOf<8>;
static_assert(offsetof(Node, hi) == offsetof(Node, lo) + 12 * sizeof(float) &&
                  offsetof(WideNode, hi) == offsetof(WideNode, lo) + 24 * sizeof(float),
              "BoxRay's plane offsets count on hi following lo");
static_assert(sizeof(Node) == 128 && sizeof(WideNode) == 256);

/// 192 bytes, three cache lines on a 64-byte boundary: four fan triangles (v0, v_i, v_i+1) of
/// the leaf's polygons; unused lanes repeat the last triangle, so they add no candidate the exact
/// test would not already see.
struct alignas(64) TrianglePacket {
    float corner[3][3][4];     ///< [vertex][axis][lane], rounded to nearest
    std::uint32_t polygon[4];  ///< the scene polygon each lane belongs to (| kLastPacketBit)
    /// A triangle polygon's corners as indices into Scene::positions, in its Scene::corners
    /// order, so the exact test need not read Scene::corners; not a triangle for a lane of a
    /// polygon of more corners.
    LaneCorners position;
};
static_assert(sizeof(TrianglePacket) == 192);

/// The leaves' packets: sized first, then written by every build thread (leaf_filling.cpp), so
/// sizing them writes nothing.
using PacketArray = std::vector<TrianglePacket, DefaultInitAllocator<TrianglePacket>>;

/// Nodes in whole huge pages (core/huge_pages.h), sized without being written when the builder
/// takes in the subtrees built on other threads, which copy their nodes in at once.
using NodeArray = std::vector<Node, UnwrittenAllocator<Node>>;
/// Sized first, then written by every build thread (collapse.cpp).
using WideNodeArray = std::vector<WideNode, DefaultInitAllocator<WideNode>>;

/// The whole structure as the builder leaves it and traversal reads it.
struct Hierarchy {
    NodeArray nodes;
    PacketArray packets;
    /// `nodes` collapsed to 8-wide (collapse.cpp); traversal reads these, `nodes` is then empty.
    WideNodeArray wide;
    std::uint32_t root = kNoChild;  ///< a child word; kNoChild for an empty scene
    /// Largest |coordinate| of any (inflated) box: the scale the float error bounds are taken at.
    double scale = 0.0;
    /// Whether a single ray asks for the polygon records of the first leaf it enters
    /// (prefetch_child.h): only where a line crosses few leaves (Bvh's constructor).
    bool first_leaf_records = true;
};

}  // namespace rt::bvh
