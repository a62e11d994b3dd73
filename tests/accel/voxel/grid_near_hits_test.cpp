// Near hits (manual 3.1) in both voxel methods: kept until their voxel is reached by default,
// accepted at once with -on; -tv ends fruitless rays; -of still finds only real hits.
#include "rt/accel/make_accelerator.h"
#include "rt/accel/octree/octree_tree.h"
#include "rt/geometry/ray_polygon.h"

#include <gtest/gtest.h>

#include "accel/grid_test_support.h"

namespace rt::test {
namespace {

// A long polygon A slanting down onto the ray so that the ray meets it in the fourth voxel along
// x, although A already lies in the first; a small polygon B square across the ray in the third.
// The world is the unit cube (four voxels a side, or an octree of depth 2 whose leaves along the
// rays are halves of it).
struct NearHitScene {
    Scene scene;
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    std::uint32_t c = 0;
    Ray ray{{-0.5, 0.375, 0.375}, {1, 0, 0}};
    Ray empty_row{{-0.5, 0.875, 0.875}, {1, 0, 0}};
};

NearHitScene near_hit_scene() {
    NearHitScene s;
    SceneBuilder b;
    b.scene() = unit_cube_anchors();
    auto z = [](double x) { return 0.375 + 0.01 * (x - 0.9); };
    s.a = b.add_polygon({{0, 0.2, z(0)}, {1, 0.2, z(1)}, {1, 0.6, z(1)}});
    s.b = b.add_polygon({{0.6, 0.3, 0.3}, {0.6, 0.45, 0.3}, {0.6, 0.375, 0.45}});
    // C: alone at the far end of an otherwise empty row of voxels.
    s.c = b.add_polygon({{0.9, 0.8, 0.8}, {0.9, 0.95, 0.8}, {0.9, 0.875, 0.95}});
    // Specks in a far corner, enough that the octree's root is split.
    for (int i = 0; i <= static_cast<int>(kMaxLeafPolygons); ++i) {
        const double x = 0.99 - 0.001 * i;
        b.add_polygon({{x, 0.01, 0.99}, {x - 0.001, 0.01, 0.99}, {x, 0.011, 0.99}});
    }
    s.scene = std::move(b.scene());
    return s;
}

std::vector<AccelSettings> voxel_methods() {
    AccelSettings seads;
    seads.kind = AccelKind::Seads;
    seads.seads_resolution = 4;
    AccelSettings octree;
    octree.kind = AccelKind::Octree;
    octree.octree.depth = 2;
    return {seads, octree};
}

TEST(NearHits, AreKeptUntilTheirVoxelIsReached) {
    const NearHitScene s = near_hit_scene();
    for (const AccelSettings& settings : voxel_methods()) {
        const auto accel = make_accelerator(s.scene, settings);
        TraceCounters counters;
        const std::optional<Hit> hit = accel->closest_hit(s.ray, {}, counters);
        ASSERT_TRUE(hit) << accel->name();
        EXPECT_EQ(hit->polygon, s.b) << accel->name();
        EXPECT_EQ(counters.near_hits, 1u) << accel->name();
    }
}

TEST(NearHitsAcceptedAtOnce, CanMissANearerPolygon) {
    const NearHitScene s = near_hit_scene();
    for (AccelSettings settings : voxel_methods()) {
        settings.accept_near_hits = true;
        const auto accel = make_accelerator(s.scene, settings);
        TraceCounters counters;
        const std::optional<Hit> hit = accel->closest_hit(s.ray, {}, counters);
        ASSERT_TRUE(hit) << accel->name();
        EXPECT_EQ(hit->polygon, s.a) << accel->name();
        EXPECT_EQ(counters.near_hits, 1u) << accel->name();
    }
}

TEST(TerminateAfterVoxels, EndsRaysThatFindNothing) {
    const NearHitScene s = near_hit_scene();
    for (AccelSettings settings : voxel_methods()) {
        settings.terminate_after_voxels = 1;
        const auto short_walk = make_accelerator(s.scene, settings);
        TraceCounters counters;
        EXPECT_FALSE(short_walk->closest_hit(s.empty_row, {}, counters)) << short_walk->name();
        EXPECT_EQ(counters.voxels_stepped, 1u);
        // A hit pending in the first voxel keeps the walk going to its voxel.
        EXPECT_EQ(short_walk->closest_hit(s.ray, {}, counters)->polygon, s.b);
        settings.terminate_after_voxels = 4;
        const auto long_walk = make_accelerator(s.scene, settings);
        EXPECT_EQ(long_walk->closest_hit(s.empty_row, {}, counters)->polygon, s.c);
    }
}

// Whatever -on and -of change, a hit they return is a real hit on that polygon, never nearer
// than brute force's.
TEST(NearHitsAcceptedAtOnce, AndNoFudgeReturnOnlyRealHits) {
    const Scene scene = random_triangle_soup(300, 41);
    const BruteForce brute(scene);
    for (AccelSettings settings : voxel_methods()) {
        for (const bool on : {false, true}) {
            settings.accept_near_hits = on;
            settings.no_fudge = !on;
            settings.seads_resolution = 12;
            settings.octree.depth = 6;
            const auto accel = make_accelerator(scene, settings);
            TraceCounters counters;
            int farther = 0;
            for (const RayCase& c : random_rays({{0, 0, 0}, {1, 1, 1}}, 5000, 42)) {
                const std::optional<Hit> want = brute.closest_hit(c.ray, c.t, counters);
                const std::optional<Hit> got = accel->closest_hit(c.ray, c.t, counters);
                ASSERT_EQ(want.has_value(), got.has_value()) << describe(c);
                if (got) {
                    EXPECT_EQ(intersect_polygon(c.ray, scene.polygon_view(got->polygon), c.t),
                              got->t);
                    EXPECT_GE(got->t, want->t);
                    farther += got->t > want->t ? 1 : 0;
                }
            }
            if (on) {
                EXPECT_GT(farther, 0) << accel->name() << ": -on never differed; a weak test";
            }
        }
    }
}

}  // namespace
}  // namespace rt::test

namespace rt::test {
namespace {

// Nothing to find, or nothing to look with: no hit, no crash.
TEST(VoxelMethods, EmptySceneAndBrokenRaysMissQuietly) {
    const Scene empty = SceneBuilder().scene();
    const Scene box = make_box({0, 0, 0}, {1, 1, 1}, true);
    const double nan = std::nan("");
    for (const AccelSettings& settings : voxel_methods()) {
        TraceCounters counters;
        const auto on_empty = make_accelerator(empty, settings);
        EXPECT_FALSE(on_empty->closest_hit({{0, 0, -1}, {0, 0, 1}}, {}, counters));
        EXPECT_FALSE(on_empty->occluded({{0, 0, -1}, {0, 0, 1}}, {}, counters));
        const auto on_box = make_accelerator(box, settings);
        EXPECT_FALSE(on_box->closest_hit({{0.5, 0.5, -1}, {0, 0, 0}}, {}, counters));
        EXPECT_FALSE(on_box->closest_hit({{0.5, 0.5, -1}, {nan, 0, 1}}, {}, counters));
        EXPECT_FALSE(on_box->closest_hit({{nan, 0.5, -1}, {0, 0, 1}}, {}, counters));
        EXPECT_FALSE(on_box->occluded({{0.5, 0.5, -1}, {0, 0, 1}}, {0.0, 0.5}, counters));
        EXPECT_TRUE(on_box->closest_hit({{0.5, 0.5, -1}, {0, 0, 1}}, {}, counters));
    }
}

}  // namespace
}  // namespace rt::test

namespace rt::test {
namespace {

// The walk's slack grows with the distance of the ray's origin, so rays from far away (where a
// computed t strays further than the fudge) still get brute force's answer.
TEST(VoxelMethods, RaysFromFarAwayMatchBruteForce) {
    const Scene scene = random_triangle_soup(300, 71);
    std::mt19937 rng(72);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<RayCase> rays;
    for (const double distance : {30.0, 1e3, 1e6}) {
        for (int i = 0; i < 3000; ++i) {
            const Vec3 away = normalize(Vec3{normal(rng), normal(rng), normal(rng)}) * distance;
            const Vec3 target{unit(rng), unit(rng), unit(rng)};
            RayCase c;
            c.ray.origin = Vec3{0.5, 0.5, 0.5} + away;
            c.ray.direction = target - c.ray.origin;
            rays.push_back(c);
        }
    }
    for (AccelSettings settings : voxel_methods()) {
        settings.seads_resolution = 16;
        settings.octree.depth = 7;
        const auto accel = make_accelerator(scene, settings);
        expect_same_as_brute_force(scene, *accel, rays);
    }
}

// A polygon whose corners lie beyond the float range, which the voxels' float test cannot judge
// (its lanes are marked to be tested exactly, cell_packets.h): rays through its near end find it
// as brute force does.
TEST(VoxelMethods, PolygonsBeyondTheFloatRangeAreStillHit) {
    SceneBuilder b;
    b.scene() = unit_cube_anchors();
    for (int k = 0; k < 6; ++k) {
        const double x = 0.1 + 0.15 * k;
        b.add_polygon({{x, 0.4, 0.5}, {x + 0.1, 0.4, 0.5}, {x + 0.05, 1e39, 0.5}});
        b.add_polygon({{x, 0.2, 0.7}, {x + 0.1, 0.2, 0.7}, {x + 0.05, 0.3, 0.7}});
    }
    const Scene scene = std::move(b.scene());
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<RayCase> rays;
    for (int i = 0; i < 2000; ++i) {
        RayCase c;
        c.ray.origin = {unit(rng), 0.2 + 0.6 * unit(rng), -1.0};
        c.ray.direction = Vec3{0.2 * (unit(rng) - 0.5), 0.2 * (unit(rng) - 0.5), 1.0};
        rays.push_back(c);
    }
    for (const AccelSettings& settings : voxel_methods()) {
        const auto accel = make_accelerator(scene, settings);
        const TraceCounters counters = expect_same_as_brute_force(scene, *accel, rays);
        EXPECT_GT(counters.hits, 300u) << accel->name();
    }
}

}  // namespace
}  // namespace rt::test
