// A model's node transforms: composed parent first, normals by the inverse transpose, mirrors
// detected.
#include "rt/scene/read/node_transform.h"

#include <cmath>

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(NodeTransform, ComposesParentThenChild) {
    // Parent: move by (10, 0, 0). Child: scale x by 2.
    const NodeTransform t = NodeTransform{}
                                .then({{{1, 0, 0, 10}, {0, 1, 0, 0}, {0, 0, 1, 0}}})
                                .then({{{2, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}});
    EXPECT_EQ(t.point({1, 2, 3}), (Vec3{12, 2, 3}));
    EXPECT_FALSE(t.mirrors());
}

TEST(NodeTransform, NormalsFollowTheInverseTranspose) {
    // Stretching x by 2 tilts a 45-degree normal towards y: (1, 1) -> (1/2, 1), normalised.
    const NodeTransform t = NodeTransform{}.then({{{2, 0, 0, 5}, {0, 1, 0, 0}, {0, 0, 1, 0}}});
    const Vec3 n = t.direction({1, 1, 0});
    EXPECT_NEAR(n.x, 1 / std::sqrt(5.0), 1e-15);
    EXPECT_NEAR(n.y, 2 / std::sqrt(5.0), 1e-15);
    EXPECT_EQ(n.z, 0.0);
    EXPECT_EQ(t.direction({0, 0, 0}), Vec3{});
}

TEST(NodeTransform, AMirrorKeepsNormalsOutward) {
    const NodeTransform t = NodeTransform{}.then({{{-1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}});
    EXPECT_TRUE(t.mirrors());
    EXPECT_EQ(t.direction({1, 0, 0}), (Vec3{-1, 0, 0}));  // the point (1,0,0)'s side went to -x
    // Flattened in x: a normal along x survives, one along y has no surface left.
    const NodeTransform flat = NodeTransform{}.then({{{0, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}});
    EXPECT_EQ(flat.direction({1, 0, 0}), (Vec3{1, 0, 0}));
    EXPECT_EQ(flat.direction({0, 1, 0}), Vec3{});
}

}  // namespace
}  // namespace rt
