// Z-buffer first hits must give brute force's answer for every eye ray: same t, same polygon.
// Cameras looking at the manual's scene, from inside boxes and spheres, through polygons that
// cross the screen plane or lie behind the eye, with sample positions on pixel corners and edges.
#include "rt/accel/zbuffer/zbuffer_first_hits.h"

#include <string>
#include <vector>

#include "rt/accel/brute_force.h"

#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"

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

struct CameraCase {
    std::string name;
    Vec3 eye;
    Vec3 look;
    double screen_distance = 1.0;
    double angle_x = 40.0;
    double angle_y = 30.0;
    int width = 48;
    int height = 36;
};

void set_view(Scene& scene, const CameraCase& c) {
    scene.view.eye = c.eye;
    scene.view.look = c.look;
    scene.view.screen_distance = c.screen_distance;
    scene.view.view_angle_x_degrees = c.angle_x;
    scene.view.view_angle_y_degrees = c.angle_y;
    scene.view.width = c.width;
    scene.view.height = c.height;
}

// Sample positions within a pixel: its corner, edge midpoints, centre, and points a hair inside
// the far edges.
constexpr double kOffsets[] = {0.0, 0.5, 1e-12, 1.0 - 1e-12};

// Compares every sample of every pixel (and the view area's far edges) with brute force.
void expect_brute_force_answers(const Scene& scene, int step = 1) {
    const Camera view = scene.view.camera();
    const BruteForce brute(scene);
    const CountingFallback fallback(scene);
    const auto zbuffer = make_zbuffer_first_hits(scene, view, fallback);
    ASSERT_TRUE(zbuffer->statistics().active) << zbuffer->statistics().inactive_reason;
    TraceCounters counters;
    int hits = 0;
    for (int y = 0; y <= view.height; y += step) {
        for (int x = 0; x <= view.width; x += step) {
            for (const double dx : kOffsets) {
                for (const double dy : kOffsets) {
                    const double px = std::min(x + dx, static_cast<double>(view.width));
                    const double py = std::min(y + dy, static_cast<double>(view.height));
                    const Ray ray = view.primary_ray(px, py);
                    for (const Interval t : {Interval{1e-9, kBeyondAnyScene}, Interval{0.0, 7.5}}) {
                        const std::optional<Hit> expected = brute.closest_hit(ray, t, counters);
                        const std::optional<Hit> got =
                            zbuffer->eye_ray_closest_hit(ray, t, counters);
                        ASSERT_EQ(expected.has_value(), got.has_value()) << px << ", " << py;
                        if (expected) {
                            ++hits;
                            ASSERT_EQ(expected->t, got->t) << px << ", " << py;
                            ASSERT_EQ(expected->polygon, got->polygon) << px << ", " << py;
                        }
                        ASSERT_EQ(brute.occluded(ray, t, counters),
                                  zbuffer->occluded(ray, t, counters));
                    }
                }
            }
        }
    }
    EXPECT_EQ(fallback.calls, 0) << "every eye ray should be answered by the item buffer";
    EXPECT_GT(hits, 0) << "the test would prove nothing";
}

TEST(ZBufferFirstHits, TwocubesAsTheManualViewsIt) {
    const Scene scene = load_twocubes();
    expect_brute_force_answers(scene, 5);
}

TEST(ZBufferFirstHits, TwocubesFromCloseByAndWide) {
    Scene scene = load_twocubes();
    for (const CameraCase& c :
         {CameraCase{"close", {3, 1, -6}, {0, 0, 0}, 2.0, 90.0, 70.0},
          CameraCase{"down", {0.5, 30, 0.5}, {0.5, 0, 0.5}, 5.0, 60.0, 60.0},
          CameraCase{"straight down", {0, 30, 0}, {0, 0, 0}, 5.0, 60.0, 60.0},
          CameraCase{"very wide", {1, 0, -4}, {0, 0, 0}, 0.5, 170.0, 160.0},
          CameraCase{"on the floor", {-1, -3, -9}, {0, -3, 0}, 1.0, 60.0, 40.0}}) {
        SCOPED_TRACE(c.name);
        set_view(scene, c);
        expect_brute_force_answers(scene);
    }
}

TEST(ZBufferFirstHits, EyeInsideABoxAndPolygonsCrossingTheScreen) {
    Scene scene = make_boxes(13, 12);
    // The eye inside the first box, with a screen distance that cuts through its walls.
    const Polygon& wall = scene.polygons[1];
    Vec3 lo = scene.corner_position(wall, 0);
    Vec3 hi = lo;
    for (std::uint32_t k = 0; k < 24; ++k) {
        const Polygon& p = scene.polygons[1 + k / 4];
        lo = min_components(lo, scene.corner_position(p, k % 4));
        hi = max_components(hi, scene.corner_position(p, k % 4));
    }
    const Vec3 centre = (lo + hi) * 0.5;
    for (const double screen : {0.05, 0.4, 1.5}) {
        SCOPED_TRACE(screen);
        set_view(scene, {"inside", centre, centre + Vec3{1, 0.2, 0.3}, screen, 100.0, 80.0});
        expect_brute_force_answers(scene);
    }
}

TEST(ZBufferFirstHits, InsideASphereAndInASoup) {
    Scene sphere = make_sphere({0, 0, 0}, 3.0, 10, 16, true);
    set_view(sphere, {"inside", {0.5, 0.2, -1}, {0, 0, 1}, 0.7, 120.0, 100.0});
    expect_brute_force_answers(sphere);
    Scene soup = make_soup(17, 200);
    set_view(soup, {"amid", {0, 0, 0}, {1, 2, 3}, 1.0, 70.0, 50.0});
    expect_brute_force_answers(soup);
    Scene warped = make_soup(18, 100, true);
    set_view(warped, {"amid warped", {0.5, 0, 0}, {1, -2, 3}, 3.0, 70.0, 50.0});
    expect_brute_force_answers(warped);
}

TEST(ZBufferFirstHits, EyeInThePlaneOfAPolygon) {
    // Seen exactly edge-on, the floor's reported hits come from the grazing branch.
    Scene scene = make_boxes(19, 4);
    set_view(scene, {"floor level", {-25, 0, -25}, {0, 0, 0}, 1.0, 60.0, 40.0});
    expect_brute_force_answers(scene);
}

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
