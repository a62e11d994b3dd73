// A packet's corner indices in 32 bytes (lane_corners.h): a triangle keeps them only when its
// steps fit in 16 bits, gives them back exactly, and every method answers as brute force does
// whichever way its lanes went.
#include "rt/accel/lane_corners.h"

#include <cstdint>
#include <memory>

#include "rt/accel/make_accelerator.h"

#include <gtest/gtest.h>

#include "accel/accel_compare.h"
#include "support/meshes/generated_meshes.h"

namespace rt {
namespace {

TEST(LaneCorners, GiveBackTheIndicesWhoseStepsFit) {
    const std::uint32_t triangles[][3] = {
        {0, 1, 2},
        {70000, 69999, 100000},
        {100000, 100000 + 32767, 100000 - 32768},
        {0xfffffff0u, 0xfffffffeu, 0xffff8000u},
        {40000, 7233, 72767},
    };
    LaneCorners corners{};
    for (const auto& triangle : triangles) {
        for (int lane = 0; lane < 4; ++lane) {
            corners.set(lane, triangle);
            ASSERT_TRUE(corners.is_triangle(lane)) << triangle[0] << " lane " << lane;
            for (int v = 0; v < 3; ++v) {
                EXPECT_EQ(corners.corner(v, lane), triangle[v]) << triangle[0] << " lane " << lane;
            }
        }
    }
    corners.set(1, triangles[1]);
    corners.copy_lane(1, 3);
    for (int v = 0; v < 3; ++v) {
        EXPECT_EQ(corners.corner(v, 3), triangles[1][v]);
    }
}

TEST(LaneCorners, AreNotATriangleWhenAStepDoesNotFit) {
    const std::uint32_t far[][3] = {
        {100000, 100000 + 32768, 100000},
        {100000, 100000, 100000 - 32769},
        {0, 0xfffffffeu, 1},
        {kNotTriangle, 0, 1},
    };
    LaneCorners corners{};
    for (const auto& triangle : far) {
        corners.set(2, triangle);
        EXPECT_FALSE(corners.is_triangle(2)) << triangle[0] << ' ' << triangle[1];
    }
    corners.set(0, nullptr);
    EXPECT_FALSE(corners.is_triangle(0));
}

// A model whose faces index vertices anywhere: most triangles' steps do not fit, the others do,
// and every exact method answers as brute force does on random rays and rays aimed at corners.
TEST(LaneCorners, EveryMethodAnswersAsBruteForceWithCornersFarApart) {
    Scene scene = test::make_triangle_soup(3000, 17);
    test::scatter_positions(scene, 30, 5);
    for (const AccelKind kind : {AccelKind::Octree, AccelKind::Seads, AccelKind::Bvh}) {
        AccelSettings settings;
        settings.kind = kind;
        settings.octree.depth = suggested_octree_depth(scene.polygons.size());
        settings.seads_resolution = suggested_seads_resolution(scene.polygons.size());
        const std::unique_ptr<Accelerator> accel = make_accelerator(scene, settings);
        test::compare_with_brute_force(scene, *accel, 4000, 23);
    }
}

}  // namespace
}  // namespace rt
