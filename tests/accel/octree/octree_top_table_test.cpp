#include "rt/accel/octree/octree_top_table.h"

#include <algorithm>
#include <cstdint>
#include <random>

#include "rt/accel/octree/octree_ddda.h"

#include <gtest/gtest.h>

#include "accel/grid_test_support.h"

namespace rt {
namespace {

using test::random_triangle_soup;

OctreeTree tree_of(const Scene& scene, int depth) {
    OctreeBuildSettings settings;
    settings.depth = depth;
    return build_octree_depth_first(scene, settings);
}

// The leaf and its size, as the cursor without a table reports them.
struct Found {
    const OctreeNode* node;
    std::int64_t size;
};

Found found(const OctreeCursor& cursor) {
    const OctreeLeafAt leaf = cursor.leaf();
    return {leaf.node, leaf.size};
}

TEST(OctreeTopTable, LevelFollowsTheTreesSizeAndDepth) {
    const Scene soup = random_triangle_soup(3000, 5);
    EXPECT_EQ(make_top_table(tree_of(soup, 2)).level, 0);  // too shallow to need one
    const OctreeTree deep = tree_of(soup, 8);
    const OctreeTopTable table = make_top_table(deep);
    ASSERT_GE(table.level, 3);
    EXPECT_LE(table.level, 5);
    // No more cells than nodes.
    EXPECT_LE(table.entry.size(), deep.nodes.size());
    EXPECT_EQ(table.entry.size(), std::size_t{1} << (3 * table.level));
}

TEST(OctreeTopTable, CursorFindsTheSameLeavesWithAndWithoutIt) {
    for (const int depth : {4, 6, 8, 10}) {
        const OctreeTree tree = tree_of(random_triangle_soup(4000, 11), depth);
        const OctreeTopTable table = make_top_table(tree);
        ASSERT_GT(table.level, 0) << "depth " << depth;
        const std::int64_t last = (std::int64_t{1} << depth) - 1;
        std::mt19937 random(static_cast<std::uint32_t>(depth));
        std::uniform_int_distribution<std::int64_t> anywhere(0, last);
        std::uniform_int_distribution<std::int64_t> nearby(-3, 3);
        std::int64_t at[3] = {anywhere(random), anywhere(random), anywhere(random)};
        OctreeCursor plain(tree, at);
        OctreeCursor tabled(tree.nodes.data(), tree.depth, at, &table);
        for (int move = 0; move < 20000; ++move) {
            ASSERT_EQ(found(tabled).node, found(plain).node)
                << "depth " << depth << " move " << move;
            ASSERT_EQ(found(tabled).size, found(plain).size);
            // Mostly short steps, as the walk takes, and now and then a jump anywhere.
            for (std::int64_t& c : at) {
                c = move % 50 == 0 ? anywhere(random)
                                   : std::clamp<std::int64_t>(c + nearby(random), 0, last);
            }
            plain.move_to(at);
            tabled.move_to(at);
        }
    }
}

}  // namespace
}  // namespace rt
