// Each voxel's (SEADS voxel, octree leaf) triangles laid out next to each other, four to a
// packet, for the float pre-filter to test four at a time. Without them a voxel's test reads its
// ids, then each polygon's box and corners from arrays indexed by id: scattered reads, each a
// likely cache miss on big meshes, and one scalar test each. With them the voxel's data is one
// contiguous run, and most triangles are rejected four at a time before any id is looked at.
//
// A polygon of n corners takes n - 2 lanes, its fan triangles (v0, v_k, v_k+1): the exact test
// (a winding number around the projected corners) can only hit where the line passes through
// one of them, so rejecting a lane whose fan triangle the line certainly misses loses nothing
// (float_prefilter/float_ray.cpp, part 3, argues the float test). A lane whose corners are not
// finite floats is marked "always": its polygon goes on to the box look and the exact test.
// Unused lanes hold NaN corners, which no comparison accepts.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <span>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "rt/accel/bvh/packet_prefilter.h"
#include "rt/accel/float_prefilter/float_ray.h"
#include "rt/accel/lane_exact_hit.h"
#include "rt/core/prefetch.h"
#include "rt/scene/scene.h"

namespace rt {

/// Set in CellPacket::polygon for a lane the float test cannot judge.
inline constexpr std::uint32_t kAlwaysTestBit = 0x80000000u;
/// CellPacket::polygon of an unused lane (the always bit clear).
inline constexpr std::uint32_t kUnusedLane = 0x7fffffffu;
/// 192 bytes on a 16-byte boundary: four fan triangles of a voxel's polygons.
struct alignas(16) CellPacket {
    float corner[3][3][4];     ///< [vertex][axis][lane], rounded to nearest; NaN in unused lanes
    std::uint32_t polygon[4];  ///< the scene polygon of each lane, | kAlwaysTestBit
    /// A triangle polygon's corners as indices into Scene::positions, in its Scene::corners
    /// order, for its exact test (lane_exact_hit.h); not a triangle for a lane of a polygon of
    /// more corners and for an unused lane.
    LaneCorners position;
};
static_assert(sizeof(CellPacket) == 192);

/// Bit k set: lane k holds a fan triangle.
inline unsigned used_lanes(const CellPacket& packet) {
    unsigned lanes = 0;
    for (unsigned lane = 0; lane < 4; ++lane) {
        lanes |= packet.polygon[lane] != kUnusedLane ? 1u << lane : 0u;
    }
    return lanes;
}

/// Bit k set: lane k is marked "always". The mark is each id's sign bit, so with SSE2 one load
/// and one sign mask find the four (a loop over the lanes was a sixth of the voxel tests' time).
inline unsigned always_lanes(const CellPacket& packet) {
    static_assert(kAlwaysTestBit == 0x80000000u, "the always mark is the sign bit");
#if defined(__SSE2__)
    const __m128i ids = _mm_load_si128(reinterpret_cast<const __m128i*>(packet.polygon));
    return static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(ids)));
#else
    unsigned always = 0;
    for (unsigned lane = 0; lane < 4; ++lane) {
        always |= (packet.polygon[lane] & kAlwaysTestBit) != 0 ? 1u << lane : 0u;
    }
    return always;
#endif
}

/// Bit k set in `maybe`: lane k's triangle may be hit by the ray (usable), or lane k is marked
/// "always"; in `sure`: the ray's line surely crosses lane k's triangle (float_ray.cpp, part 4),
/// never for an "always" lane. Lane for lane the operations of triangle_candidate
/// (float_prefilter/triangle_prefilter.h).
inline bvh::FanVerdicts cell_packet_verdicts(const CellPacket& packet, const FloatRay& ray) {
    const unsigned always = always_lanes(packet);
    const bvh::FanVerdicts verdicts = bvh::fan_verdicts(packet.corner, ray);
    return {verdicts.maybe | always, verdicts.sure & ~always};
}

/// cell_packet_verdicts' `maybe` alone.
inline int cell_packet_candidates(const CellPacket& packet, const FloatRay& ray) {
    return static_cast<int>(cell_packet_verdicts(packet, ray).maybe);
}

/// CellView::plane_polygon of a cell with no plane group in front.
inline constexpr std::uint32_t kNoPlaneGroup = 0xffffffffu;

/// A voxel's packets, and its bounds (voxel_bounds.h) where the structure has them.
struct CellView {
    const float* bounds = nullptr;  ///< lo x y z, hi x y z; null when the structure has none
    std::span<const CellPacket> packets;
    /// With bounds: the cell's largest plane group (in_plane_group, ray_polygon.h) of at least
    /// four lanes comes first, its first polygon `plane_polygon`, and fills the first
    /// `plane_packets` packets alone (kNoPlaneGroup and 0: none). A ray leaving a polygon with
    /// the group's normal may skip them (plane_group_certainly_missed).
    std::uint32_t plane_polygon = kNoPlaneGroup;
    std::uint32_t plane_packets = 0;
};

class CellPackets {
public:
    CellPackets() = default;
    /// Packets for cells 0 .. cells - 1, whose polygon ids ids_of(cell) gives; with
    /// `bounds_slots` != 0, each non-empty cell's bounds (in front of its ids) are copied in
    /// front of its packets, so the walk reads one run of memory per voxel. `threads` fill the
    /// cells (0: one a core for a large scene, parallel_parts.h); the packets are the same for
    /// any number. Throws Error, before allocating them, if they would take 2^32 - 1
    /// blocks or more.
    CellPackets(const Scene& scene, std::size_t cells, std::uint32_t bounds_slots,
                const std::function<std::span<const std::uint32_t>(std::size_t)>& ids_of,
                int threads = 0);

    CellView cell(std::size_t c) const { return blocks(first_block(c), block_count(c)); }
    /// Where cell c's header and packets start, and how many blocks they take (0: no packets):
    /// a structure that keeps these in its own nodes reads a cell without the table.
    std::uint32_t first_block(std::size_t c) const { return first_[c]; }
    std::uint32_t block_count(std::size_t c) const { return first_[c + 1] - first_[c]; }
    /// The cell whose header and packets are the `count` blocks from `first`.
    CellView blocks(std::uint32_t first, std::uint32_t count) const {
        if (count == 0) {
            return {};
        }
        const Block* begin = blocks_.data() + first;
        const Block* end = begin + count;
        CellView view;
        if (with_bounds_) {
            view.bounds = begin->f;
            std::memcpy(&view.plane_polygon, &begin[1].f[2], sizeof(std::uint32_t));
            std::memcpy(&view.plane_packets, &begin[1].f[3], sizeof(std::uint32_t));
            begin += kHeaderBlocks;
        }
        view.packets = {reinterpret_cast<const CellPacket*>(begin),
                        reinterpret_cast<const CellPacket*>(end)};
        return view;
    }
    /// Asks the cache for the start of the header and packets from block `first`.
    void prefetch_blocks(std::uint32_t first) const { prefetch(blocks_.data() + first); }
    /// The table indexed by cell number the walk may prefetch from.
    const std::uint32_t* cell_table() const { return first_.data(); }
    /// The largest |coordinate| of any finite lane corner: the FloatRay's scene scale covers it.
    double scale() const { return scale_; }
    std::size_t memory_bytes() const {
        return first_.capacity() * sizeof(std::uint32_t) + blocks_.capacity() * sizeof(Block);
    }

private:
    struct alignas(16) Block {
        float f[4];
    };
    /// The bounds (6 floats), then the plane group's polygon and packet count (as bits).
    static constexpr std::uint32_t kHeaderBlocks = 2;
    static constexpr std::uint32_t kPacketBlocks = sizeof(CellPacket) / sizeof(Block);
    static_assert(sizeof(CellPacket) % sizeof(Block) == 0);

    /// cells + 1: cell c's header and packets are blocks [first_[c], first_[c+1])
    std::vector<std::uint32_t> first_;
    std::vector<Block> blocks_;
    bool with_bounds_ = false;
    double scale_ = 0.0;
};

}  // namespace rt
