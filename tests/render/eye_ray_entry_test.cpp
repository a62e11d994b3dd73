// The renderer asks for its eye rays' first hits through the accelerator's eye-ray entry point
// (which the z-buffer answers from its item buffer), and for every other ray through closest_hit.
#include <atomic>

#include "rt/accel/brute_force.h"
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
    bool occluded(const Ray& ray, Interval t, TraceCounters& counters) const override {
        return brute_.occluded(ray, t, counters);
    }
    mutable std::atomic<std::uint64_t> eye_rays{0};
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
}

}  // namespace
}  // namespace rt
