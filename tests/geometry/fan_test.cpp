// Open fans around a shared corner: a line through that corner, or through a shared spoke, hits
// exactly one triangle, flat or umbrella-shaped, and at scales where every product of two
// coordinates underflows or overflows.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "support/line_hits.h"
#include "support/scene_builder.h"

namespace rt::test {
namespace {

// A flat fan: any line through its middle corner (not in its plane) hits exactly one triangle.
TEST(Fan, ExactlyOneHitThroughTheSharedCorner) {
    for (const int count : {3, 7, 16, 64}) {
        const Scene fan = make_fan(count, 2.0);
        for (const Vec3& direction : dyadic_directions()) {
            if (direction.z == 0) {
                continue;
            }
            const LineHits h = hits_along(fan, ray_through({0, 0, 0}, direction));
            EXPECT_EQ(h.count, 1) << count << " triangles, "
                                  << describe(ray_through({}, direction));
        }
    }
}

TEST(Fan, ExactlyOneHitThroughTheSharedEdges) {
    std::mt19937_64 random(31);
    std::uniform_real_distribution<double> along(0.05, 0.95);
    for (const int count : {3, 7, 16}) {
        const Scene fan = make_fan(count, 2.0);
        for (std::uint32_t id = 0; id < fan.polygons.size(); ++id) {
            const Vec3 spoke_end = fan.corner_position(fan.polygons[id], 1);
            for (int i = 0; i < 50; ++i) {
                Vec3 direction = random_unit(random);
                if (std::fabs(direction.z) < 1e-3) {
                    continue;
                }
                const Vec3 on_spoke = spoke_end * along(random);
                const LineHits h = hits_along(fan, {on_spoke - direction * 3.0, direction});
                EXPECT_EQ(h.count, 1) << count << " triangles, spoke " << id;
            }
        }
    }
}

// At 1e-170 every product of two projected coordinates underflows to zero, at 1e170 it
// overflows: only the exact edge signs keep the fan watertight there.
TEST(Fan, ExactlyOneHitAtExtremeScales) {
    std::mt19937_64 random(33);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (const double scale : {1e-170, 1e-155, 1e155, 1e170}) {
        SceneBuilder builder;
        const int count = 12;
        const Vec3 centre = Vec3{0.3, -0.2, 0.1} * scale;
        std::vector<Vec3> rim;
        for (int j = 0; j < count; ++j) {
            const double phi = 2.0 * std::numbers::pi * j / count;
            rim.push_back(centre + Vec3{std::cos(phi), std::sin(phi), 0.3 * std::cos(phi)} * scale);
        }
        for (int j = 0; j < count; ++j) {
            builder.add_polygon({centre, rim[j], rim[(j + 1) % count]}, {0, 0, 1});
        }
        for (int i = 0; i < 500; ++i) {
            // Through points of the fan's plane (z = 0.3 x) well inside the rim, or exactly
            // through the shared centre.
            const double u = unit(random), v = unit(random);
            const Vec3 target = i % 5 == 0 ? centre : centre + Vec3{u, v, 0.3 * u} * (0.6 * scale);
            Vec3 direction = random_unit(random);
            direction.z = std::fabs(direction.z) + 0.2;
            const Ray ray{target - direction * scale, direction};
            EXPECT_EQ(hits_along(builder.scene(), ray).count, 1)
                << "scale " << scale << ", " << describe(ray);
        }
    }
}

// A non-planar umbrella of triangles around an apex at awkward coordinates, its rim a convex
// polygon (irregular corners on a circle in a tilted plane) so that the solid cone it bounds is
// convex: a line through the apex inside that cone crosses the umbrella exactly once. (Around a
// non-convex cone a line next to the apex can rightly cross three times.)
TEST(Fan, ExactlyOneHitThroughTheApexOfAnUmbrella) {
    std::mt19937_64 random(32);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    std::uniform_real_distribution<double> weight(0.01, 1.0);
    const Vec3 apex{0.1, 0.2, 0.3};
    for (const int count : {3, 5, 9, 31}) {
        SceneBuilder builder;
        std::vector<Vec3> rim;
        for (int j = 0; j < count; ++j) {
            const double phi = 2.0 * std::numbers::pi * (j + jitter(random)) / count;
            const double x = std::cos(phi), y = std::sin(phi);
            rim.push_back(apex + Vec3{x, y, -1.0 + 0.4 * x - 0.2 * y});
        }
        for (int j = 0; j < count; ++j) {
            builder.add_polygon({apex, rim[j], rim[(j + 1) % count]});
        }
        const Scene& umbrella = builder.scene();
        for (int i = 0; i < 400; ++i) {
            // A positive mix of three rim directions lies strictly inside the convex cone.
            const int j = i % count;
            const Vec3 direction = (rim[j] - apex) * weight(random) +
                                   (rim[(j + 1) % count] - apex) * weight(random) +
                                   (rim[(j + 2) % count] - apex) * weight(random);
            const Ray ray{apex - direction * 2.0, direction};
            EXPECT_EQ(hits_along(umbrella, ray).count, 1)
                << count << " triangles, " << describe(ray);
        }
    }
}

}  // namespace
}  // namespace rt::test
