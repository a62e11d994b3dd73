// Brute force, the reference every other accelerator is compared with: the nearest hit, ties to
// the lowest polygon id, the open interval, occluded() agreeing with closest_hit().
#include "rt/accel/brute_force.h"

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "rt/geometry/ray_polygon.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

constexpr Interval kAhead{0.0, 1e300};

// Unit squares facing +z at the given heights, in the order given.
Scene squares_at(const std::vector<double>& heights) {
    test::SceneBuilder b;
    for (const double z : heights) {
        b.add_polygon({{-1, -1, z}, {1, -1, z}, {1, 1, z}, {-1, 1, z}}, {0, 0, 1});
    }
    return std::move(b.scene());
}

constexpr Ray kDown{{0.25, 0.5, 10}, {0, 0, -1}};

TEST(BruteForce, ReturnsTheNearestHitWhateverTheOrder) {
    const Scene scene = squares_at({-3, 4, 1, 7.5, -1});
    const BruteForce accel(scene);
    TraceCounters counters;
    const std::optional<Hit> hit = accel.closest_hit(kDown, kAhead, counters);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->polygon, 3u);
    EXPECT_DOUBLE_EQ(hit->t, 2.5);
    EXPECT_EQ(counters.polygon_tests, 5u);
}

TEST(BruteForce, RespectsTheOpenInterval) {
    const Scene scene = squares_at({-3, 4, 1, 7.5, -1});
    const BruteForce accel(scene);
    TraceCounters counters;
    // Starting exactly at the nearest square's t: that one no longer counts (open at min).
    const std::optional<Hit> past = accel.closest_hit(kDown, {2.5, 1e300}, counters);
    ASSERT_TRUE(past);
    EXPECT_EQ(past->polygon, 1u);
    // Ending exactly at a square's t: not hit (open at max).
    EXPECT_FALSE(accel.closest_hit(kDown, {0.0, 2.5}, counters));
    EXPECT_FALSE(accel.occluded(kDown, {0.0, 2.5}, counters));
    EXPECT_TRUE(accel.occluded(kDown, {0.0, std::nextafter(2.5, 3.0)}, counters));
}

TEST(BruteForce, TiesGoToTheLowestPolygonId) {
    // Polygons 1, 2 and 4 coincide; 0 and 3 are farther.
    const Scene scene = squares_at({-2, 1, 1, -5, 1});
    const BruteForce accel(scene);
    TraceCounters counters;
    const std::optional<Hit> hit = accel.closest_hit(kDown, kAhead, counters);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->polygon, 1u);
    EXPECT_DOUBLE_EQ(hit->t, 9.0);
}

TEST(BruteForce, TiesBetweenDifferentShapesAtOneDepth) {
    // A triangle and a quad touching the same point of the ray at the same t, given in both orders.
    const std::vector<Vec3> triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<Vec3> quad{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    const Ray ray{{0.2, 0.2, 3}, {0, 0, -1}};
    for (const bool triangle_first : {true, false}) {
        test::SceneBuilder b;
        b.add_polygon(triangle_first ? triangle : quad, {0, 0, 1});
        b.add_polygon(triangle_first ? quad : triangle, {0, 0, 1});
        const BruteForce accel(b.scene());
        TraceCounters counters;
        const std::optional<Hit> hit = accel.closest_hit(ray, kAhead, counters);
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->polygon, 0u);
    }
}

TEST(BruteForce, EmptySceneAndInvalidRaysHitNothing) {
    const Scene empty;
    const BruteForce none(empty);
    TraceCounters counters;
    EXPECT_FALSE(none.closest_hit(kDown, kAhead, counters));
    EXPECT_FALSE(none.occluded(kDown, kAhead, counters));

    const Scene scene = squares_at({0});
    const BruteForce accel(scene);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const Vec3& direction : {Vec3{0, 0, 0}, Vec3{0, 0, nan}, Vec3{0, 0, -HUGE_VAL}}) {
        const Ray ray{{0, 0, 5}, direction};
        EXPECT_FALSE(accel.closest_hit(ray, kAhead, counters));
        EXPECT_FALSE(accel.occluded(ray, kAhead, counters));
    }
}

TEST(BruteForce, OccludedStopsAtTheFirstHit) {
    const Scene scene = squares_at({1, 2, 3, 4});
    const BruteForce accel(scene);
    TraceCounters counters;
    EXPECT_TRUE(accel.occluded(kDown, kAhead, counters));
    EXPECT_EQ(counters.polygon_tests, 1u);
}

// A scene of closed meshes with shared edges: boxes of quads and triangles, a sphere, a fan.
Scene clutter() {
    test::SceneBuilder b;
    const auto append = [&](const Scene& part) {
        for (const Polygon& p : part.polygons) {
            std::vector<Vec3> loop;
            for (std::uint32_t k = 0; k < p.corner_count; ++k) {
                loop.push_back(part.corner_position(p, k));
            }
            b.add_polygon(loop, p.normal);
        }
    };
    append(test::make_box({-2, -2, -2}, {-0.5, 0, 1}, false));
    append(test::make_box({0.5, -1, -1}, {2, 2, 0.5}, true));
    append(test::make_sphere({0, 1.5, 1}, 0.8, 6, 10, false));
    append(test::make_fan(9, 1.2));
    return std::move(b.scene());
}

// The nearest hit by the definition: every polygon tested on its own.
std::optional<Hit> nearest_by_definition(const Scene& scene, const Ray& ray, Interval t) {
    std::optional<Hit> best;
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        const std::optional<double> hit = intersect_polygon(ray, scene, id, t);
        if (hit && (!best || *hit < best->t)) {
            best = Hit{*hit, id};
        }
    }
    return best;
}

TEST(BruteForce, AgreesWithThePolygonsTestedOneByOne) {
    const Scene scene = clutter();
    const BruteForce accel(scene);
    std::mt19937_64 random(51);
    std::uniform_real_distribution<double> coordinate(-4.0, 4.0);
    std::normal_distribution<double> gauss;
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        const Ray ray{{coordinate(random), coordinate(random), coordinate(random)},
                      {gauss(random), gauss(random), gauss(random)}};
        const Interval t{i % 3 == 0 ? 0.5 : 0.0, i % 5 == 0 ? 2.0 : 1e300};
        TraceCounters counters;
        const std::optional<Hit> expected = nearest_by_definition(scene, ray, t);
        const std::optional<Hit> hit = accel.closest_hit(ray, t, counters);
        ASSERT_EQ(hit.has_value(), expected.has_value());
        if (hit) {
            ++hits;
            EXPECT_EQ(hit->polygon, expected->polygon);
            EXPECT_EQ(hit->t, expected->t);
            EXPECT_GT(hit->t, t.min);
            EXPECT_LT(hit->t, t.max);
        }
        EXPECT_EQ(accel.occluded(ray, t, counters), hit.has_value());
        // Shortened to end just before the nearest hit, nothing is in the way.
        if (hit) {
            EXPECT_FALSE(accel.occluded(ray, {t.min, hit->t}, counters));
            EXPECT_FALSE(accel.closest_hit(ray, {t.min, hit->t}, counters));
        }
    }
    EXPECT_GT(hits, 200);
    EXPECT_LT(hits, 3900);
}

TEST(BruteForce, MakeBruteForceNamesItself) {
    const Scene scene = squares_at({0});
    const std::unique_ptr<Accelerator> accel = make_brute_force(scene);
    EXPECT_EQ(accel->name(), "brute force");
    TraceCounters counters;
    EXPECT_TRUE(accel->closest_hit(kDown, kAhead, counters));
}

}  // namespace
}  // namespace rt
