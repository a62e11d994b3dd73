// The table's edges: what it refuses to cull, what it always culls, its size and its report.
#include "rt/accel/exit_culling/exit_culling_table.h"

#include "rt/accel/brute_force.h"
#include "rt/accel/exit_culling/exit_culling.h"

#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"

namespace rt::test {
namespace {

TEST(ExitCullingTable, AnEmptySceneCullsEveryValidRay) {
    const Scene scene = SceneBuilder().scene();
    const ExitCullingTable table(scene, 4, 8);
    EXPECT_TRUE(table.nothing_ahead({{1, 2, 3}, {0, 0, 1}}, {0.0, kBeyondAnyScene}));
    EXPECT_FALSE(table.nothing_ahead({{1, 2, 3}, {0, 0, 0}}, {0.0, kBeyondAnyScene}));
}

TEST(ExitCullingTable, RaysItCannotVouchForAreNeverCulled) {
    const Scene scene = make_box({-1, -1, -1}, {1, 1, 1}, false);
    const ExitCullingTable table(scene, 4, 8);
    const Ray away{{0, 5, 0}, {0, 1, 0}};
    EXPECT_TRUE(table.nothing_ahead(away, {0.0, kBeyondAnyScene}));
    EXPECT_FALSE(table.nothing_ahead(away, {-1.0, kBeyondAnyScene})) << "t.min < 0 looks backwards";
    EXPECT_FALSE(table.nothing_ahead({{0, 1e6, 0}, {0, 1, 0}}, {0.0, kBeyondAnyScene}))
        << "too far away";
    const double nan = std::nan("");
    EXPECT_FALSE(table.nothing_ahead({{0, 5, 0}, {nan, 1, 0}}, {0.0, kBeyondAnyScene}));
    EXPECT_FALSE(table.nothing_ahead({{0, 5, 0}, {0, 1, 0}}, {nan, kBeyondAnyScene}));
}

TEST(ExitCullingTable, ARayMissingTheWorldIsCulledAndOneInsideAClosedBoxIsNot) {
    const Scene scene = make_box({-1, -1, -1}, {1, 1, 1}, true);
    const ExitCullingTable table(scene, 6, 8);
    EXPECT_TRUE(table.nothing_ahead({{5, 5, 5}, {1, 0, 0}}, {0.0, kBeyondAnyScene}));
    EXPECT_FALSE(table.nothing_ahead({{0.1, 0.2, 0.3}, {1, 0.5, 0}}, {0.0, kBeyondAnyScene}));
    EXPECT_FALSE(table.nothing_ahead({{5, 0, 0}, {-1, 0, 0}}, {0.0, kBeyondAnyScene}));
}

TEST(ExitCullingTable, TwocubesTableIsSmall) {
    const Scene scene = load_twocubes();
    const ExitCulling culling(scene, make_brute_force(scene));
    const ExitCullingStatistics statistics = culling.statistics();
    EXPECT_EQ(statistics.grid_resolution, 8);
    EXPECT_EQ(statistics.regions, 512u);
    EXPECT_LT(statistics.memory_bytes, 1u << 20);
    EXPECT_GT(statistics.empty_fraction, 0.0);
    // The table's line, the eye rays' coverage and the leaving table, no -de lines unless
    // checking.
    const std::vector<std::string> lines = describe(statistics);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[1],
              "exit culling of eye rays: 30818 of 204800 pixels covered (15.0%), 25600 bytes; item "
              "buffer of 8x8-pixel tiles: 1071 entries (at most 9 in a tile), 18624 bytes");
    EXPECT_EQ(lines[2],
              "exit culling of rays leaving a polygon: 71 polygons x 2x2 patches x 6x16x16 "
              "direction bins, 497 guards, 100.0% of bins clear but for guards, 1037520 bytes");
}

TEST(ExitCulling, DebugModeReportsItsChecks) {
    const Scene scene = load_twocubes();
    ExitCullingSettings settings;
    settings.check_culled = true;
    const ExitCulling culling(scene, make_brute_force(scene), settings);
    TraceCounters counters;
    EXPECT_FALSE(
        culling.closest_hit({{100, 100, 100}, {1, 0, 0}}, {0.0, kBeyondAnyScene}, counters));
    EXPECT_EQ(counters.culled_exits, 1u);
    const ExitCullingStatistics statistics = culling.statistics();
    EXPECT_EQ(statistics.checked, 1u);
    EXPECT_EQ(statistics.violations, 0u);
    const std::vector<std::string> lines = describe(statistics);
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[3],
              "exit culling check (-de): 1 culled rays re-traced, 0 hit something; 0 rays "
              "answered from a few polygons (guards, tiles) re-traced, 0 answered otherwise");
    EXPECT_EQ(culling.name(), "exit culling over brute force");
}

TEST(ExitCulling, DefaultResolutionGrowsWithThePolygonCount) {
    EXPECT_EQ(default_exit_culling_resolution(0), 4);
    EXPECT_EQ(default_exit_culling_resolution(71), 8);
    EXPECT_EQ(default_exit_culling_resolution(1000000), 8);
}

}  // namespace
}  // namespace rt::test
