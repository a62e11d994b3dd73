// The debugging decorators and listings: -ds/-dsp/-dso (strike check), -dl (intersection log),
// -doo (octree listing).
#include <sstream>

#include "rt/accel/debug/intersection_log.h"
#include "rt/accel/debug/strike_check.h"
#include "rt/accel/make_accelerator.h"
#include "rt/accel/octree/octree_listing.h"

#include <gtest/gtest.h>

#include "accel/grid_test_support.h"

namespace rt::test {
namespace {

AccelSettings seads(int side, bool accept_near_hits) {
    AccelSettings s;
    s.kind = AccelKind::Seads;
    s.seads_resolution = side;
    s.accept_near_hits = accept_near_hits;
    return s;
}

struct Collected {
    std::vector<std::string> lines;
    std::function<void(const std::string&)> sink() {
        return [this](const std::string& line) { lines.push_back(line); };
    }
};

TEST(StrikeCheck, FindsNoDifferenceInAnExactMethod) {
    const Scene scene = random_triangle_soup(200, 51);
    Collected printed;
    const StrikeCheck check(scene, make_accelerator(scene, seads(8, false)), {true, true},
                            printed.sink());
    TraceCounters counters;
    for (const RayCase& c : random_rays({{0, 0, 0}, {1, 1, 1}}, 2000, 52)) {
        (void)check.closest_hit(c.ray, c.t, counters);
        (void)check.occluded(c.ray, c.t, counters);
    }
    EXPECT_EQ(check.rays_checked(), 4000u);
    EXPECT_EQ(check.differences(), 0u);
    EXPECT_TRUE(printed.lines.empty());
    EXPECT_NE(check.summary().find("0 of 4000"), std::string::npos) << check.summary();
}

TEST(StrikeCheck, ReportsEachDifferenceWithTheVoxelsVisited) {
    // -on accepts near hits at once, so it sometimes answers a farther polygon.
    const Scene scene = random_triangle_soup(300, 53);
    Collected printed;
    const StrikeCheck check(scene, make_accelerator(scene, seads(12, true)), {true, true},
                            printed.sink());
    TraceCounters counters;
    for (const RayCase& c : random_rays({{0, 0, 0}, {1, 1, 1}}, 3000, 54)) {
        (void)check.closest_hit(c.ray, c.t, counters);
    }
    ASSERT_GT(check.differences(), 0u);
    ASSERT_EQ(printed.lines.size(), check.differences());
    EXPECT_NE(printed.lines[0].find("brute force polygon"), std::string::npos) << printed.lines[0];
    EXPECT_NE(printed.lines[0].find("voxel ("), std::string::npos) << printed.lines[0];
}

TEST(StrikeCheck, CountsSilentlyWithoutPrintSwitches) {
    const Scene scene = random_triangle_soup(300, 53);
    Collected printed;
    AccelSettings octree;
    octree.kind = AccelKind::Octree;
    octree.octree.depth = 5;
    // -tv 1: a ray gives up after one fruitless leaf, so it often misses what brute force hits.
    octree.terminate_after_voxels = 1;
    const StrikeCheck check(scene, make_accelerator(scene, octree), {}, printed.sink());
    TraceCounters counters;
    for (const RayCase& c : random_rays({{0, 0, 0}, {1, 1, 1}}, 3000, 54)) {
        (void)check.closest_hit(c.ray, c.t, counters);
    }
    EXPECT_GT(check.differences(), 0u);
    EXPECT_TRUE(printed.lines.empty());
}

TEST(IntersectionLog, PrintsEveryQueryAndPassesTheAnswerOn) {
    const Scene scene = make_box({0, 0, 0}, {1, 1, 1}, true);
    Collected printed;
    const IntersectionLog log(make_accelerator(scene, seads(2, false)), printed.sink());
    TraceCounters counters;
    const std::optional<Hit> hit = log.closest_hit({{0.5, 0.5, -1}, {0, 0, 1}}, {}, counters);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->t, 1.0);
    EXPECT_FALSE(log.closest_hit({{5, 5, -1}, {0, 0, 1}}, {}, counters));
    ASSERT_EQ(printed.lines.size(), 2u);
    EXPECT_NE(printed.lines[0].find("polygon " + std::to_string(hit->polygon) + " at t 1"),
              std::string::npos)
        << printed.lines[0];
    EXPECT_NE(printed.lines[1].find("-> nothing"), std::string::npos) << printed.lines[1];
}

TEST(OctreeListing, ListsEveryNodeAndIsTheSameForBothFills) {
    const Scene scene = random_triangle_soup(200, 55);
    OctreeBuildSettings settings;
    settings.depth = 4;
    const OctreeTree tree = build_octree_depth_first(scene, settings);
    std::ostringstream depth_first;
    write_octree_listing(tree, depth_first);
    std::ostringstream level_order;
    write_octree_listing(build_octree_level_order(scene, settings), level_order);
    EXPECT_EQ(depth_first.str(), level_order.str());

    const std::string text = depth_first.str();
    EXPECT_EQ(text.rfind("# octree: depth 4", 0), 0u) << text.substr(0, 80);
    std::size_t lines = 0;
    for (const char c : text) {
        lines += c == '\n' ? 1 : 0;
    }
    EXPECT_EQ(lines, tree.nodes.size() + 1);
}

}  // namespace
}  // namespace rt::test
