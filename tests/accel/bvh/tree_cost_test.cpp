// The tree's expected cost in Embree's measure, on a tree laid out by hand whose shares are
// worked out below, and on the edge cases: no tree, and a tree that is one leaf. Then the
// builder's trees for the lab's 10k meshes, against their cost when measured: a change that
// makes the trees worse fails here, whatever the machine's load does to the rates.
#include "rt/accel/bvh/tree_cost.h"

#include <array>
#include <cstdint>

#include "rt/accel/bvh/bvh.h"

#include <gtest/gtest.h>

#include "support/meshes/generated_meshes.h"

namespace rt::bvh {
namespace {

using Bounds = std::array<float, 6>;  // lo x, y, z, hi x, y, z

WideNode node_of(std::initializer_list<std::pair<std::uint32_t, Bounds>> children) {
    WideNode node{};
    for (int c = 0; c < 8; ++c) {
        node.child[c] = kNoChild;
    }
    int c = 0;
    for (const auto& [child, b] : children) {
        node.child[c] = child;
        for (int k = 0; k < 3; ++k) {
            node.lo[k][c] = b[k];
            node.hi[k][c] = b[3 + k];
        }
        ++c;
    }
    return node;
}

TrianglePacket packet(bool last) {
    TrianglePacket p{};
    p.polygon[3] = last ? kLastPacketBit : 0;
    return p;
}

TEST(TreeCost, SharesOfTheRootsSurface) {
    Hierarchy tree;
    tree.packets.resize(4);
    tree.packets[0] = packet(false);  // a leaf of two packets
    tree.packets[1] = packet(true);
    tree.packets[2] = packet(true);
    tree.packets[3] = packet(true);
    tree.wide.resize(2);
    // The root's box is its children's union, 2 x 1 x 1: half its surface is 2 + 1 + 2 = 5.
    tree.wide[0] = node_of({{kLeafBit | 0, {0, 0, 0, 2, 1, 1}},  // the whole root: 2 packets
                            {1, {0, 0, 0, 1, 1, 1}}});           // a node, 3 / 5 = 0.6
    tree.wide[1] = node_of({{kLeafBit | 2, {0, 0, 0, 1, 1, 0}},  // flat: 1 / 5 = 0.2
                            {kLeafBit | 3, {0.5, 0.5, 0.5, 1, 1, 1}}});  // 0.75 / 5 = 0.15
    tree.root = 0;
    const TreeCost cost = tree_cost(tree);
    EXPECT_DOUBLE_EQ(cost.nodes, 1.0 + 0.6);
    EXPECT_DOUBLE_EQ(cost.leaves, 2 * 1.0 + 0.2 + 0.15);
    EXPECT_DOUBLE_EQ(cost.leaf_pairs, 1.0 + 0.2 + 0.15);  // the two packets are one pair
    EXPECT_DOUBLE_EQ(cost.total(), 3.95);
    EXPECT_DOUBLE_EQ(cost.total_in_pairs(), 2.95);
    EXPECT_EQ(cost.leaf_count, 3u);
    EXPECT_DOUBLE_EQ(cost.fill, 4.0 / 16.0);
    // The leaves' shares alone, whatever their packets: 1 + 0.2 + 0.15.
    EXPECT_DOUBLE_EQ(leaves_a_line_crosses(tree), 1.35);
}

TEST(TreeCost, NoTreeCostsNothingAndALeafItsPackets) {
    const Hierarchy empty;
    EXPECT_EQ(tree_cost(empty).total(), 0.0);
    EXPECT_EQ(tree_cost(empty).leaf_count, 0u);

    Hierarchy leaf;
    leaf.packets = {packet(false), packet(false), packet(true)};
    leaf.root = kLeafBit | 0;
    EXPECT_EQ(tree_cost(leaf).nodes, 0.0);
    EXPECT_EQ(tree_cost(leaf).leaves, 3.0);
    EXPECT_EQ(tree_cost(leaf).leaf_pairs, 2.0);
    EXPECT_EQ(tree_cost(leaf).leaf_count, 1u);
    EXPECT_EQ(leaves_a_line_crosses(empty), 0.0);
    EXPECT_EQ(leaves_a_line_crosses(leaf), 1.0);
}

TEST(TreeCost, TheLabsMeshesCostNoMoreThanWhenMeasured) {
    // This builder's costs on 2026-12-06 (docs/lab/tree-cost-2026-12-06.md), 1 % allowed, in
    // packets and in the pairs of packets the walk tests at once. A builder that makes better
    // trees should lower them. Embree 3.13.5's own trees of the same meshes cost 10.80 (sphere)
    // and 27.75 (soup), in its blocks of four triangles.
    const Scene sphere_scene = test::make_tessellated_sphere(10000);
    const Scene soup_scene = test::make_triangle_soup(10000);
    const TreeCost sphere = Bvh(sphere_scene).tree_cost();
    const TreeCost soup = Bvh(soup_scene).tree_cost();
    EXPECT_LE(sphere.total(), 12.51 * 1.01);
    EXPECT_LE(soup.total(), 35.40 * 1.01);
    EXPECT_LE(sphere.total_in_pairs(), 10.39 * 1.01);
    EXPECT_LE(soup.total_in_pairs(), 26.56 * 1.01);
}

TEST(TreeCost, OnlyRaysThroughASurfaceAskForTheirFirstLeafsRecords) {
    // A line crosses about two of a sphere's leaves, and the first a ray enters usually holds its
    // hit; it crosses a dozen of the 10k soup's, where the records would be asked for in vain.
    const Scene sphere_scene = test::make_tessellated_sphere(10000);
    const Scene soup_scene = test::make_triangle_soup(10000);
    const Bvh sphere(sphere_scene);
    const Bvh soup(soup_scene);
    EXPECT_LT(sphere.leaves_a_line_crosses(), 4.0);
    EXPECT_TRUE(sphere.asks_first_leaf_records());
    EXPECT_GT(soup.leaves_a_line_crosses(), 9.0);
    EXPECT_FALSE(soup.asks_first_leaf_records());
}

}  // namespace
}  // namespace rt::bvh
