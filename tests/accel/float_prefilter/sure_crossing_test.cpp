// The float pre-filter's sure verdicts (float_ray.cpp, part 4): a lane it calls sure must be one
// it keeps, and its triangle must have a nonzero exact winding number around the ray, however
// close to an edge or a corner the ray passes. plane_decides_crossing must then give the exact
// test's answer whenever it decides. The BVH's and the voxel methods' walks take these answers
// instead of the exact test's, and their agreement with brute force is checked in their own tests.
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "rt/accel/bvh/packet_pair_prefilter.h"
#include "rt/accel/bvh/packet_prefilter.h"
#include "rt/accel/float_prefilter/float_ray.h"
#include "rt/geometry/ray_polygon.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

struct Triangle {
    Vec3 corner[3];
};

Vec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<double> normal(0.0, 1.0);
    return normalize(Vec3{normal(rng), normal(rng), normal(rng)});
}

// A triangle of size 1e-4 to 10, near the origin or far off, now and then long and thin.
Triangle random_triangle(std::mt19937& rng, int i) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Vec3 centre = random_unit(rng) * (i % 5 == 0 ? 100.0 : unit(rng));
    const double size = std::pow(10.0, 1.0 - 5.0 * unit(rng));
    Triangle t{};
    for (int v = 0; v < 3; ++v) {
        const double stretch = (i % 7 == 0 && v == 1) ? 50.0 : 1.0;
        t.corner[v] = centre + random_unit(rng) * (size * stretch);
    }
    return t;
}

// A ray through a point near the triangle: inside it, just across an edge, on a corner, or
// anywhere in its plane, from a random side.
Ray ray_near(std::mt19937& rng, const Triangle& t) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int edge = static_cast<int>(rng() % 3);
    const Vec3& a = t.corner[edge];
    const Vec3& b = t.corner[(edge + 1) % 3];
    const Vec3& c = t.corner[(edge + 2) % 3];
    Vec3 target;
    switch (rng() % 4) {
        case 0: {  // inside, by barycentric weights
            const double u = unit(rng);
            const double v = unit(rng) * (1.0 - u);
            target = a + (b - a) * u + (c - a) * v;
            break;
        }
        case 1: {  // across an edge by 1e-16 to 1e-2 of its length, either way
            const Vec3 on = a + (b - a) * unit(rng);
            const Vec3 inward = normalize(c - on);
            const double offset = std::pow(10.0, -16.0 + 14.0 * unit(rng)) * length(b - a);
            target = on + inward * ((rng() % 2 == 0 ? 1.0 : -1.0) * offset);
            break;
        }
        case 2:  // a corner
            target = a;
            break;
        default:  // anywhere near, in the plane
            target = a + (b - a) * (3.0 * unit(rng) - 1.0) + (c - a) * (3.0 * unit(rng) - 1.0);
    }
    const Vec3 direction = random_unit(rng) * std::pow(2.0, static_cast<int>(rng() % 9) - 4);
    return Ray{target - direction * (1.0 + 10.0 * unit(rng)), direction};
}

int exact_winding(const Ray& ray, const Triangle& t) {
    const std::vector<Vec3> corners{t.corner[0], t.corner[1], t.corner[2]};
    return winding_number(RaySpace(ray), corners);
}

double largest_coordinate(const std::vector<Triangle>& triangles) {
    double scale = 0.0;
    for (const Triangle& t : triangles) {
        for (const Vec3& c : t.corner) {
            scale = std::max({scale, std::fabs(static_cast<double>(static_cast<float>(c.x))),
                              std::fabs(static_cast<double>(static_cast<float>(c.y))),
                              std::fabs(static_cast<double>(static_cast<float>(c.z)))});
        }
    }
    return scale;
}

void put_lane(float (&corner)[3][3][4], int lane, const Triangle& t) {
    for (int v = 0; v < 3; ++v) {
        for (int a = 0; a < 3; ++a) {
            corner[v][a][lane] = static_cast<float>(t.corner[v][a]);
        }
    }
}

TEST(SureCrossing, ASureLaneIsKeptAndItsWindingNumberIsNotZero) {
    std::mt19937 rng(31);
    std::vector<Triangle> triangles;
    triangles.reserve(2000);
    for (int i = 0; i < 2000; ++i) {
        triangles.push_back(random_triangle(rng, i));
    }
    const double scale = largest_coordinate(triangles);
    int sure = 0;
    int kept_not_sure = 0;
    for (int i = 0; i < 200000; ++i) {
        const std::size_t aimed = rng() % triangles.size();
        const Ray ray = ray_near(rng, triangles[aimed]);
        const FloatRay float_ray(ray, scale);
        ASSERT_TRUE(float_ray.usable);
        float corner[3][3][4];
        std::size_t lane_triangle[4];
        for (int lane = 0; lane < 4; ++lane) {
            lane_triangle[lane] = lane == 0 ? aimed : rng() % triangles.size();
            put_lane(corner, lane, triangles[lane_triangle[lane]]);
        }
        const bvh::FanVerdicts verdicts = bvh::fan_verdicts(corner, float_ray);
        ASSERT_EQ(verdicts.sure & ~verdicts.maybe, 0u) << "case " << i;
        for (int lane = 0; lane < 4; ++lane) {
            const bool is_sure = ((verdicts.sure >> lane) & 1) != 0;
            if (is_sure) {
                ++sure;
                ASSERT_NE(exact_winding(ray, triangles[lane_triangle[lane]]), 0)
                    << "case " << i << " lane " << lane;
            } else if (((verdicts.maybe >> lane) & 1) != 0) {
                ++kept_not_sure;
            }
        }
#ifdef RT_PACKET_PAIR_AVX2
        if (__builtin_cpu_supports("avx2")) {
            float second[3][3][4];
            for (int lane = 0; lane < 4; ++lane) {
                put_lane(second, lane, triangles[lane_triangle[3 - lane]]);
            }
            const bvh::FanVerdicts pair = bvh::fan_pair_verdicts(corner, second, float_ray);
            const bvh::FanVerdicts second_alone = bvh::fan_verdicts(second, float_ray);
            // The eight-wide form gives each lane the four-wide form's verdicts.
            ASSERT_EQ(pair.maybe & 0xfu, verdicts.maybe) << "case " << i;
            ASSERT_EQ(pair.sure & 0xfu, verdicts.sure) << "case " << i;
            ASSERT_EQ(pair.maybe >> 4, second_alone.maybe) << "case " << i;
            ASSERT_EQ(pair.sure >> 4, second_alone.sure) << "case " << i;
        }
#endif
    }
    // Both verdicts are common: the rays aimed at edges land on both sides of the margin.
    EXPECT_GT(sure, 30000);
    EXPECT_GT(kept_not_sure, 1000);
}

TEST(SureCrossing, ThePlaneGivesTheExactAnswerWheneverItDecides) {
    std::mt19937 rng(32);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int decided = 0;
    int hits = 0;
    for (int i = 0; i < 100000; ++i) {
        const Triangle t = random_triangle(rng, i);
        const Ray ray = ray_near(rng, t);
        if (exact_winding(ray, t) == 0) {
            continue;  // plane_decides_crossing is asked only of crossed polygons
        }
        const std::vector<Vec3> corners{t.corner[0], t.corner[1], t.corner[2]};
        const Vec3 normal = normalize(cross(t.corner[1] - t.corner[0], t.corner[2] - t.corner[0]));
        // Intervals that hold the hit, end before it, or begin after it.
        const double t_min = i % 3 == 0 ? 0.0 : 20.0 * unit(rng) - 5.0;
        const Interval interval{t_min, t_min + 20.0 * unit(rng)};
        std::optional<double> hit;
        if (!plane_decides_crossing(ray, normal, t.corner[0], interval, hit)) {
            continue;
        }
        ++decided;
        hits += hit ? 1 : 0;
        const std::optional<double> exact = intersect_polygon(ray, corners, normal, interval);
        ASSERT_EQ(hit.has_value(), exact.has_value()) << "case " << i;
        if (hit) {
            ASSERT_EQ(*hit, *exact) << "case " << i;
        }
    }
    EXPECT_GT(decided, 35000);
    EXPECT_GT(hits, 10000);
    EXPECT_LT(hits, decided);
}

TEST(SureCrossing, ThePlaneDecidesNothingEdgeOnOrForADirectionTooLongToMeasure) {
    const Vec3 normal{0.0, 0.0, 1.0};
    const Vec3 corner{0.0, 0.0, 1.0};
    std::optional<double> hit;
    // In the plane's direction: edge-on.
    EXPECT_FALSE(
        plane_decides_crossing(Ray{{0, 0, 0}, {1.0, 0.0, 1e-9}}, normal, corner, {0.0, 1e30}, hit));
    // A direction whose length RaySpace cannot take: the exact test misses every polygon.
    const Ray huge{{0, 0, 0}, {1.5e308, 1.5e308, 1.7e308}};
    EXPECT_FALSE(RaySpace(huge).valid());
    EXPECT_FALSE(plane_decides_crossing(huge, normal, corner, {0.0, 1e30}, hit));
    // A NaN origin.
    EXPECT_FALSE(plane_decides_crossing(Ray{{std::nan(""), 0, 0}, {0, 0, 1}}, normal, corner,
                                        {0.0, 1e30}, hit));
    // An ordinary crossing is decided, and its t is the plane's.
    ASSERT_TRUE(
        plane_decides_crossing(Ray{{0, 0, 0}, {0, 0, 2}}, normal, corner, {0.0, 1e30}, hit));
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(*hit, 0.5);
}

}  // namespace
}  // namespace rt
