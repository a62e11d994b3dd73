// Bounds in front of the octree's leaves' ids (voxel_bounds.h), added after either fill so that
// both fills, and every thread count, still build the same tree first.
#include <cstdint>
#include <limits>
#include <vector>

#include "rt/accel/octree/octree_tree.h"
#include "rt/accel/voxel/voxel_bounds.h"

namespace rt {

void add_leaf_bounds(const Scene& scene, OctreeTree& tree) {
    std::size_t occupied = 0;
    for (const OctreeNode& node : tree.nodes) {
        occupied += node.is_leaf() && node.count != 0 ? 1 : 0;
    }
    // (The ids are at most 2^32 - 1 slots; bounds must not push them past it.)
    const std::uint64_t slots = tree.polygons.size() + std::uint64_t{kVoxelBoundsSlots} * occupied;
    if (tree.bounds_slots != 0 ||
        !worth_voxel_bounds(tree.polygons.size(), occupied, kLeafBoundsFromMeanPolygons) ||
        slots > std::numeric_limits<std::uint32_t>::max()) {
        return;
    }
    const double growth = voxel_fudge(tree.world, false);
    const std::vector<float> boxes = grown_polygon_boxes(scene, growth);
    std::vector<std::uint32_t> laid_out;
    laid_out.reserve(tree.polygons.size() + kVoxelBoundsSlots * occupied);
    // Depth first, children in order: the leaves keep the order the fills gave them.
    struct Pending {
        std::uint32_t node;
        std::int64_t origin[3];
        std::int64_t size;
    };
    std::vector<Pending> pending{{0, {0, 0, 0}, std::int64_t{1} << tree.depth}};
    while (!pending.empty()) {
        const Pending at = pending.back();
        pending.pop_back();
        OctreeNode& node = tree.nodes[at.node];
        if (!node.is_leaf()) {
            const std::int64_t half = at.size / 2;
            for (std::uint32_t child = 8; child-- > 0;) {
                pending.push_back({node.first + child,
                                   {at.origin[0] + ((child & 1) != 0 ? half : 0),
                                    at.origin[1] + ((child & 2) != 0 ? half : 0),
                                    at.origin[2] + ((child & 4) != 0 ? half : 0)},
                                   half});
            }
            continue;
        }
        const auto first = static_cast<std::uint32_t>(laid_out.size());
        if (node.count != 0) {
            Box3 leaf;
            for (int a = 0; a < 3; ++a) {
                leaf.lo[a] = tree.lattice(a, at.origin[a]);
                leaf.hi[a] = tree.lattice(a, at.origin[a] + at.size);
            }
            const std::span<const std::uint32_t> ids{tree.polygons.data() + node.first, node.count};
            append_voxel_bounds(boxes, ids, leaf, growth, laid_out);
            laid_out.insert(laid_out.end(), ids.begin(), ids.end());
        }
        node.first = first;
    }
    tree.polygons = std::move(laid_out);
    tree.bounds_slots = kVoxelBoundsSlots;
}

}  // namespace rt
