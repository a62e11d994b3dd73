// The octree depth a scene gets when nothing names one: measured from how its polygons fill
// space, so a surface goes deeper than a soup of as many polygons.
#include "rt/accel/octree_depth_for.h"

#include "rt/accel/accel_settings.h"

#include <gtest/gtest.h>

#include "support/meshes/generated_meshes.h"

namespace rt {
namespace {

TEST(OctreeDepthFor, SmallScenesTakeTheRuleForTheirCount) {
    for (const std::uint32_t triangles : {1u, 142u, 1000u, 4000u}) {
        const Scene soup = test::make_triangle_soup(triangles);
        EXPECT_EQ(octree_depth_for(soup), suggested_octree_depth(soup.polygons.size()))
            << triangles;
    }
}

TEST(OctreeDepthFor, ASurfaceGoesDeeperThanASoupOfAsManyPolygons) {
    const Scene sphere = test::make_tessellated_sphere(100000);
    const Scene soup = test::make_triangle_soup(100000);
    EXPECT_EQ(octree_depth_for(sphere), 5);
    EXPECT_EQ(octree_depth_for(soup), 4);
    EXPECT_EQ(octree_depth_for(test::make_cube_sphere(100000)), 5);
    EXPECT_EQ(octree_depth_for(test::make_tessellated_sphere(10000)), 4);
    EXPECT_EQ(octree_depth_for(test::make_triangle_soup(10000)), 3);
}

TEST(OctreeDepthFor, FromOccupancyFollowsTheGrowthOfOccupiedCells) {
    // A volume: all 64 cells of level 2 and all 4096 of level 4 occupied; 12 polygons a cell at
    // depth d when 12 * 8^d polygons.
    EXPECT_EQ(octree_depth_from_occupancy(12 * 4096, 2, 64, 4096), 4);
    EXPECT_EQ(octree_depth_from_occupancy(12 * 32768, 2, 64, 4096), 5);
    // A surface: occupied cells four times as many a level.
    EXPECT_EQ(octree_depth_from_occupancy(12 * 40 * 256, 2, 40, 640), 6);
    // Fewer polygons than 20 a cell even at the coarse level: no deeper than it.
    EXPECT_EQ(octree_depth_from_occupancy(100, 3, 64, 500), 3);
    // Degenerate counts stay within 1 to 20.
    EXPECT_EQ(octree_depth_from_occupancy(0, 1, 0, 0), 1);
    EXPECT_EQ(octree_depth_from_occupancy(std::size_t{1} << 62, 4, 1, 1), 20);
}

}  // namespace
}  // namespace rt
