// The case that makes exit culling subtle: a ray lying (nearly) in a polygon's plane, starting
// beside the polygon and looking away from it. The ray-polygon test may still report a hit ahead
// (its t is clamped to the corners' depths), so the table must not cull it. Single tilted
// polygons, so no other geometry sets the bins by chance.
#include "rt/accel/brute_force.h"
#include "rt/accel/exit_culling/exit_culling_table.h"

#include <gtest/gtest.h>

#include "accel/accel_test_scenes.h"

namespace rt::test {
namespace {

TEST(ExitCullingGrazing, RaysLeavingAPolygonAlongItsPlaneAreNotCulledWhenTheyHit) {
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int grazing_hits = 0;
    int wrong = 0;
    for (int scene_index = 0; scene_index < 300; ++scene_index) {
        SceneBuilder builder;
        const Vec3 centre = random_point(rng, {-3, -3, -3}, {3, 3, 3});
        const Vec3 e1 = random_direction(rng) * (0.5 + u(rng));
        const Vec3 e2 = normalize(cross(random_direction(rng), e1)) * (0.5 + u(rng));
        builder.add_polygon(
            {centre - e1 - e2, centre + e1 - e2, centre + e1 + e2, centre - e1 + e2});
        const Scene& scene = builder.scene();
        const BruteForce brute(scene);
        const ExitCullingTable table(scene, 8, 8);
        const Vec3 n = scene.polygons[0].normal;
        for (int i = 0; i < 300; ++i) {
            const Vec3 away = normalize(cross(n, random_direction(rng)));
            const Vec3 on = point_on(scene, 0, rng);
            const Ray ray{on + away * (3.0 * u(rng)), away};
            TraceCounters counters;
            if (!brute.closest_hit(ray, {0.0, kBeyondAnyScene}, counters)) {
                continue;
            }
            ++grazing_hits;
            if (table.nothing_ahead(ray, {0.0, kBeyondAnyScene})) {
                ++wrong;
            }
        }
    }
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(grazing_hits, 0) << "the test would prove nothing";
}

}  // namespace
}  // namespace rt::test
