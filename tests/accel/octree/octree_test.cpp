// The octree against brute force: identical answers on random and adversarial rays at depths 0 to
// the maximum, and its limits (-ol) and build settings (-ss, -op).
#include "rt/accel/octree/octree.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "rt/accel/octree/octree_ddda.h"
#include "rt/core/diagnostics.h"
#include "rt/core/error.h"
#include "rt/scene/read/load_scene.h"

#include <gtest/gtest.h>

#include "accel/grid_test_support.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

OctreeBuildSettings at_depth(int depth, int seed_size_power = kDefaultSeedSizePower) {
    OctreeBuildSettings s;
    s.depth = depth;
    s.seed_size_power = seed_size_power;
    return s;
}

AccelSettings octree(int depth) {
    AccelSettings s;
    s.kind = AccelKind::Octree;
    s.octree.depth = depth;
    return s;
}

TEST(Octree, RandomSoupMatchesBruteForceAtEveryDepth) {
    const Scene scene = random_triangle_soup(300, 21);
    for (const int depth : {0, 1, 3, 6, kMaxOctreeDepth}) {
        const Octree accel(scene, octree(depth));
        expect_same_as_brute_force(scene, accel, random_rays(accel.tree().world, 10000, depth));
    }
}

TEST(Octree, ClosedMeshesMatchBruteForceDownToTheMaximumDepth) {
    // The poles' 24 triangles share a corner, so the tree goes down to the last level there.
    const Scene sphere = make_sphere({0.1, 0.2, 0.3}, 2.0, 16, 24, true);
    for (const int depth : {5, kMaxOctreeDepth}) {
        const Octree accel(sphere, octree(depth));
        expect_same_as_brute_force(sphere, accel, random_rays(accel.tree().world, 10000, 5));
    }
    const Scene fan = make_fan(40, 1.0);
    const Octree on_fan(fan, octree(kMaxOctreeDepth));
    expect_same_as_brute_force(fan, on_fan, random_rays(on_fan.tree().world, 5000, 6));
}

TEST(Octree, TwoCubesSceneMatchesBruteForce) {
    Diagnostics diagnostics;
    const Scene scene =
        load_scene(source_dir() / "scenes/twocubes.scn", ReaderDialect{}, diagnostics);
    const Octree accel(scene, octree(4));
    expect_same_as_brute_force(scene, accel, random_rays(accel.tree().world, 15000, 7));
}

TEST(Octree, PolygonsInVoxelFacesAndRaysAlongThemMatchBruteForce) {
    for (const int depth : {2, 4}) {
        Scene scene = unit_cube_anchors();
        const OctreeTree bare = build_octree_depth_first(scene, at_depth(depth));
        const Lattice lattice = [&bare](int axis, int k) { return bare.lattice(axis, k); };
        const int divisions = 1 << depth;
        add_lattice_faces(scene, lattice, divisions, 150, depth);
        const Octree accel(scene, octree(depth));
        ASSERT_EQ(accel.tree().world.lo, bare.world.lo);
        expect_same_as_brute_force(scene, accel, lattice_rays(lattice, divisions, 12000, 3));
    }
}

// Every leaf of `tree` with its box, from the lattice as the walk computes it.
struct LeafBox {
    const OctreeNode* node;
    Box3 box;
};

void collect_leaves(const OctreeTree& tree, std::uint32_t n, const std::int64_t origin[3],
                    std::int64_t size, std::vector<LeafBox>& leaves) {
    const OctreeNode& node = tree.nodes[n];
    if (node.is_leaf()) {
        Box3 box;
        for (int a = 0; a < 3; ++a) {
            box.lo[a] = tree.lattice(a, origin[a]);
            box.hi[a] = tree.lattice(a, origin[a] + size);
        }
        leaves.push_back({&node, box});
        return;
    }
    for (std::uint32_t child = 0; child < 8; ++child) {
        const std::int64_t half = size / 2;
        const std::int64_t at[3] = {origin[0] + ((child & 1u) != 0 ? half : 0),
                                    origin[1] + ((child & 2u) != 0 ? half : 0),
                                    origin[2] + ((child & 4u) != 0 ? half : 0)};
        collect_leaves(tree, node.first + child, at, half, leaves);
    }
}

// Where the ray's line is inside `box` within `t`, by the slab method: {entry, exit}, entry >
// exit when it never is.
Interval line_inside(const Ray& ray, const Box3& box, Interval t) {
    for (int a = 0; a < 3; ++a) {
        if (ray.direction[a] == 0.0) {
            if (ray.origin[a] < box.lo[a] || ray.origin[a] > box.hi[a]) {
                return {1.0, 0.0};
            }
            continue;
        }
        const double t0 = (box.lo[a] - ray.origin[a]) / ray.direction[a];
        const double t1 = (box.hi[a] - ray.origin[a]) / ray.direction[a];
        t.min = std::max(t.min, std::min(t0, t1));
        t.max = std::min(t.max, std::max(t0, t1));
    }
    return t;
}

// The walk against the leaves' boxes themselves, on a tree whose leaves range from the finest
// lattice step to large empty cubes: each leaf the line crosses for more than a sliver is
// visited, each leaf at most once, in the order the line enters them, and none that the line
// misses by more than a sliver.
TEST(Octree, WalkVisitsTheLeavesTheRayCrossesInOrder) {
    const Scene sphere = make_sphere({0.1, 0.2, 0.3}, 2.0, 24, 32, true);
    for (const int depth : {4, 7}) {
        const OctreeTree tree = build_octree_depth_first(sphere, at_depth(depth));
        std::vector<LeafBox> leaves;
        const std::int64_t root[3] = {0, 0, 0};
        collect_leaves(tree, 0, root, std::int64_t{1} << depth, leaves);
        ASSERT_GT(leaves.size(), 100u);
        const Vec3 extent = tree.world.extent();
        const double sliver = 1e-9 * std::max({extent.x, extent.y, extent.z});
        int crossings = 0;
        for (const RayCase& c : random_rays(tree.world, 3000, 17)) {
            std::vector<const OctreeNode*> walked;
            walk_octree(tree, c.ray, c.t, [&](auto, double, const OctreeLeafAt& leaf) {
                walked.push_back(leaf.node);
                return false;
            });
            const double speed = length(c.ray.direction);
            std::vector<std::pair<double, const OctreeNode*>> crossed;
            for (const LeafBox& leaf : leaves) {
                const Interval in = line_inside(c.ray, leaf.box, c.t);
                if ((in.max - in.min) * speed > sliver) {
                    crossed.emplace_back(in.min, leaf.node);
                }
                if (std::find(walked.begin(), walked.end(), leaf.node) != walked.end()) {
                    EXPECT_GE((in.max - in.min) * speed, -sliver)
                        << "visited a leaf the line misses: " << describe(c);
                }
            }
            std::sort(crossed.begin(), crossed.end());
            crossings += static_cast<int>(crossed.size());
            EXPECT_EQ(std::set<const OctreeNode*>(walked.begin(), walked.end()).size(),
                      walked.size())
                << "a leaf visited twice: " << describe(c);
            // The crossed leaves appear in the walk in the order the line enters them.
            std::size_t next = 0;
            for (const auto& [entry, node] : crossed) {
                const auto found =
                    std::find(walked.begin() + static_cast<long>(next), walked.end(), node);
                ASSERT_NE(found, walked.end())
                    << "depth " << depth << ": missed or out of order a leaf entered at t " << entry
                    << ": " << describe(c);
                next = static_cast<std::size_t>(found - walked.begin()) + 1;
            }
        }
        EXPECT_GT(crossings, 3000) << "depth " << depth;
    }
}

// The walk that finds each next leaf before visiting the current one (to prefetch it) and the
// one that finds it after (a small tree's) visit the same leaves in the same order, and stop at
// the same one when a visit ends the walk.
TEST(Octree, BothWalkFormsVisitTheSameLeaves) {
    const Scene sphere = make_sphere({0.1, 0.2, 0.3}, 2.0, 24, 32, true);
    for (const int depth : {3, 6}) {
        const OctreeTree tree = build_octree_depth_first(sphere, at_depth(depth));
        int stopped = 0;
        for (const RayCase& c : random_rays(tree.world, 2000, 23)) {
            Interval inside;
            if (!clip_to_box(c.ray, tree.world, c.t, inside)) {
                continue;
            }
            const Vec3& d = c.ray.direction;
            const Vec3 inverse{1.0 / d.x, 1.0 / d.y, 1.0 / d.z};
            for (const std::size_t stop_after :
                 {std::size_t{1}, std::size_t{3}, std::size_t{1000}}) {
                std::vector<const OctreeNode*> ahead;
                std::vector<const OctreeNode*> after;
                std::size_t prefetched = 0;
                walk_octree_leaves<true>(
                    tree, tree.nodes.data(), nullptr, c.ray, inverse, inside,
                    [&](double, const OctreeLeafAt& leaf) {
                        ahead.push_back(leaf.node);
                        return ahead.size() == stop_after;
                    },
                    [&](const OctreeNode*) { ++prefetched; });
                walk_octree_leaves<false>(
                    tree, tree.nodes.data(), nullptr, c.ray, inverse, inside,
                    [&](double, const OctreeLeafAt& leaf) {
                        after.push_back(leaf.node);
                        return after.size() == stop_after;
                    },
                    [&](const OctreeNode*) { ADD_FAILURE() << "prefetch without look-ahead"; });
                ASSERT_EQ(ahead, after) << describe(c);
                stopped += ahead.size() == stop_after ? 1 : 0;
                EXPECT_GE(prefetched + 1, ahead.size());
            }
        }
        EXPECT_GT(stopped, 1000) << "depth " << depth;
    }
}

TEST(Octree, BothFillsBuildTheSameTree) {
    const std::vector<Scene> scenes = {random_triangle_soup(500, 31),
                                       make_sphere({0, 0, 0}, 1.0, 12, 20, false),
                                       make_fan(30, 2.0)};
    for (const Scene& scene : scenes) {
        for (const int depth : {0, 3, 8}) {
            const OctreeTree a = build_octree_depth_first(scene, at_depth(depth));
            const OctreeTree b = build_octree_level_order(scene, at_depth(depth));
            EXPECT_EQ(a.nodes, b.nodes) << depth;
            EXPECT_EQ(a.polygons, b.polygons) << depth;
        }
    }
}

TEST(Octree, ThreadCountDoesNotChangeTheTree) {
    const std::vector<Scene> scenes = {random_triangle_soup(3000, 34),
                                       make_sphere({0, 0, 0}, 1.0, 24, 40, false)};
    for (const Scene& scene : scenes) {
        for (const int depth : {0, 1, 2, 6}) {
            OctreeBuildSettings settings = at_depth(depth);
            settings.threads = 1;
            const OctreeTree one = build_octree_depth_first(scene, settings);
            for (const unsigned threads : {2u, 3u, 16u, 64u}) {
                settings.threads = threads;
                const OctreeTree many = build_octree_depth_first(scene, settings);
                EXPECT_EQ(one.nodes, many.nodes) << depth << " " << threads;
                EXPECT_EQ(one.polygons, many.polygons) << depth << " " << threads;
                EXPECT_EQ(many.nodes.capacity(), many.nodes.size());
                EXPECT_EQ(many.polygons.capacity(), many.polygons.size());
            }
        }
    }
}

TEST(Octree, RunningOutOfOctlistIsTheSameErrorOnAnyThreadCount) {
    const Scene scene = random_triangle_soup(3000, 35);
    OctreeBuildSettings settings = at_depth(7);
    settings.threads = 1;
    const std::size_t needed = build_octree_depth_first(scene, settings).nodes.size();
    int power = 0;
    while ((std::size_t{1} << power) < needed) {
        ++power;
    }
    for (const unsigned threads : {1u, 2u, 16u}) {
        settings.threads = threads;
        settings.octlist_power = power;
        EXPECT_EQ(build_octree_depth_first(scene, settings).nodes.size(), needed) << threads;
        settings.octlist_power = power - 1;
        try {
            build_octree_depth_first(scene, settings);
            ADD_FAILURE() << "no error for -ol " << power - 1 << " on " << threads << " threads";
        } catch (const SettingError& e) {
            EXPECT_EQ(e.setting(), "octree node limit");
            EXPECT_NE(std::string(e.what()).find("raise the octree node limit"), std::string::npos)
                << e.what();
        }
    }
}

TEST(Octree, SeedSizeDoesNotChangeTheTree) {
    const Scene scene = random_triangle_soup(400, 32);
    const OctreeTree a = build_octree_depth_first(scene, at_depth(6, 0));
    const OctreeTree b = build_octree_depth_first(scene, at_depth(6, 16));
    EXPECT_EQ(a.nodes, b.nodes);
    EXPECT_EQ(a.polygons, b.polygons);
}

TEST(Octree, RunningOutOfOctlistIsAClearError) {
    const Scene scene = random_triangle_soup(400, 33);
    const std::size_t needed = build_octree_depth_first(scene, at_depth(6)).nodes.size();
    int power = 0;
    while ((std::size_t{1} << power) < needed) {
        ++power;
    }
    AccelSettings settings = octree(6);
    settings.octree.octlist_power = power;
    EXPECT_NO_THROW(Octree(scene, settings));
    settings.octree.octlist_power = power - 1;
    for (const bool level_order : {false, true}) {
        settings.octree.level_order = level_order;
        try {
            Octree accel(scene, settings);
            ADD_FAILURE() << "no error for -ol " << power - 1;
        } catch (const SettingError& e) {
            EXPECT_EQ(e.setting(), "octree node limit");
            EXPECT_NE(std::string(e.what()).find("raise the octree node limit"), std::string::npos)
                << e.what();
        }
    }
}

TEST(Octree, RefusesDepthsOutsideTheLattice) {
    const Scene scene = make_box({0, 0, 0}, {1, 1, 1}, true);
    EXPECT_THROW(Octree(scene, octree(-1)), UsageError);
    EXPECT_THROW(Octree(scene, octree(kMaxOctreeDepth + 1)), UsageError);
}

TEST(Octree, LeavesHoldFewPolygonsUnlessAtTheFinestLevel) {
    const Scene scene = random_triangle_soup(1000, 34);
    const Octree accel(scene, octree(10));
    std::size_t leaves = 0;
    for (const OctreeNode& node : accel.tree().nodes) {
        leaves += node.is_leaf() ? 1 : 0;
    }
    EXPECT_GT(leaves, 1000u / kMaxLeafPolygons);
    EXPECT_LT(accel.memory_bytes(), 1000u * 250u);  // with leaf bounds and packets
}

}  // namespace
}  // namespace rt::test
