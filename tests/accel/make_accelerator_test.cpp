// make_accelerator and the names and sizes around it: each --accel name builds its method, which
// answers as brute force does, and the suggested voxel sizes follow their documented rule.
#include "rt/accel/make_accelerator.h"

#include <cmath>
#include <random>
#include <string>

#include "rt/accel/brute_force.h"
#include "rt/core/error.h"

#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"

namespace rt {
namespace {

constexpr AccelKind kKinds[] = {AccelKind::BruteForce, AccelKind::Octree, AccelKind::Seads,
                                AccelKind::Bvh, AccelKind::Embree};

TEST(AccelKindNames, AreTheOnesAccelTakesBothWays) {
    const char* const names[] = {"brute", "octree", "seads", "bvh", "embree"};
    for (int i = 0; i < 5; ++i) {
        EXPECT_EQ(accel_kind_name(kKinds[i]), names[i]);
        EXPECT_EQ(accel_kind_from_name(names[i]), kKinds[i]) << names[i];
    }
    for (const char* unknown : {"", "BVH", "brute force", "octree ", "grid"}) {
        EXPECT_FALSE(accel_kind_from_name(unknown).has_value()) << "'" << unknown << "'";
    }
}

TEST(SuggestedVoxelSizes, SeadsIsSevenTenthsOfTheCubeRootClampedTo4Through322) {
    EXPECT_EQ(suggested_seads_resolution(0), 4);
    EXPECT_EQ(suggested_seads_resolution(27), 4);
    EXPECT_EQ(suggested_seads_resolution(1000), 7);
    EXPECT_EQ(suggested_seads_resolution(100000), 32);
    EXPECT_EQ(suggested_seads_resolution(1000000), 70);
    EXPECT_EQ(suggested_seads_resolution(std::size_t{1} << 40), 322);
}

TEST(SuggestedVoxelSizes, OctreeDepthIsHalfOfLog2LessSixClampedTo1Through20) {
    EXPECT_EQ(suggested_octree_depth(0), 1);
    EXPECT_EQ(suggested_octree_depth(1), 1);
    EXPECT_EQ(suggested_octree_depth(142), 1);      // 0.57 rounds up
    EXPECT_EQ(suggested_octree_depth(1024), 2);     // (10 - 6) / 2
    EXPECT_EQ(suggested_octree_depth(100000), 5);   // 5.3 rounds down
    EXPECT_EQ(suggested_octree_depth(1 << 20), 7);  // (20 - 6) / 2
    EXPECT_EQ(suggested_octree_depth(1 << 21), 8);  // 7.5 rounds up
    EXPECT_EQ(suggested_octree_depth(1 << 22), 8);
    EXPECT_EQ(suggested_octree_depth(std::size_t{1} << 62), 20);
}

// The centre of a polygon's corners.
Vec3 centre_of(const Scene& scene, std::uint32_t id) {
    const Polygon& p = scene.polygons[id];
    Vec3 sum;
    for (std::uint32_t k = 0; k < p.corner_count; ++k) {
        sum += scene.corner_position(p, k);
    }
    return sum / static_cast<double>(p.corner_count);
}

// The scene header decides what the settings leave unset, and only that: a depth or a method set
// (by -od or --accel) wins over the header's, and a method the header does not name is sized for
// the scene's polygon count.
TEST(MethodForScene, TheHeaderFillsWhatTheSettingsLeaveUnset) {
    Scene scene = test::make_soup(3, 1000);
    const auto decided = [&](int sptncde, int octr, const AccelSettings& asked) {
        scene.header.sptncde = sptncde;
        scene.header.octr = octr;
        return method_for_scene(scene, asked);
    };
    const AccelSettings none;
    EXPECT_EQ(decided(0, 0, none).kind, AccelKind::BruteForce);
    EXPECT_EQ(decided(1, 3, none).kind, AccelKind::Octree);
    EXPECT_EQ(decided(1, 3, none).octree.depth, 3);
    EXPECT_EQ(decided(12, 0, none).kind, AccelKind::Seads);
    EXPECT_EQ(decided(12, 0, none).seads_resolution, 12);
    // Not named by the header: the suggested sizes (1000 polygons: depth 2, 7 a side). The depth
    // is measured only for an octree.
    AccelSettings octree;
    octree.kind = AccelKind::Octree;
    EXPECT_EQ(decided(12, 0, octree).octree.depth, 2);
    EXPECT_FALSE(decided(12, 0, none).octree.depth.has_value());
    EXPECT_FALSE(decided(0, 0, none).octree.depth.has_value());
    EXPECT_EQ(decided(1, 3, none).seads_resolution, 7);
    AccelSettings asked;
    asked.kind = AccelKind::Bvh;
    asked.octree.depth = 6;
    asked.seads_resolution = 9;
    for (const int sptncde : {0, 1, 12}) {
        const AccelSettings d = decided(sptncde, 3, asked);
        EXPECT_EQ(d.kind, AccelKind::Bvh) << sptncde;
        EXPECT_EQ(d.octree.depth, 6) << sptncde;
        EXPECT_EQ(d.seads_resolution, 9) << sptncde;
    }
}

// Every exact method built by name answers rays through a soup as brute force does (the t of the
// nearest hit to rounding, the same occlusion). Half the rays aim at a polygon's centre, so that
// most of those hit something; the others go anywhere.
TEST(MakeAccelerator, EveryExactMethodAnswersAsBruteForce) {
    const Scene scene = test::make_soup(7, 300);
    const auto reference = make_brute_force(scene);
    std::mt19937_64 rng(11);
    std::uniform_int_distribution<std::uint32_t> polygon(0, 299);
    for (const AccelKind kind :
         {AccelKind::BruteForce, AccelKind::Octree, AccelKind::Seads, AccelKind::Bvh}) {
        AccelSettings settings;
        settings.kind = kind;
        settings.octree.depth = suggested_octree_depth(scene.polygons.size());
        settings.seads_resolution = suggested_seads_resolution(scene.polygons.size());
        const std::unique_ptr<Accelerator> accel = make_accelerator(scene, settings);
        int hits = 0;
        for (int i = 0; i < 200; ++i) {
            const Vec3 origin = test::random_point(rng, {-12, -12, -12}, {12, 12, 12});
            const Vec3 direction = i % 2 == 0 ? normalize(centre_of(scene, polygon(rng)) - origin)
                                              : test::random_direction(rng);
            const Ray ray{origin, direction};
            const Interval all{1e-9, 1e30};
            TraceCounters counters;
            const std::optional<Hit> want = reference->closest_hit(ray, all, counters);
            const std::optional<Hit> got = accel->closest_hit(ray, all, counters);
            ASSERT_EQ(got.has_value(), want.has_value()) << accel->name() << " ray " << i;
            if (want) {
                ++hits;
                EXPECT_NEAR(got->t, want->t, 1e-5 * want->t) << accel->name() << " ray " << i;
            }
            EXPECT_EQ(accel->occluded(ray, all, counters), want.has_value())
                << accel->name() << " ray " << i;
        }
        EXPECT_GT(hits, 80) << accel->name();  // the rays do meet the soup
    }
}

// Polygons of more corners than the voxel methods' overlap test keeps on its stack (16): discs
// of 40 corners in random planes, crossed by rays through their centres and beside them.
TEST(MakeAccelerator, ManyCorneredPolygonsAnswerAsBruteForce) {
    std::mt19937_64 rng(5);
    test::SceneBuilder b;
    std::vector<Vec3> centres;
    for (int i = 0; i < 30; ++i) {
        const Vec3 centre = test::random_point(rng, {-8, -8, -8}, {8, 8, 8});
        const Vec3 e1 = normalize(cross(test::random_direction(rng), {0.3, 0.5, 0.8}));
        const Vec3 e2 = normalize(cross(e1, test::random_direction(rng)));
        const Vec3 e3 = normalize(cross(e2, e1));
        std::vector<Vec3> disc;
        for (int k = 0; k < 40; ++k) {
            const double a = 2.0 * 3.141592653589793 * k / 40.0;
            disc.push_back(centre + e1 * (1.5 * std::cos(a)) + e3 * (1.5 * std::sin(a)));
        }
        b.add_polygon(disc);
        centres.push_back(centre);
    }
    const Scene& scene = b.scene();
    const auto reference = make_brute_force(scene);
    for (const AccelKind kind : {AccelKind::Octree, AccelKind::Seads, AccelKind::Bvh}) {
        AccelSettings settings;
        settings.kind = kind;
        settings.octree.depth = 4;
        settings.seads_resolution = 8;
        const std::unique_ptr<Accelerator> accel = make_accelerator(scene, settings);
        int hits = 0;
        for (std::size_t i = 0; i < 200; ++i) {
            const Vec3 origin = test::random_point(rng, {-12, -12, -12}, {12, 12, 12});
            const Vec3 target = centres[i % centres.size()] +
                                (i % 4 == 0 ? test::random_direction(rng) * 1.4 : Vec3{});
            const Ray ray{origin, normalize(target - origin)};
            TraceCounters counters;
            const std::optional<Hit> want = reference->closest_hit(ray, {1e-9, 1e30}, counters);
            const std::optional<Hit> got = accel->closest_hit(ray, {1e-9, 1e30}, counters);
            ASSERT_EQ(got.has_value(), want.has_value()) << accel->name() << " ray " << i;
            if (want) {
                ++hits;
                EXPECT_EQ(got->polygon, want->polygon) << accel->name() << " ray " << i;
                EXPECT_NEAR(got->t, want->t, 1e-9 * want->t) << accel->name() << " ray " << i;
            }
        }
        EXPECT_GT(hits, 150) << accel->name();
    }
}

// Embree (comparison only, single precision) may be absent from the build: then asking for it
// says so instead of building something else.
TEST(MakeAccelerator, EmbreeIsBuiltOrSaysWhatItNeeds) {
    const Scene scene = test::make_box({-1, -1, -1}, {1, 1, 1}, true);
    AccelSettings settings;
    settings.kind = AccelKind::Embree;
    try {
        const std::unique_ptr<Accelerator> embree = make_accelerator(scene, settings);
        EXPECT_EQ(embree->name(), "embree");
        TraceCounters counters;
        const std::optional<Hit> hit =
            embree->closest_hit({{0.1, 0.2, -5}, {0, 0, 1}}, {1e-9, 1e30}, counters);
        ASSERT_TRUE(hit.has_value());
        EXPECT_NEAR(hit->t, 4.0, 1e-5);
        EXPECT_GT(embree->memory_bytes(), 0U);
    } catch (const NotImplementedError& e) {
        EXPECT_NE(std::string(e.what()).find("needs Embree 3"), std::string::npos) << e.what();
    }
}

// -p's "memory" line: brute force keeps nothing of its own; a hierarchy's memory grows with the
// scene.
TEST(MakeAccelerator, MemoryIsNothingForBruteForceAndGrowsWithTheScene) {
    const Scene small = test::make_soup(3, 100);
    const Scene large = test::make_soup(3, 800);
    EXPECT_EQ(make_brute_force(small)->memory_bytes(), 0U);
    for (const AccelKind kind : {AccelKind::Octree, AccelKind::Seads, AccelKind::Bvh}) {
        AccelSettings settings;
        settings.kind = kind;
        settings.octree.depth = 4;
        settings.seads_resolution = 16;
        const std::size_t small_bytes = make_accelerator(small, settings)->memory_bytes();
        const std::size_t large_bytes = make_accelerator(large, settings)->memory_bytes();
        EXPECT_GT(small_bytes, 0U) << accel_kind_name(kind);
        EXPECT_GT(large_bytes, small_bytes) << accel_kind_name(kind);
    }
}

}  // namespace
}  // namespace rt
