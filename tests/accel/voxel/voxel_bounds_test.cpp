// Bounds in front of a voxel's ids (voxel_bounds.h): they hold every polygon's part within the
// voxel, and skipping voxels by them leaves every answer brute force's.
#include "rt/accel/voxel/voxel_bounds.h"

#include "rt/accel/octree/octree.h"
#include "rt/accel/seads/seads.h"

#include <gtest/gtest.h>

#include "accel/grid_test_support.h"

namespace rt::test {
namespace {

// Dense enough that coarse voxels hold far more than kBoundsFromMeanPolygons polygons each.
Scene dense_sphere() {
    return make_sphere({0.1, -0.2, 0.3}, 1.5, 40, 60, true);
}

// SEADS with 5 voxels a side: some 30 polygons a voxel on the dense sphere.
AccelSettings coarse_seads() {
    AccelSettings settings;
    settings.kind = AccelKind::Seads;
    settings.seads_resolution = 5;
    return settings;
}

TEST(VoxelBounds, SeadsBoundsHoldEveryPolygonsPartInTheVoxel) {
    const Scene scene = dense_sphere();
    const Seads accel(scene, coarse_seads());
    const SeadsGrid& grid = accel.grid();
    ASSERT_EQ(grid.bounds_slots, kVoxelBoundsSlots);
    int checked = 0;
    for (int z = 0; z < grid.side; ++z) {
        for (int y = 0; y < grid.side; ++y) {
            for (int x = 0; x < grid.side; ++x) {
                const auto ids = grid.voxel(grid.index(x, y, z));
                if (ids.empty()) {
                    continue;
                }
                const std::array<float, 6> bounds = bounds_before(ids);
                const Box3 voxel = grid.voxel_box(x, y, z);
                for (const std::uint32_t id : ids) {
                    const Box3 b = polygon_bounds(scene, id);
                    for (int a = 0; a < 3; ++a) {
                        EXPECT_LE(bounds[a], std::max(b.lo[a], voxel.lo[a]));
                        EXPECT_GE(bounds[3 + a], std::min(b.hi[a], voxel.hi[a]));
                    }
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(checked, 4000);
}

TEST(VoxelBounds, SkippingByThemMatchesBruteForce) {
    const Scene scene = dense_sphere();
    const Seads on_grid(scene, coarse_seads());
    ASSERT_EQ(on_grid.grid().bounds_slots, kVoxelBoundsSlots);
    expect_same_as_brute_force(scene, on_grid, random_rays(on_grid.grid().world, 20000, 31));

    AccelSettings octree;
    octree.kind = AccelKind::Octree;
    octree.octree.depth = 2;
    const Octree on_tree(scene, octree);
    ASSERT_EQ(on_tree.tree().bounds_slots, kVoxelBoundsSlots);
    expect_same_as_brute_force(scene, on_tree, random_rays(on_tree.tree().world, 20000, 32));
}

TEST(VoxelBounds, BothOctreeFillsStillGiveTheSameTree) {
    const Scene scene = dense_sphere();
    AccelSettings settings;
    settings.kind = AccelKind::Octree;
    settings.octree.depth = 3;
    const Octree depth_first(scene, settings);
    settings.octree.level_order = true;
    const Octree level_order(scene, settings);
    EXPECT_EQ(depth_first.tree().nodes, level_order.tree().nodes);
    EXPECT_EQ(depth_first.tree().polygons, level_order.tree().polygons);
}

TEST(VoxelBounds, OnlyWhereVoxelsHoldManyPolygons) {
    EXPECT_FALSE(worth_voxel_bounds(0, 0));
    EXPECT_FALSE(worth_voxel_bounds(90, 10));
    EXPECT_TRUE(worth_voxel_bounds(100, 10));
    EXPECT_FALSE(worth_voxel_bounds(19, 10, kLeafBoundsFromMeanPolygons));
    EXPECT_TRUE(worth_voxel_bounds(20, 10, kLeafBoundsFromMeanPolygons));
}

}  // namespace
}  // namespace rt::test
