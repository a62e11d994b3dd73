// Exit culling's eye rays (eye_coverage.h): an eye ray through a pixel that no occupied box
// covers is culled, and must hit nothing. Every sample of every pixel (corners, edges, centres)
// is asked as an eye ray of ExitCulling over brute force and compared with brute force, for
// cameras far and close, wide, inside boxes and spheres, in a polygon's plane, and with
// polygons crossing the screen; rays that are not the view's eye rays go to the table.
#include <string>
#include <vector>

#include "rt/accel/brute_force.h"
#include "rt/accel/exit_culling/exit_culling.h"
#include "rt/accel/exit_culling/eye_coverage.h"
#include "rt/accel/hit_regions/eye_view.h"

#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"
#include "accel/viewed_scenes.h"

namespace rt::test {
namespace {

struct EyeCounts {
    int culled = 0;
    int answered = 0;  ///< from the item buffer, without the method
    int hits = 0;
};

// Asks eye rays of ExitCulling over brute force, one at a time and in packets of eight, and
// compares each answer with brute force's: its own answers, and under -de, which re-traces every
// culled ray and every ray answered from the item buffer, the checks' findings.
class EyeRayChecker {
public:
    explicit EyeRayChecker(const Scene& scene)
        : brute_(scene),
          culling_(scene, make_brute_force(scene), checking()),
          answering_(scene, make_brute_force(scene)) {}

    const ExitCulling& culling() const { return culling_; }
    const EyeCounts& counts() const { return counts_; }

    void check(const Ray& ray, Interval t) {
        const std::optional<Hit> expected = brute_.closest_hit(ray, t, brute_counters_);
        const std::uint64_t culled_before = counters_.culled_exits;
        const std::optional<Hit> got = culling_.eye_ray_closest_hit(ray, t, counters_);
        counts_.culled += static_cast<int>(counters_.culled_exits - culled_before);
        expect_same(expected, got);
        const std::uint64_t answered_before = answering_counters_.guard_answers;
        expect_same(expected, answering_.eye_ray_closest_hit(ray, t, answering_counters_));
        counts_.answered += static_cast<int>(answering_counters_.guard_answers - answered_before);
        counts_.hits += expected && got ? 1 : 0;
        const int lane = static_cast<int>(expected_lanes_.size());
        packet_.rays[lane] = ray;
        packet_.t[lane] = t;
        packet_.active = (2u << lane) - 1u;
        expected_lanes_.push_back(expected);
        if (lane + 1 == kPacketSize) {
            check_packet();
        }
    }

private:
    static ExitCullingSettings checking() {
        ExitCullingSettings settings;
        settings.check_culled = true;
        return settings;
    }
    static void expect_same(const std::optional<Hit>& expected, const std::optional<Hit>& got) {
        ASSERT_EQ(expected.has_value(), got.has_value());
        if (expected) {
            EXPECT_EQ(expected->t, got->t);
            EXPECT_EQ(expected->polygon, got->polygon);
        }
    }
    void check_packet() {
        for (const ExitCulling* culling : {&culling_, &answering_}) {
            PacketHits hits;
            culling->eye_ray_closest_hit_packet(packet_, hits, counters_);
            for (int lane = 0; lane < kPacketSize; ++lane) {
                expect_same(expected_lanes_[static_cast<std::size_t>(lane)], hits[lane]);
            }
        }
        expected_lanes_.clear();
    }

    BruteForce brute_;
    ExitCulling culling_;
    ExitCulling answering_;  ///< without -de: the answers are its own
    TraceCounters answering_counters_;
    TraceCounters brute_counters_;
    TraceCounters counters_;
    EyeCounts counts_;
    RayPacket packet_;
    std::vector<std::optional<Hit>> expected_lanes_;
};

// Every sample of every `step`-th pixel, with and without an end to the interval.
EyeCounts expect_brute_force_answers(const Scene& scene, int step = 1, bool expect_hits = true) {
    const Camera view = scene.view.camera();
    EyeRayChecker checker(scene);
    EXPECT_TRUE(checker.culling().statistics().eye_coverage)
        << checker.culling().statistics().eye_inactive_reason;
    for_each_view_sample(view, step, [&](double px, double py) {
        SCOPED_TRACE(testing::Message() << px << ", " << py);
        const Ray ray = view.primary_ray(px, py);
        checker.check(ray, {1e-9, kBeyondAnyScene});
        checker.check(ray, {0.0, 7.5});
    });
    EXPECT_EQ(checker.culling().statistics().violations, 0u);
    EXPECT_EQ(checker.culling().statistics().guard_violations, 0u);
    if (expect_hits) {
        EXPECT_GT(checker.counts().hits, 0) << "the test would prove nothing";
        EXPECT_GT(checker.counts().answered, 0) << "no eye ray was answered from the item buffer";
    }
    return checker.counts();
}

class ExitCullingViewedScenes : public ::testing::TestWithParam<std::string> {};

TEST_P(ExitCullingViewedScenes, EveryEyeRayAsBruteForce) {
    const ViewedScene viewed = viewed_scene(GetParam());
    const EyeCounts counts = expect_brute_force_answers(viewed.scene, viewed.step);
    if (GetParam() == "manual") {
        // Most of the manual's view is empty sky: most of its eye rays are culled.
        EXPECT_GT(counts.culled, 1000);
    }
}

INSTANTIATE_TEST_SUITE_P(Views, ExitCullingViewedScenes, ::testing::ValuesIn(viewed_scene_names()),
                         [](const auto& param_info) { return param_info.param; });

TEST(ExitCullingEyeRays, LookingAwayCullsEveryEyeRay) {
    Scene scene = load_twocubes();
    set_view(scene, {{0, 0, -40}, {0, 0, -80}, 1.0, 60.0, 40.0});
    const EyeCounts away = expect_brute_force_answers(scene, 1, false);
    EXPECT_EQ(away.culled, 49 * 37 * 16 * 2);
}

// Rays that are not the view's eye rays get no verdict from the coverage; asked as eye rays,
// ExitCulling answers them from the table, as brute force would.
TEST(ExitCullingEyeRays, OtherRaysAreNotEyeRays) {
    const Scene scene = load_twocubes();
    const Camera view = scene.view.camera();
    const ExitCullingTable table(scene, 8, 8);
    const EyeCoverage coverage(view, scene.bounds(), table.cells());
    ASSERT_TRUE(coverage.active());
    using Verdict = EyeCoverage::Verdict;
    // A camera ray through an empty corner of the view is culled; moved along itself, or asked
    // with t.min < 0, or turned a little, or started off the screen, it is not an eye ray.
    Ray sky = view.primary_ray(0.5, 0.5);
    ASSERT_EQ(coverage.verdict(sky, {1e-9, kBeyondAnyScene}), Verdict::HitsNothing);
    EXPECT_EQ(coverage.verdict(sky, {-1.0, kBeyondAnyScene}), Verdict::NotAnEyeRay);
    Ray moved = sky;
    moved.origin = sky.at(0.5);
    EXPECT_EQ(coverage.verdict(moved, {1e-9, kBeyondAnyScene}), Verdict::NotAnEyeRay);
    Ray turned = sky;
    turned.direction = normalize(sky.direction + Vec3{0, 1e-6, 0});
    EXPECT_EQ(coverage.verdict(turned, {1e-9, kBeyondAnyScene}), Verdict::NotAnEyeRay);
    Ray outside = view.primary_ray(-0.01, 0.5);
    EXPECT_EQ(coverage.verdict(outside, {1e-9, kBeyondAnyScene}), Verdict::NotAnEyeRay);
    Ray endless = sky;
    endless.direction = {1e300, 1e300, 1e300};
    EXPECT_EQ(coverage.verdict(endless, {1e-9, kBeyondAnyScene}), Verdict::NotAnEyeRay);
    endless.direction = {kBeyondAnyScene * 1e300, 0, 0};
    EXPECT_EQ(coverage.verdict(endless, {1e-9, kBeyondAnyScene}), Verdict::NotAnEyeRay);
    // The centre of the view sees the cubes.
    EXPECT_EQ(coverage.verdict(view.primary_ray(0.5 * view.width, 0.5 * view.height),
                               {1e-9, kBeyondAnyScene}),
              Verdict::MayHit);
    // Random rays, asked as eye rays, are answered as brute force answers them.
    const BruteForce brute(scene);
    ExitCullingSettings settings;
    settings.check_culled = true;
    const ExitCulling culling(scene, make_brute_force(scene), settings);
    TraceCounters counters;
    for (const TestRay& r : make_test_rays(scene, 31, 3000)) {
        EXPECT_EQ(coverage.verdict(r.ray, r.t), Verdict::NotAnEyeRay);
        const std::optional<Hit> expected = brute.closest_hit(r.ray, r.t, counters);
        const std::optional<Hit> got = culling.eye_ray_closest_hit(r.ray, r.t, counters);
        ASSERT_EQ(expected.has_value(), got.has_value());
        if (expected) {
            EXPECT_EQ(expected->polygon, got->polygon);
        }
    }
    EXPECT_EQ(culling.statistics().violations, 0u);
}

// The pixel an eye ray is found in is the one the camera aimed it through.
TEST(ExitCullingEyeRays, PixelOfACameraRayIsItsOwn) {
    const Scene scene = load_twocubes();
    const Camera view = scene.view.camera();
    const EyeView eye(view, scene.bounds());
    for (int y = 0; y < view.height; y += 7) {
        for (int x = 0; x < view.width; x += 5) {
            for (const double inside : {0.25, 0.5, 0.75}) {
                const std::optional<ViewPixel> pixel =
                    eye.pixel_of(view.primary_ray(x + inside, y + inside), {0.0, 1.0});
                ASSERT_TRUE(pixel.has_value());
                EXPECT_EQ(pixel->x, x);
                EXPECT_EQ(pixel->y, y);
            }
        }
    }
}

// Without a view (eye and look point the same) there is no coverage: eye rays go to the table.
TEST(ExitCullingEyeRays, NoViewNoCoverage) {
    Scene scene = load_twocubes();
    scene.view.look = scene.view.eye;
    const ExitCulling culling(scene, make_brute_force(scene));
    const ExitCullingStatistics statistics = culling.statistics();
    EXPECT_FALSE(statistics.eye_coverage);
    EXPECT_EQ(statistics.eye_inactive_reason, "the view has no area");
    const std::vector<std::string> lines = describe(statistics);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[1], "exit culling of eye rays by the table: the view has no area");
    ExitCullingSettings settings;
    settings.eye_coverage = false;
    const Scene viewed = load_twocubes();
    const ExitCulling without(viewed, make_brute_force(viewed), settings);
    EXPECT_FALSE(without.statistics().eye_coverage);
    EXPECT_EQ(describe(without.statistics()).size(), 2u);  // the cells' and the leaving table
}

}  // namespace
}  // namespace rt::test
