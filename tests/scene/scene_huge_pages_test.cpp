// Moving a scene's per-ray arrays to huge pages changes nothing a reader of the scene sees.
#include "rt/scene/scene.h"

#include <gtest/gtest.h>

#include "support/meshes/generated_meshes.h"

namespace rt {
namespace {

TEST(SceneHugePages, MovingKeepsEveryPositionCornerAndPolygon) {
    // 200k triangles: positions, corners and polygons each over the 4 MiB worth moving.
    Scene scene = test::make_triangle_soup(200000, 3);
    const Scene before = test::make_triangle_soup(200000, 3);
    move_to_huge_pages(scene);
    ASSERT_EQ(scene.positions.size(), before.positions.size());
    ASSERT_EQ(scene.corners, before.corners);
    ASSERT_EQ(scene.polygons.size(), before.polygons.size());
    for (std::size_t i = 0; i < scene.positions.size(); ++i) {
        ASSERT_EQ(scene.positions[i], before.positions[i]) << i;
    }
    for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
        ASSERT_EQ(scene.polygons[i].first_corner, before.polygons[i].first_corner) << i;
        ASSERT_EQ(scene.polygons[i].corner_count, before.polygons[i].corner_count) << i;
        ASSERT_EQ(scene.polygons[i].normal, before.polygons[i].normal) << i;
    }
    EXPECT_EQ(scene.positions.capacity(), scene.positions.size());
}

}  // namespace
}  // namespace rt
