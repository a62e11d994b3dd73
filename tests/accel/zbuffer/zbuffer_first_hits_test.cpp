// Z-buffer first hits must give brute force's answer for every eye ray: same t, same polygon.
// Cameras looking at the manual's scene, from inside boxes and spheres, through polygons that
// cross the screen plane or lie behind the eye, with sample positions on pixel corners and edges.
#include "rt/accel/zbuffer/zbuffer_first_hits.h"

#include <string>
#include <vector>

#include "rt/accel/brute_force.h"

#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"
#include "accel/viewed_scenes.h"

namespace rt::test {
namespace {

// Passes every call to brute force and counts the nearest-hit queries, to show which rays the
// z-buffer answered.
class CountingFallback : public Accelerator {
public:
    explicit CountingFallback(const Scene& scene) : brute_(scene) {}
    std::string_view name() const override { return "counting brute force"; }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override {
        ++calls;
        return brute_.closest_hit(ray, t, counters);
    }
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override {
        return brute_.occluded(ray, t, counters);
    }
    void closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                            TraceCounters& counters) const override {
        ++packet_calls;
        Accelerator::closest_hit_packet(packet, hits, counters);
    }
    std::uint32_t occluded_packet(const RayPacket& packet, TraceCounters& counters) const override {
        ++packet_calls;
        return Accelerator::occluded_packet(packet, counters);
    }
    mutable int calls = 0;
    mutable int packet_calls = 0;  ///< closest_hit_packet and occluded_packet (eye rays too)

private:
    BruteForce brute_;
};

// Compares every sample of every pixel (and the view area's far edges) with brute force.
void expect_brute_force_answers(const Scene& scene, int step = 1) {
    const Camera view = scene.view.camera();
    const BruteForce brute(scene);
    const CountingFallback fallback(scene);
    const auto zbuffer = make_zbuffer_first_hits(scene, view, fallback);
    ASSERT_TRUE(zbuffer->statistics().active) << zbuffer->statistics().inactive_reason;
    TraceCounters counters;
    int hits = 0;
    for_each_view_sample(view, step, [&](double px, double py) {
        const Ray ray = view.primary_ray(px, py);
        for (const Interval t : {Interval{1e-9, kBeyondAnyScene}, Interval{0.0, 7.5}}) {
            const std::optional<Hit> expected = brute.closest_hit(ray, t, counters);
            const std::optional<Hit> got = zbuffer->eye_ray_closest_hit(ray, t, counters);
            ASSERT_EQ(expected.has_value(), got.has_value()) << px << ", " << py;
            if (expected) {
                ++hits;
                ASSERT_EQ(expected->t, got->t) << px << ", " << py;
                ASSERT_EQ(expected->polygon, got->polygon) << px << ", " << py;
            }
            ASSERT_EQ(brute.occluded(ray, t, counters), zbuffer->occluded(ray, t, counters));
        }
    });
    EXPECT_EQ(fallback.calls, 0) << "every eye ray should be answered by the item buffer";
    EXPECT_GT(hits, 0) << "the test would prove nothing";
}

class ZBufferViewedScenes : public ::testing::TestWithParam<std::string> {};

TEST_P(ZBufferViewedScenes, EveryEyeRayAsBruteForce) {
    const ViewedScene viewed = viewed_scene(GetParam());
    expect_brute_force_answers(viewed.scene, viewed.step);
}

INSTANTIATE_TEST_SUITE_P(Views, ZBufferViewedScenes, ::testing::ValuesIn(viewed_scene_names()),
                         [](const auto& param_info) { return param_info.param; });

TEST(ZBufferFirstHits, OtherRaysGoToTheFallback) {
    const Scene scene = load_twocubes();
    const Camera view = scene.view.camera();
    const CountingFallback fallback(scene);
    const BruteForce brute(scene);
    const auto zbuffer = make_zbuffer_first_hits(scene, view, fallback);
    TraceCounters counters;
    int calls = 0;
    for (const TestRay& r : make_test_rays(scene, 5, 2000)) {
        const std::optional<Hit> expected = brute.closest_hit(r.ray, r.t, counters);
        const std::optional<Hit> got = zbuffer->closest_hit(r.ray, r.t, counters);
        ASSERT_EQ(expected.has_value(), got.has_value());
        if (expected) {
            EXPECT_EQ(expected->t, got->t);
            EXPECT_EQ(expected->polygon, got->polygon);
        }
        ++calls;
    }
    EXPECT_EQ(fallback.calls, calls);
    // Only the eye-ray entry point consults the buffer: an eye ray asked as any other ray goes
    // to the fallback; so does one asked as an eye ray with t.min < 0, or moved off the screen.
    zbuffer->closest_hit(view.primary_ray(10, 10), {1e-9, kBeyondAnyScene}, counters);
    zbuffer->eye_ray_closest_hit(view.primary_ray(10, 10), {-1.0, kBeyondAnyScene}, counters);
    Ray moved = view.primary_ray(10, 10);
    moved.origin = moved.at(0.5);
    zbuffer->eye_ray_closest_hit(moved, {1e-9, kBeyondAnyScene}, counters);
    EXPECT_EQ(fallback.calls, calls + 3);
    zbuffer->eye_ray_closest_hit(view.primary_ray(10, 10), {1e-9, kBeyondAnyScene}, counters);
    EXPECT_EQ(fallback.calls, calls + 3);
}

// Packets of rays that are not eye rays, and eye-ray packets while the buffer is off, go to the
// fallback whole (for a packet walk such as the BVH's), each lane with brute force's answer.
TEST(ZBufferFirstHits, PacketsGoToTheFallbackWhole) {
    const Scene scene = load_twocubes();
    const Camera view = scene.view.camera();
    const CountingFallback fallback(scene);
    ZBufferSettings off;
    off.max_bytes = 1000;
    const auto zbuffer = make_zbuffer_first_hits(scene, view, fallback);
    const auto zbuffer_off = make_zbuffer_first_hits(scene, view, fallback, off);
    ASSERT_FALSE(zbuffer_off->statistics().active);
    const BruteForce brute(scene);
    const std::vector<TestRay> rays = make_test_rays(scene, 6, 400);
    TraceCounters counters;
    int packets = 0;
    for (std::size_t first = 0; first + kPacketSize <= rays.size(); first += kPacketSize) {
        RayPacket packet;
        for (int lane = 0; lane < kPacketSize; ++lane) {
            packet.rays[lane] = rays[first + lane].ray;
            packet.t[lane] = rays[first + lane].t;
        }
        packet.active = first % 16 == 0 ? 0xffu : 0x5au;
        PacketHits hits;
        PacketHits eye_hits;
        zbuffer->closest_hit_packet(packet, hits, counters);
        const std::uint32_t blocked = zbuffer->occluded_packet(packet, counters);
        zbuffer_off->eye_ray_closest_hit_packet(packet, eye_hits, counters);
        packets += 3;
        for (int lane = 0; lane < kPacketSize; ++lane) {
            if (((packet.active >> lane) & 1u) == 0) {
                EXPECT_FALSE(hits[lane] || eye_hits[lane] || ((blocked >> lane) & 1u));
                continue;
            }
            const std::optional<Hit> want =
                brute.closest_hit(packet.rays[lane], packet.t[lane], counters);
            for (const std::optional<Hit>& got : {hits[lane], eye_hits[lane]}) {
                ASSERT_EQ(want.has_value(), got.has_value());
                if (want) {
                    EXPECT_EQ(want->t, got->t);
                    EXPECT_EQ(want->polygon, got->polygon);
                }
            }
            EXPECT_EQ(brute.occluded(packet.rays[lane], packet.t[lane], counters),
                      ((blocked >> lane) & 1u) != 0);
        }
    }
    EXPECT_EQ(fallback.packet_calls, packets);
}

TEST(ZBufferFirstHits, OverTheMemoryLimitEveryRayGoesToTheFallback) {
    const Scene scene = load_twocubes();
    const Camera view = scene.view.camera();
    const CountingFallback fallback(scene);
    ZBufferSettings settings;
    settings.max_bytes = 1000;
    const auto zbuffer = make_zbuffer_first_hits(scene, view, fallback, settings);
    const ZBufferStatistics statistics = zbuffer->statistics();
    EXPECT_FALSE(statistics.active);
    EXPECT_NE(statistics.inactive_reason.find("over its limit"), std::string::npos)
        << statistics.inactive_reason;
    EXPECT_EQ(describe(statistics).front().rfind("z-buffer off: ", 0), 0u);
    TraceCounters counters;
    const BruteForce brute(scene);
    const Ray ray = view.primary_ray(256, 200);
    EXPECT_EQ(brute.closest_hit(ray, {1e-9, kBeyondAnyScene}, counters)->polygon,
              zbuffer->eye_ray_closest_hit(ray, {1e-9, kBeyondAnyScene}, counters)->polygon);
    EXPECT_EQ(fallback.calls, 1);
}

TEST(ZBufferFirstHits, StatisticsDescribeTheBuffer) {
    const Scene scene = load_twocubes();
    const BruteForce brute(scene);
    const auto zbuffer = make_zbuffer_first_hits(scene, scene.view.camera(), brute);
    const ZBufferStatistics statistics = zbuffer->statistics();
    EXPECT_TRUE(statistics.active);
    EXPECT_EQ(statistics.polygons_in_view, scene.polygons.size());
    EXPECT_GT(statistics.entries, 0u);
    EXPECT_LE(statistics.longest_list, scene.polygons.size());
    EXPECT_GT(statistics.memory_bytes, 512u * 400u * 4u);
    EXPECT_EQ(describe(statistics).size(), 1u);
}

}  // namespace
}  // namespace rt::test
