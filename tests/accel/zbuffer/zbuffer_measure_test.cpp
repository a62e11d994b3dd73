// Not a check but a measurement for docs/exit-culling-and-zbuffer.md: the item buffer's build
// time and size, and polygon tests per eye ray against brute force's, on twocubes. Prints only.
// Disabled in the suite; run:
//   build/bin/accel_test --gtest_also_run_disabled_tests --gtest_filter='*Measure*'
#include <iostream>

#include "rt/accel/brute_force.h"
#include "rt/accel/zbuffer/zbuffer_first_hits.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"

namespace rt::test {
namespace {

TEST(ZBufferMeasure, DISABLED_TwocubesEyeRays) {
    const Scene scene = load_twocubes();
    const Camera view = scene.view.camera();
    const BruteForce brute(scene);
    const auto zbuffer = make_zbuffer_first_hits(scene, view, brute);
    TraceCounters brute_counters;
    TraceCounters zbuffer_counters;
    std::uint64_t rays = 0;
    for (int y = 0; y < view.height; ++y) {
        for (int x = 0; x < view.width; ++x) {
            const Ray ray = view.primary_ray(x + 0.5, y + 0.5);
            ++rays;
            const auto expected = brute.closest_hit(ray, {1e-9, kBeyondAnyScene}, brute_counters);
            const auto got =
                zbuffer->eye_ray_closest_hit(ray, {1e-9, kBeyondAnyScene}, zbuffer_counters);
            EXPECT_EQ(expected.has_value(), got.has_value());
        }
    }
    for (const std::string& line : describe(zbuffer->statistics())) {
        std::cout << "twocubes: " << line << "\n";
    }
    std::cout << fmt::format(
        "twocubes: {} eye rays, {:.2f} polygon tests per ray (brute force "
        "{:.2f})\n",
        rays, static_cast<double>(zbuffer_counters.polygon_tests) / rays,
        static_cast<double>(brute_counters.polygon_tests) / rays);
}

}  // namespace
}  // namespace rt::test
