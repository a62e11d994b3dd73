// Exit culling must never change the picture: no ray it culls may hit anything, for any scene,
// any ray, any table size. Checked against brute force on 100k rays per scene kind.
#include <string>

#include "rt/accel/brute_force.h"
#include "rt/accel/exit_culling/exit_culling.h"
#include "rt/accel/exit_culling/exit_culling_table.h"

#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"
#include "accel/exit_culling/culling_equals_brute_force.h"

namespace rt::test {
namespace {

struct SceneCase {
    std::string name;
    Scene (*make)();
};

Scene soup() {
    return make_soup(11, 300);
}
Scene small_soup() {
    return make_soup(12, 20);
}
Scene warped_soup() {
    return make_soup(14, 100, true);
}
Scene sphere() {
    return make_sphere({1, 2, 3}, 5.0, 12, 24, false);
}
Scene triangle_sphere() {
    return make_sphere({0, 0, 0}, 1.0, 6, 9, true);
}
Scene boxes() {
    return make_boxes(13, 12);
}
Scene flat_fan() {
    return make_fan(12, 3.0);
}
Scene twocubes() {
    return load_twocubes();
}

class ExitCullingNeverCullsAHit : public ::testing::TestWithParam<SceneCase> {};

// Every culled ray is traced by brute force, both as a nearest-hit ray and as a feeler.
TEST_P(ExitCullingNeverCullsAHit, OnAHundredThousandRandomRays) {
    const Scene scene = GetParam().make();
    const BruteForce brute(scene);
    const ExitCullingTable table(scene, default_exit_culling_resolution(scene.polygons.size()), 8);
    TraceCounters counters;
    int culled = 0;
    int wrong = 0;
    for (const TestRay& r : make_test_rays(scene, 21, 100000)) {
        if (!table.nothing_ahead(r.ray, r.t)) {
            continue;
        }
        ++culled;
        if (brute.closest_hit(r.ray, r.t, counters) || brute.occluded(r.ray, r.t, counters)) {
            ++wrong;
        }
    }
    EXPECT_EQ(wrong, 0);
    if (GetParam().name != "warped_soup") {  // warped polygons may be hit from far away
        EXPECT_GT(culled, 0) << "the test would prove nothing";
    }
}

// Tables of every shape: one cell, one bin per face, the finest grid and bins.
TEST_P(ExitCullingNeverCullsAHit, WithAnyTableSize) {
    const Scene scene = GetParam().make();
    const BruteForce brute(scene);
    const std::vector<TestRay> rays = make_test_rays(scene, 22, 5000);
    for (const auto& [resolution, bins] : {std::pair{1, 1}, {2, 3}, {5, 16}, {12, 8}}) {
        const ExitCullingTable table(scene, resolution, bins);
        TraceCounters counters;
        int wrong = 0;
        for (const TestRay& r : rays) {
            if (table.nothing_ahead(r.ray, r.t) && brute.closest_hit(r.ray, r.t, counters)) {
                ++wrong;
            }
        }
        EXPECT_EQ(wrong, 0) << resolution << " cells a side, " << bins << " bins a side";
    }
}

// The decorator answers exactly as the accelerator it wraps, and -de finds nothing to report.
TEST_P(ExitCullingNeverCullsAHit, DecoratorEqualsBruteForce) {
    const Scene scene = GetParam().make();
    expect_culling_equals_brute_force(scene, make_test_rays(scene, 23, 4000));
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, ExitCullingNeverCullsAHit,
    ::testing::Values(SceneCase{"soup", soup}, SceneCase{"small_soup", small_soup},
                      SceneCase{"warped_soup", warped_soup}, SceneCase{"sphere", sphere},
                      SceneCase{"triangle_sphere", triangle_sphere}, SceneCase{"boxes", boxes},
                      SceneCase{"flat_fan", flat_fan}, SceneCase{"twocubes", twocubes}),
    [](const auto& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace rt::test
