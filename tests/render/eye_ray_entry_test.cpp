// The renderer asks for its eye rays' first hits through the accelerator's eye-ray entry point
// (which the z-buffer answers from its item buffer), and for every other ray through closest_hit.
#include <atomic>

#include "rt/accel/brute_force.h"
#include "rt/accel/make_accelerator.h"
#include "rt/render/renderer.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

// Brute force's answers, counting which entry point each nearest-hit query came through.
class CountingEntryPoints : public Accelerator {
public:
    explicit CountingEntryPoints(const Scene& scene) : brute_(scene) {}
    std::string_view name() const override { return "counting brute force"; }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override {
        ++other_rays;
        return brute_.closest_hit(ray, t, counters);
    }
    std::optional<Hit> eye_ray_closest_hit(const Ray& ray, Interval t,
                                           TraceCounters& counters) const override {
        ++eye_rays;
        return brute_.closest_hit(ray, t, counters);
    }
    void eye_ray_closest_hit_packet(const RayPacket& packet, PacketHits& hits,
                                    TraceCounters& counters) const override {
        ++eye_packets;
        for (int lane = 0; lane < kPacketSize; ++lane) {
            if ((packet.active >> lane) & 1u) {
                ++eye_rays;
                ++eye_rays_in_packets;
                hits[lane] = brute_.closest_hit(packet.rays[lane], packet.t[lane], counters);
            }
        }
    }
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override {
        return brute_.occluded(ray, t, counters);
    }
    mutable std::atomic<std::uint64_t> eye_rays{0};
    mutable std::atomic<std::uint64_t> eye_packets{0};
    mutable std::atomic<std::uint64_t> eye_rays_in_packets{0};
    mutable std::atomic<std::uint64_t> other_rays{0};

private:
    BruteForce brute_;
};

TEST(EyeRayEntry, TheRendererSendsEyeRaysAndOnlyThemThroughIt) {
    // Inside a closed box, so that every eye ray hits something.
    Scene scene = test::make_box({-1, -1, -1}, {1, 1, 1}, true);
    scene.view.eye = {0.2, 0.1, -0.5};
    scene.view.look = {0, 0, 1};
    const CountingEntryPoints accel(scene);
    RenderSettings settings;
    settings.window = {0, 0, 15, 11};
    settings.threads = 2;
    RenderObserver observer;
    RenderStatistics statistics;
    render(scene, accel, settings, observer, statistics);
    const std::uint64_t eye = statistics.by_kind[RayKind::Eye].rays;
    EXPECT_EQ(eye, 16u * 12u);  // one sample a pixel
    EXPECT_EQ(accel.eye_rays.load(), eye);
    EXPECT_EQ(accel.other_rays.load(), statistics.counters.rays - eye);
    // One sample a pixel: eight neighbouring pixels' rays a packet, a row of 16 in two.
    EXPECT_EQ(accel.eye_rays_in_packets.load(), eye);
    EXPECT_EQ(accel.eye_packets.load(), 2u * 12u);
}

TEST(EyeRayEntry, APixelsFirstSamplesGoEightAtATimeAndEveryOtherSampleAlone) {
    Scene scene = test::make_box({-1, -1, -1}, {1, 1, 1}, true);
    scene.view.eye = {0.2, 0.1, -0.5};
    scene.view.look = {0, 0, 1};
    scene.view.sample_resolution_x = 4;  // 16 samples, the first 4 always taken
    scene.view.sample_resolution_y = 4;
    const CountingEntryPoints accel(scene);
    RenderSettings settings;
    settings.window = {0, 0, 11, 11};
    settings.threads = 1;
    RenderObserver observer;
    RenderStatistics statistics;
    render(scene, accel, settings, observer, statistics);
    const std::uint64_t eye = statistics.by_kind[RayKind::Eye].rays;
    // The eye entry point also answers the probes through neighbouring pixels' centres.
    EXPECT_GT(accel.eye_rays.load(), eye);
    EXPECT_LE(accel.eye_rays_in_packets.load(), eye);
    // Two pixels' first four samples a packet: a row of 12 pixels in six, at least.
    EXPECT_GE(accel.eye_packets.load(), 6u * 12u);
    EXPECT_GE(accel.eye_rays_in_packets.load(), 4u * 12u * 12u);
}

// A method's answers one ray at a time: its packet calls fall back to closest_hit lane by lane.
class OneRayAtATime : public Accelerator {
public:
    explicit OneRayAtATime(const Accelerator& method) : method_(method) {}
    std::string_view name() const override { return "one ray at a time"; }
    std::optional<Hit> closest_hit(const Ray& ray, Interval t,
                                   TraceCounters& counters) const override {
        return method_.closest_hit(ray, t, counters);
    }
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override {
        return method_.occluded(ray, t, counters);
    }

private:
    const Accelerator& method_;
};

TEST(EyeRayEntry, ThePictureThroughBvhPacketsIsTheOneOfSingleRays) {
    Scene scene = test::make_box({-1, -1, -1}, {1, 1, 1}, true);
    scene.view.eye = {0.2, 0.1, -0.5};
    scene.view.look = {0, 0.3, 1};
    scene.view.sample_resolution_x = 4;
    scene.view.sample_resolution_y = 4;
    AccelSettings bvh_settings;
    bvh_settings.kind = AccelKind::Bvh;
    const std::unique_ptr<Accelerator> bvh = make_accelerator(scene, bvh_settings);
    const OneRayAtATime single(*bvh);
    for (const bool adaptive : {true, false}) {
        RenderSettings settings;
        settings.window = {0, 0, 23, 17};
        settings.threads = 1;
        settings.shading.sampling.adaptive = adaptive;
        RenderObserver observer;
        RenderStatistics by_packets;
        RenderStatistics by_single;
        const Film packets = render(scene, *bvh, settings, observer, by_packets);
        const Film singles = render(scene, single, settings, observer, by_single);
        EXPECT_EQ(packets.data(), singles.data()) << "adaptive " << adaptive;
        EXPECT_EQ(by_packets.counters.rays, by_single.counters.rays);
        EXPECT_EQ(by_packets.counters.hits, by_single.counters.hits);
    }
}

}  // namespace
}  // namespace rt
