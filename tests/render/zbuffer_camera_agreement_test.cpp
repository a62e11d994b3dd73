// The renderer and the z-buffer share the scene's Camera; this checks that every eye ray the
// renderer makes, asked as an eye ray, is vouched for by the z-buffer and answered from its pixel
// as brute force would.
#include "rt/accel/brute_force.h"
#include "rt/accel/zbuffer/zbuffer_first_hits.h"
#include "rt/core/diagnostics.h"
#include "rt/geometry/camera.h"
#include "rt/scene/read/load_scene.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace rt::test {
namespace {

TEST(ZBufferCameraAgreement, EveryCameraRayIsAnsweredByTheItemBufferAsBruteForce) {
    Diagnostics diagnostics;
    const Scene scene = load_scene(source_dir() / "tests/data/scene/manual/twocubes.scn",
                                   ReaderDialect{}, diagnostics);
    const Camera camera = scene.view.camera();
    const BruteForce brute(scene);
    const auto zbuffer = make_zbuffer_first_hits(scene, camera, brute);
    TraceCounters brute_counters;
    TraceCounters zbuffer_counters;
    for (int y = 0; y <= scene.view.height; y += 3) {
        for (int x = 0; x <= scene.view.width; x += 3) {
            const Ray ray = camera.primary_ray(x + 0.5 * (y % 2), y + 0.5 * (x % 2));
            const std::optional<Hit> expected =
                brute.closest_hit(ray, {1e-9, kBeyondAnyScene}, brute_counters);
            const std::optional<Hit> got =
                zbuffer->eye_ray_closest_hit(ray, {1e-9, kBeyondAnyScene}, zbuffer_counters);
            ASSERT_EQ(expected.has_value(), got.has_value());
            if (expected) {
                ASSERT_EQ(expected->t, got->t);
                ASSERT_EQ(expected->polygon, got->polygon);
            }
        }
    }
    // The item buffer answered: far fewer polygon tests than brute force's.
    EXPECT_LT(zbuffer_counters.polygon_tests * 4, brute_counters.polygon_tests);
}

}  // namespace
}  // namespace rt::test
