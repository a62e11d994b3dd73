// The octree's memory layout (manual 2.2 "1 depth", part three): a cube halved along every axis
// at each level, down to at most the given depth, with nodes in one flat array (eight siblings
// side by side) and the leaves' polygon ids in another. Node boxes sit on an integer lattice of
// 2^depth steps a side, so the build and the DDDA compute every boundary the same way.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rt/accel/accel_settings.h"
#include "rt/accel/voxel/box.h"
#include "rt/scene/scene.h"

namespace rt {

/// The deepest octree built: 2^20 finest voxels a side keeps the lattice well inside an int.
inline constexpr int kMaxOctreeDepth = 20;
/// A node holding more polygons than this is split (while the depth allows).
inline constexpr std::uint32_t kMaxLeafPolygons = 16;
/// Default -ol and -ss: 2^24 nodes at most (128 MiB), 2^12 allocated at first.
inline constexpr int kDefaultOctlistPower = 24;
inline constexpr int kDefaultSeedSizePower = 12;

struct OctreeNode {
    static constexpr std::uint32_t kInterior = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t first = 0;  ///< interior: index of the first of 8 children; leaf: into polygons
    std::uint32_t count = 0;  ///< leaf: number of polygons; kInterior for an interior node
    bool is_leaf() const { return count != kInterior; }
    friend bool operator==(const OctreeNode&, const OctreeNode&) = default;
};

struct OctreeTree {
    Box3 world;                           ///< a cube (up to rounding)
    int depth = 0;                        ///< the finest level; the root is level 0
    Vec3 step;                            ///< world extent / 2^depth: one lattice step per axis
    Vec3 per_step;                        ///< 1 / step, for the walk (set with step)
    std::vector<OctreeNode> nodes;        ///< nodes[0] is the root; children in x, y, z bit order
    std::vector<std::uint32_t> polygons;  ///< each leaf's ids, ascending
    /// kVoxelBoundsSlots once add_leaf_bounds has put bounds in front of each leaf's ids, else 0.
    std::uint32_t bounds_slots = 0;

    /// Where lattice plane k along `axis` lies: the one formula the build and the walk share.
    double lattice(int axis, std::int64_t k) const {
        return world.lo[axis] + static_cast<double>(k) * step[axis];
    }
    std::span<const std::uint32_t> leaf_polygons(const OctreeNode& leaf) const {
        return {polygons.data() + leaf.first + (leaf.count != 0 ? bounds_slots : 0), leaf.count};
    }
    std::size_t memory_bytes() const {
        return nodes.capacity() * sizeof(OctreeNode) + polygons.capacity() * sizeof(std::uint32_t);
    }
};

/// Puts bounds (voxel_bounds.h) in front of every non-empty leaf's ids, if the leaves hold enough
/// polygons on average to be worth it; the same leaves and ids otherwise.
void add_leaf_bounds(const Scene& scene, OctreeTree& tree);

// Both fills need settings.depth; `no_fudge` (-of) files polygons in voxels without the fudge.
/// The default fill: each node's polygons sent to its children depth first.
OctreeTree build_octree_depth_first(const Scene& scene, const OctreeBuildSettings& settings,
                                    bool no_fudge = false);
/// -op, the "new fill-plane": one whole level of the tree at a time. The same tree, bit for bit.
OctreeTree build_octree_level_order(const Scene& scene, const OctreeBuildSettings& settings,
                                    bool no_fudge = false);

}  // namespace rt
