// Bounds in front of a voxel's polygon ids (SEADS voxels and octree leaves): the box around its
// polygons' parts within it, so that a ray passing through the voxel but not near its polygons
// skips them all after one box test. The bounds take the first 6 of the voxel's 32-bit slots
// (floats, as bits), in the cache line of its first ids: no extra memory access.
//
// Why skipping is safe: a ray's nearest hit lies at a point P of its polygon, and the walk visits
// a voxel whose box grown by the fudge holds P (box.h), where the polygon is filed; the polygon's
// box grown by the fudge, clipped to that voxel grown by twice the fudge, holds P, so the bounds
// do, and the line through P meets them. A polygon skipped in one voxel is not marked as tested,
// so it is still tested in the voxel that holds its hit. The answers stay brute force's.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rt/accel/voxel/box.h"
#include "rt/scene/scene.h"

namespace rt {

/// Slots (of 32 bits) the bounds take in front of a voxel's ids.
inline constexpr std::uint32_t kVoxelBoundsSlots = 6;
/// SEADS voxels get bounds when the occupied ones hold at least this many polygons on average:
/// with fewer, the voxel's few packets cost about what the one test of the bounds would.
inline constexpr double kBoundsFromMeanPolygons = 10.0;
/// The octree's leaves, from this many: a leaf's test is a float test per packet of four fan
/// triangles, and its bounds pay from sparser leaves (twocubes4; docs/accelerators.md).
inline constexpr double kLeafBoundsFromMeanPolygons = 2.0;

/// Whether a structure whose `occupied` voxels hold `references` polygon ids in all gets bounds.
inline bool worth_voxel_bounds(std::size_t references, std::size_t occupied,
                               double from_mean = kBoundsFromMeanPolygons) {
    return occupied > 0 &&
           static_cast<double>(references) >= from_mean * static_cast<double>(occupied);
}

/// Each polygon's box grown by `growth`, as floats rounded outward: lo x y z, hi x y z.
std::vector<float> grown_polygon_boxes(const Scene& scene, double growth);

/// Appends to `out` the bounds of the voxel `voxel` holding `ids`: the union of their boxes from
/// grown_polygon_boxes(scene, growth), clipped to the voxel grown by 2 * growth.
void append_voxel_bounds(const std::vector<float>& grown_boxes, std::span<const std::uint32_t> ids,
                         const Box3& voxel, double growth, std::vector<std::uint32_t>& out);

/// The bounds in front of `ids` (a voxel's ids, from a structure that has bounds).
inline std::array<float, 6> bounds_before(std::span<const std::uint32_t> ids) {
    std::array<float, 6> box{};
    const std::uint32_t* slots = ids.data() - kVoxelBoundsSlots;
    for (std::size_t k = 0; k < 6; ++k) {
        box[k] = std::bit_cast<float>(slots[k]);
    }
    return box;
}

}  // namespace rt
