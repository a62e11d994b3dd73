// Not a check but a measurement for docs/exit-culling-and-zbuffer.md: table build time and size,
// and the share of rays culled, on twocubes' eye rays and on the random test rays. Prints only;
// timings are never asserted. Disabled in the suite; run:
//   build/bin/accel_test --gtest_also_run_disabled_tests --gtest_filter='*Measure*'
#include <chrono>
#include <iostream>

#include "rt/accel/brute_force.h"
#include "rt/accel/exit_culling/exit_culling.h"
#include "rt/geometry/camera.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"

namespace rt::test {
namespace {

struct Tally {
    std::uint64_t rays = 0;
    std::uint64_t misses = 0;  ///< rays brute force finds no hit for: the most culling can end
    std::uint64_t culled = 0;
};

void count(const BruteForce& brute, const ExitCulling& culling, const Ray& ray, Interval t,
           Tally& tally) {
    TraceCounters counters;
    ++tally.rays;
    const bool hit = brute.closest_hit(ray, t, counters).has_value();
    tally.misses += hit ? 0 : 1;
    TraceCounters culling_counters;
    const std::optional<Hit> got = culling.closest_hit(ray, t, culling_counters);
    tally.culled += culling_counters.culled_exits;
    EXPECT_EQ(hit, got.has_value());
}

void print(const std::string& what, const ExitCulling& culling, const Tally& tally) {
    for (const std::string& line : describe(culling.statistics())) {
        std::cout << what << ": " << line << "\n";
    }
    std::cout << fmt::format("{}: {} rays, {:.1f}% miss everything, {:.1f}% culled\n", what,
                             tally.rays, 100.0 * tally.misses / tally.rays,
                             100.0 * tally.culled / tally.rays);
}

TEST(ExitCullingMeasure, DISABLED_TwocubesEyeRays) {
    const Scene scene = load_twocubes();
    const BruteForce brute(scene);
    const ExitCulling culling(scene, make_brute_force(scene));
    const Camera view = scene.view.camera();
    Tally tally;
    for (int y = 0; y < view.height; ++y) {
        for (int x = 0; x < view.width; ++x) {
            count(brute, culling, view.primary_ray(x + 0.5, y + 0.5), {1e-9, kBeyondAnyScene},
                  tally);
        }
    }
    print("twocubes eye rays", culling, tally);
}

TEST(ExitCullingMeasure, DISABLED_RandomRays) {
    const std::vector<std::pair<std::string, Scene>> scenes = {
        {"twocubes", load_twocubes()},
        {"sphere", make_sphere({1, 2, 3}, 5.0, 12, 24, false)},
        {"boxes", make_boxes(13, 12)},
        {"soup", make_soup(11, 300)},
        {"soup 3000", make_soup(15, 3000)}};
    for (const auto& [name, scene] : scenes) {
        const BruteForce brute(scene);
        const ExitCulling culling(scene, make_brute_force(scene));
        Tally tally;
        for (const TestRay& r : make_test_rays(scene, 31, name == "soup 3000" ? 2000 : 20000)) {
            count(brute, culling, r.ray, r.t, tally);
        }
        print(name + " random rays", culling, tally);
    }
}

}  // namespace
}  // namespace rt::test
