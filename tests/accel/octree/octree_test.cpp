// The octree against brute force: identical answers on random and adversarial rays at depths 0 to
// the maximum, and its limits (-ol) and build settings (-ss, -op).
#include "rt/accel/octree/octree.h"

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
