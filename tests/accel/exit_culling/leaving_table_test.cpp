// Exit culling of rays leaving a polygon (leaving_table.h) must never cull a ray that hits
// anything, for rays as the renderer makes them (reflected, refracted, grazing, shadow feelers),
// and must cull most of those that leave a surface into the sky: it exists for them.
#include "rt/accel/exit_culling/leaving_table.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "rt/accel/brute_force.h"
#include "rt/accel/exit_culling/exit_culling.h"
#include "rt/geometry/ray_polygon.h"

#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"
#include "accel/exit_culling/culling_equals_brute_force.h"
#include "accel/surface_rays.h"
#include "support/scene_builder.h"

namespace rt::test {
namespace {

// An emitting attribute for the scene's light; its index.
std::uint32_t add_light_attribute(SceneBuilder& b) {
    Attribute light;
    light.emission = 1.0;
    b.scene().attributes.push_back(light);
    return static_cast<std::uint32_t>(b.scene().attributes.size() - 1);
}

// A checkerboard of coplanar tiles (one plane group), boxes standing on it, floating above it and
// sunk into it, and an emitting square above: every kind of guard.
Scene checkerboard_with_boxes() {
    SceneBuilder b;
    const std::uint32_t light_attribute = add_light_attribute(b);
    for (int i = -4; i < 4; ++i) {
        for (int k = -4; k < 4; ++k) {
            const double x = 2.0 * i;
            const double z = 2.0 * k;
            b.add_polygon({{x, 0, z}, {x + 2, 0, z}, {x + 2, 0, z + 2}, {x, 0, z + 2}}, {0, 1, 0});
        }
    }
    add_box(b, {-3, 0, -3}, {-1, 2, -1});        // standing on the floor, on tile corners
    add_box(b, {1.5, 1, 1.5}, {3.5, 2.5, 2.5});  // floating
    add_box(b, {-6, -1, 3}, {-5, 1, 5});         // sunk into the floor
    b.add_polygon({{-1, 8, -1}, {1, 8, -1}, {1, 8, 1}, {-1, 8, 1}}, {0, -1, 0}, light_attribute);
    return b.scene();
}

// A closed room (its walls facing out, as add_box makes them) with three boxes and a light
// inside: its floor sees 23 units, more than 15, so its masks are 32 bits wide.
Scene room_with_boxes() {
    SceneBuilder b;
    const std::uint32_t light_attribute = add_light_attribute(b);
    add_box(b, {-5, 0, -5}, {5, 6, 5});
    add_box(b, {-3, 0, -3}, {-1, 3, -1});
    add_box(b, {1, 0, 1}, {3, 1.5, 3.5});
    add_box(b, {-2, 2, 2}, {-1, 3, 3});  // floating
    b.add_polygon({{-1, 5.9, -1}, {1, 5.9, -1}, {1, 5.9, 1}, {-1, 5.9, 1}}, {0, -1, 0},
                  light_attribute);
    return b.scene();
}

struct SceneCase {
    std::string name;
    Scene (*make)();
    bool must_cull;  ///< whether some rays surely leave it into the void
    /// Whether some rays surely meet only a few guards (a flat fan's meet nothing but edge-on).
    bool must_confine = must_cull;
};

Scene twocubes() {
    return load_twocubes();
}
Scene boxes() {
    return make_boxes(13, 12);
}
Scene soup() {
    return make_soup(11, 150);
}
Scene warped_soup() {
    return make_soup(14, 100, true);
}
Scene closed_box() {
    return make_box({-1, -2, -3}, {1, 2, 3}, false);
}
Scene closed_box_of_triangles() {
    return make_box({0, 0, 0}, {1, 1, 1}, true);
}
Scene sphere() {
    return make_sphere({1, 2, 3}, 5.0, 8, 12, false);
}
Scene flat_fan() {
    return make_fan(12, 3.0);
}

// The renderer's rays, each naming the polygon it leaves.
std::vector<SurfaceRay> leaving_rays(const Scene& scene, int count, std::uint64_t seed) {
    std::vector<SurfaceRay> rays = surface_rays(scene, count, seed);
    for (SurfaceRay& r : grazing_surface_rays(scene, count / 10, seed + 1)) {
        rays.push_back(r);
    }
    for (SurfaceRay& r : rays) {
        r.ray.leaves = r.from;
    }
    return rays;
}

class LeavingTableNeverCullsAHit : public ::testing::TestWithParam<SceneCase> {};

TEST_P(LeavingTableNeverCullsAHit, OnRaysLeavingPolygons) {
    const Scene scene = GetParam().make();
    const BruteForce brute(scene);
    const LeavingTable table(scene, culling_frame(scene), 1);
    ASSERT_TRUE(table.active());
    TraceCounters counters;
    int culled = 0;
    int wrong = 0;
    for (const SurfaceRay& r : leaving_rays(scene, 20000, 51)) {
        if (!table.nothing_ahead(r.ray, r.t)) {
            continue;
        }
        ++culled;
        if (brute.closest_hit(r.ray, r.t, counters) || brute.occluded(r.ray, r.t, counters)) {
            ++wrong;
        }
    }
    EXPECT_EQ(wrong, 0);
    if (GetParam().must_cull) {
        EXPECT_GT(culled, 0) << "the test would prove nothing";
    }
}

// Coarse bins and no patches (as for bigger scenes) leave the answers safe too.
TEST_P(LeavingTableNeverCullsAHit, WithCoarseBins) {
    const Scene scene = GetParam().make();
    const BruteForce brute(scene);
    const LeavingTable table(scene, culling_frame(scene), 1, 2);
    TraceCounters counters;
    int wrong = 0;
    for (const SurfaceRay& r : leaving_rays(scene, 5000, 52)) {
        if (table.nothing_ahead(r.ray, r.t) && brute.closest_hit(r.ray, r.t, counters)) {
            ++wrong;
        }
    }
    EXPECT_EQ(wrong, 0);
}

// A ray the table confines to some of its guards hits no polygon but those: every polygon the
// exact test reports hit is among them.
TEST_P(LeavingTableNeverCullsAHit, ConfinesRaysToPolygonsThatHoldEveryHit) {
    const Scene scene = GetParam().make();
    const LeavingTable table(scene, culling_frame(scene), 1);
    std::uint64_t confined = 0;
    for (const SurfaceRay& r : leaving_rays(scene, 5000, 58)) {
        LeavingVerdict verdict;
        table.verdict(r.ray, r.t, verdict);
        if (verdict.kind != LeavingVerdict::Kind::AmongGuards) {
            continue;
        }
        ++confined;
        const std::span<const std::uint32_t> named = verdict.candidates();
        for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
            if (id != r.from && intersect_polygon(r.ray, scene.polygon_view(id), r.t)) {
                ASSERT_NE(std::find(named.begin(), named.end(), id), named.end())
                    << "polygon " << id << " hit but not named, leaving " << r.from;
            }
        }
    }
    if (GetParam().must_confine) {
        EXPECT_GT(confined, 0u) << "the test would prove nothing";
    }
}

// The whole layer answers as brute force on the same rays, nearest hits and feelers alike.
TEST_P(LeavingTableNeverCullsAHit, ExitCullingEqualsBruteForce) {
    const Scene scene = GetParam().make();
    expect_culling_equals_brute_force(scene, leaving_rays(scene, 4000, 53));
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, LeavingTableNeverCullsAHit,
    ::testing::Values(SceneCase{"twocubes", twocubes, true},
                      SceneCase{"checkerboard_with_boxes", checkerboard_with_boxes, true},
                      SceneCase{"boxes", boxes, true}, SceneCase{"soup", soup, true},
                      SceneCase{"warped_soup", warped_soup, false},
                      SceneCase{"closed_box", closed_box, true},
                      SceneCase{"room_with_boxes", room_with_boxes, true},
                      SceneCase{"closed_box_of_triangles", closed_box_of_triangles, true},
                      SceneCase{"sphere", sphere, false},
                      SceneCase{"flat_fan", flat_fan, true, false}),
    [](const auto& param_info) { return param_info.param.name; });

// Rays leaving the checkerboard upwards: most of those that meet nothing are culled, and each
// kind of guard (the floor's own group, the boxes' faces, the light) lets some through.
TEST(LeavingTable, CullsMostRaysLeavingAFloorIntoTheSky) {
    const Scene scene = checkerboard_with_boxes();
    const BruteForce brute(scene);
    const LeavingTable table(scene, culling_frame(scene), 1);
    std::mt19937_64 rng(54);
    const double epsilon = renderer_epsilon(scene);
    TraceCounters counters;
    int misses = 0;
    int culled = 0;
    for (int i = 0; i < 20000; ++i) {
        const auto tile = static_cast<std::uint32_t>(i % 64);
        Vec3 d = random_direction(rng);
        d.y = std::fabs(d.y) + 0.05;
        const Ray ray{point_in_fan(scene, tile, rng), d, tile};
        const Interval t{epsilon, kBeyondAnyScene};
        const bool hits = brute.closest_hit(ray, t, counters).has_value();
        const bool cull = table.nothing_ahead(ray, t);
        ASSERT_FALSE(hits && cull);
        misses += hits ? 0 : 1;
        culled += cull ? 1 : 0;
    }
    EXPECT_GT(misses, 10000);
    EXPECT_GT(culled, misses * 8 / 10) << culled << " of " << misses << " misses culled";
}

// A shadow feeler from a tile to the light, past the boxes, ends on the light's polygon outside
// its interval: the light is a guard, ruled out by its plane.
TEST(LeavingTable, CullsShadowFeelersThatReachTheLight) {
    const Scene scene = checkerboard_with_boxes();
    const BruteForce brute(scene);
    const LeavingTable table(scene, culling_frame(scene), 1);
    std::mt19937_64 rng(55);
    const double epsilon = renderer_epsilon(scene);
    TraceCounters counters;
    int reaching = 0;
    int culled = 0;
    for (int i = 0; i < 4000; ++i) {
        const auto tile = static_cast<std::uint32_t>(i % 64);
        const Vec3 from = point_in_fan(scene, tile, rng);
        const Vec3 span = Vec3{0, 8, 0} - from;
        const double distance = length(span);
        const Ray feeler{from, span, tile};
        const Interval t{epsilon / distance, 1.0 - epsilon / distance};
        const bool blocked = brute.closest_hit(feeler, t, counters).has_value();
        const bool cull = table.nothing_ahead(feeler, t);
        ASSERT_FALSE(blocked && cull);
        reaching += blocked ? 0 : 1;
        culled += cull ? 1 : 0;
    }
    EXPECT_GT(reaching, 2000);
    EXPECT_GT(culled, reaching / 2) << culled << " of " << reaching << " feelers culled";
}

// Rays leaving the boxes' faces downwards meet the checkerboard (a guarding plane group) or a
// neighbouring face: the layer answers most of them from those few polygons alone, as brute force
// does, without a walk.
TEST(LeavingTable, AnswersRaysTowardTheFloorFromTheirGuards) {
    const Scene scene = checkerboard_with_boxes();
    const auto light = static_cast<std::uint32_t>(scene.polygons.size() - 1);
    std::vector<SurfaceRay> down;
    for (const SurfaceRay& r : leaving_rays(scene, 20000, 57)) {
        if (r.from >= 64 && r.from != light && r.ray.direction.y < 0.0) {
            down.push_back(r);
        }
    }
    ASSERT_GT(down.size(), 1000u);
    const std::uint64_t answered = expect_culling_equals_brute_force(scene, down);
    EXPECT_GT(answered, down.size() / 2) << answered << " of " << down.size();
}

// A polygon that sees more than 15 others keeps each as a guard (32-bit masks), so none of its
// bins says "any other polygon"; a scene whose polygons see at most 15 keeps 16-bit masks.
TEST(LeavingTable, KeepsEveryUnitAsAGuardUpToThirtyOne) {
    const Scene room = room_with_boxes();
    const LeavingTable wide(room, culling_frame(room), 1);
    EXPECT_EQ(wide.empty_fraction(), 1.0);
    EXPECT_GT(wide.guards(), 15u * 4);
    const Scene cubes = twocubes();
    const LeavingTable narrow(cubes, culling_frame(cubes), 1);
    EXPECT_EQ(narrow.empty_fraction(), 1.0);
    const std::size_t masks = cubes.polygons.size() * 4 * 6 * 16 * 16;
    EXPECT_LT(narrow.memory_bytes(), masks * 3) << "16-bit masks, not 32";
}

TEST(LeavingTable, SameAnswersOnAnyNumberOfThreads) {
    const Scene scene = twocubes();
    const LeavingTable one(scene, culling_frame(scene), 1);
    const LeavingTable three(scene, culling_frame(scene), 3);
    EXPECT_EQ(one.guards(), three.guards());
    EXPECT_EQ(one.memory_bytes(), three.memory_bytes());
    for (const SurfaceRay& r : leaving_rays(scene, 5000, 56)) {
        ASSERT_EQ(one.nothing_ahead(r.ray, r.t), three.nothing_ahead(r.ray, r.t));
    }
}

TEST(LeavingTable, AsksForThePolygonTheRayLeaves) {
    const Scene scene = checkerboard_with_boxes();
    const LeavingTable table(scene, culling_frame(scene), 1);
    const Ray up{{0.5, 0, 0.5}, {0.3, 1, 0.2}, 36};
    const Interval t{1e-9, kBeyondAnyScene};
    ASSERT_TRUE(table.nothing_ahead(up, t)) << "the sky above a tile, away from the boxes";
    Ray anonymous = up;
    anonymous.leaves = kLeavesNoPolygon;
    EXPECT_FALSE(table.nothing_ahead(anonymous, t));
    Ray elsewhere = up;
    elsewhere.origin = {0.5, 3, 0.5};  // not on the tile it names
    EXPECT_FALSE(table.nothing_ahead(elsewhere, t));
    EXPECT_FALSE(table.nothing_ahead(up, {-1.0, kBeyondAnyScene}));
    Ray still = up;
    still.direction = {};
    EXPECT_FALSE(table.nothing_ahead(still, t));
}

TEST(LeavingTable, NoneForScenesOfManyPolygons) {
    const Scene scene = make_soup(57, static_cast<int>(kMostLeavingTablePolygons) + 1);
    const LeavingTable table(scene, culling_frame(scene), 1);
    EXPECT_FALSE(table.active());
    const Ray ray{scene.corner_position(scene.polygons[0], 0), {0, 1, 0}, 0};
    EXPECT_FALSE(table.nothing_ahead(ray, {1e-9, kBeyondAnyScene}));
}

// A polygon out of the doubles' range, or with a NaN corner (which the exact test may report
// hit, and which no box holds), leaves the scene without a table. (The scene readers refuse
// both; a scene made in code may hold them.)
TEST(LeavingTable, NoneWithCornersOutOfRange) {
    for (const double bad : {1e308, std::numeric_limits<double>::quiet_NaN()}) {
        SceneBuilder b;
        b.scene() = checkerboard_with_boxes();
        b.add_polygon({{0, 1, 0}, {bad, 1, 0}, {0, 1, 1}}, {0, 1, 0});
        const LeavingTable table(b.scene(), culling_frame(b.scene()), 1);
        EXPECT_FALSE(table.active()) << bad;
        const Ray up{{0.5, 0, 0.5}, {0.3, 1, 0.2}, 36};
        EXPECT_FALSE(table.nothing_ahead(up, {1e-9, kBeyondAnyScene})) << bad;
    }
}

// Turned off, the layer culls no ray leaving a polygon (they all start in full cells).
TEST(LeavingTable, CanBeTurnedOff) {
    const Scene scene = checkerboard_with_boxes();
    ExitCullingSettings settings;
    settings.leaving_table = false;
    const ExitCulling culling(scene, make_brute_force(scene), settings);
    TraceCounters counters;
    const Ray up{{0.5, 0, 0.5}, {0.3, 1, 0.2}, 36};
    EXPECT_FALSE(culling.closest_hit(up, {1e-9, kBeyondAnyScene}, counters).has_value());
    EXPECT_EQ(counters.culled_exits, 0u);
    EXPECT_EQ(culling.statistics().leaving_polygons, 0u);
    const ExitCulling with_table(scene, make_brute_force(scene));
    EXPECT_FALSE(with_table.closest_hit(up, {1e-9, kBeyondAnyScene}, counters).has_value());
    EXPECT_EQ(counters.culled_exits, 1u);
    EXPECT_EQ(with_table.statistics().leaving_polygons, scene.polygons.size());
}

}  // namespace
}  // namespace rt::test
