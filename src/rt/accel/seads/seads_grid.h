// The SEADS grid (manual 2.2: "N 0" in the scene header): N x N x N equal voxels over the world
// box, each with the ids of the polygons that touch it, in one flat array with an offset table.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "rt/accel/voxel/box.h"
#include "rt/accel/voxel/voxel_bounds.h"
#include "rt/scene/scene.h"

namespace rt {

/// The largest grid built: 2^25 voxels (322 a side), whose offset table alone is 128 MiB.
inline constexpr std::uint64_t kMaxSeadsVoxels = std::uint64_t{1} << 25;

struct SeadsGrid {
    Box3 world;
    int side = 1;     ///< voxels along each axis
    Vec3 voxel_size;  ///< world extent / side, per axis
    Vec3 per_voxel;   ///< 1 / voxel_size, for the walk (set with voxel_size)
    /// side^3 + 1: voxel v's entries are [offsets[v], offsets[v+1]), none for an empty voxel
    std::vector<std::uint32_t> offsets;
    /// Voxel after voxel, for each occupied one: its bounds (kVoxelBoundsSlots floats, as bits:
    /// the box around its polygons' parts within it, grown by the fudge), then its polygon ids,
    /// ascending. The bounds share the ids' first cache line, so a ray that passes through a
    /// voxel but not near its polygons skips them all for one box test and no extra miss.
    std::vector<std::uint32_t> polygons;
    /// kVoxelBoundsSlots if the occupied voxels carry bounds (voxel_bounds.h), else 0.
    std::uint32_t bounds_slots = 0;
    /// Per voxel, how far the nearest voxel holding polygons is, counted in voxels along the
    /// farthest axis (the chessboard distance), at most 255: 0 for a voxel with polygons, and
    /// for an empty one with clearance c every voxel within c - 1 steps on every axis is empty
    /// too, so the walk can leap out of that cube at once ("proximity clouds"). One byte a
    /// voxel, 1/4 of the offset table, so the walk through empty space stays in cache.
    std::vector<std::uint8_t> clearance;

    std::size_t index(int x, int y, int z) const {
        return (static_cast<std::size_t>(z) * side + y) * side + x;
    }
    std::span<const std::uint32_t> voxel(std::size_t v) const {
        if (offsets[v] == offsets[v + 1]) {
            return {};
        }
        return {polygons.data() + offsets[v] + bounds_slots, polygons.data() + offsets[v + 1]};
    }
    /// The box of voxel (x, y, z), not grown.
    Box3 voxel_box(int x, int y, int z) const;
    std::size_t memory_bytes() const {
        return offsets.capacity() * sizeof(std::uint32_t) +
               polygons.capacity() * sizeof(std::uint32_t) +
               clearance.capacity() * sizeof(std::uint8_t);
    }
};

/// Files every polygon in each voxel it touches, each voxel grown by the fudge for the test.
/// Throws SettingError for a side below 1 or a grid above kMaxSeadsVoxels, before allocating.
SeadsGrid build_seads_grid(const Scene& scene, int side, bool no_fudge);

}  // namespace rt
