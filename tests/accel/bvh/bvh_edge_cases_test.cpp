// The BVH against brute force where float boxes and pre-filters are most likely to go wrong:
// rays along box faces and shared edges, axis-parallel rays, rays lying in a polygon's plane,
// rays starting inside, coincident polygons (ties go to the lowest id), non-planar and
// degenerate polygons, coordinates beyond the float tests' range, and empty scenes.
#include <cmath>
#include <limits>
#include <random>
#include <thread>
#include <vector>

#include "rt/accel/brute_force.h"
#include "rt/accel/bvh/bvh.h"

#include <gtest/gtest.h>

#include "accel/accel_compare.h"
#include "support/meshes/generated_meshes.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

using test::expect_same_answers;
using test::RayQuery;
using test::SceneBuilder;

// A lattice of unit cubes made of quads, so box faces, shared edges and node boundaries all lie
// on integer coordinates.
Scene cube_lattice(int n) {
    SceneBuilder b;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            for (int k = 0; k < n; ++k) {
                const Scene cube = test::make_box({double(i), double(j), double(k)},
                                                  {i + 0.6, j + 0.6, k + 0.6}, (i + j + k) % 2);
                for (const Polygon& p : cube.polygons) {
                    std::vector<Vec3> corners;
                    for (std::uint32_t c = 0; c < p.corner_count; ++c) {
                        corners.push_back(cube.corner_position(p, c));
                    }
                    b.add_polygon(corners, p.normal);
                }
            }
        }
    }
    return std::move(b.scene());
}

TEST(BvhEdgeCases, AxisParallelRaysAlongFacesAndEdges) {
    const Scene scene = cube_lattice(3);
    const Bvh bvh(scene);
    std::vector<RayQuery> queries;
    const double coords[] = {-0.5, 0.0, 0.3, 0.6, 1.0, 1.6, 2.0, 2.6};
    for (int axis = 0; axis < 3; ++axis) {
        for (const double u : coords) {
            for (const double v : coords) {
                for (const double sign : {1.0, -1.0}) {
                    Vec3 origin;
                    origin[axis] = sign > 0 ? -1.0 : 4.0;
                    origin[(axis + 1) % 3] = u;
                    origin[(axis + 2) % 3] = v;
                    Vec3 direction;
                    direction[axis] = sign;
                    queries.push_back({{origin, direction}, Interval{}});
                    queries.push_back({{origin, direction * 1e-3}, Interval{0.0, 3e3}});
                }
            }
        }
    }
    expect_same_answers(scene, bvh, queries);
}

TEST(BvhEdgeCases, RaysStartingOnFacesAndInsideBoxes) {
    const Scene scene = cube_lattice(2);
    const Bvh bvh(scene);
    std::vector<RayQuery> queries;
    for (const Vec3 origin : {Vec3{0, 0, 0}, Vec3{0.3, 0.3, 0.3}, Vec3{0.6, 0.3, 0.0},
                              Vec3{1.0, 1.0, 1.0}, Vec3{0.6, 0.6, 0.6}}) {
        for (const Vec3 direction : {Vec3{1, 0, 0}, Vec3{0, -1, 0}, Vec3{1, 1, 0}, Vec3{1, 1, 1},
                                     Vec3{-1, 2, 3}, Vec3{0, 0, -1}}) {
            queries.push_back({{origin, direction}, Interval{}});
            queries.push_back({{origin, direction}, Interval{-kBeyondAnyScene, kBeyondAnyScene}});
        }
    }
    expect_same_answers(scene, bvh, queries);
    const Scene sphere = test::make_tessellated_sphere(2000);
    test::compare_with_brute_force(sphere, Bvh(sphere), 500, 3);
    std::vector<RayQuery> inside;
    for (int i = 0; i < 400; ++i) {
        const double a = 0.1 * i;
        inside.push_back({{Vec3{0.3 * std::sin(a), 0.2 * std::cos(a), 0.1},
                           Vec3{std::cos(a), std::sin(2 * a), std::sin(a)}},
                          Interval{}});
    }
    // Every ray from inside the closed sphere hits it.
    expect_same_answers(sphere, Bvh(sphere), inside, 1.0);
}

TEST(BvhEdgeCases, RaysInThePlaneOfTiltedTriangles) {
    // A fan tilted off every axis: rays from one corner through another lie in its plane,
    // where the exact test's depth comes from the corners (a grazing hit), not the plane.
    SceneBuilder b;
    const Vec3 centre{0.1, 0.2, 0.3};
    const Vec3 u = normalize(Vec3{1, 0.3, 0.2});
    const Vec3 v = normalize(cross(Vec3{0.1, 0.7, 0.4}, u));
    std::vector<Vec3> rim;
    for (int j = 0; j < 12; ++j) {
        const double phi = 2 * 3.141592653589793 * j / 12;
        rim.push_back(centre + u * std::cos(phi) + v * (0.7 * std::sin(phi)));
    }
    for (int j = 0; j < 12; ++j) {
        b.add_polygon({centre, rim[j], rim[(j + 1) % 12]});
    }
    const Scene& scene = b.scene();
    const Bvh bvh(scene);
    std::vector<RayQuery> queries;
    for (std::size_t i = 0; i < scene.positions.size(); ++i) {
        for (std::size_t j = 0; j < scene.positions.size(); ++j) {
            if (i == j) {
                continue;
            }
            const Vec3 a = scene.positions[i];
            const Vec3 d = scene.positions[j] - a;
            for (const double back : {0.0, 0.5, 2.0}) {
                queries.push_back({{a - d * back, d}, Interval{}});
                queries.push_back({{a - d * back, d}, Interval{1e-12, 0.9}});
            }
        }
    }
    expect_same_answers(scene, bvh, queries);
}

TEST(BvhEdgeCases, CoincidentPolygonsGoToTheLowestId) {
    SceneBuilder b;
    for (int copy = 0; copy < 40; ++copy) {
        b.add_polygon({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}});
        b.add_polygon({{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}});
    }
    const Scene& scene = b.scene();
    const Bvh bvh(scene);
    TraceCounters counters;
    for (const double x : {0.1, 0.25, 0.5, 0.7}) {
        const std::optional<Hit> hit =
            bvh.closest_hit({{x, 0.2, -1}, {0, 0, 1}}, Interval{}, counters);
        ASSERT_TRUE(hit.has_value());
        EXPECT_EQ(hit->polygon, x + 0.2 < 1.0 ? 0u : 1u);
        EXPECT_EQ(hit->t, 2.0);
    }
    test::compare_with_brute_force(scene, bvh, 3000, 21);
}

TEST(BvhEdgeCases, NonPlanarAndDegeneratePolygons) {
    SceneBuilder b;
    for (int i = 0; i < 30; ++i) {
        const double x = i * 0.3;
        b.add_polygon({{x, 0, 0}, {x + 1, 0, 0.4}, {x + 1, 1, 0}, {x, 1, 0.5}});  // twisted
        b.add_polygon({{x, 2, 0}, {x + 1, 2, 0}, {x + 2, 2, 0}});                 // a segment
        b.add_polygon({{x, 3, 0}, {x, 3, 0}, {x, 3, 0}});                         // a point
        b.add_polygon({{x, 4, 0},
                       {x + 1, 4, 1},
                       {x, 5, 0},
                       {x + 1, 4, 1},
                       {x + 2, 4, 0}});  // a loop that revisits a corner
    }
    const Scene& scene = b.scene();
    test::compare_with_brute_force(scene, Bvh(scene), 6000, 22);
}

TEST(BvhEdgeCases, PolygonsWithoutANormalTakeTheGrazingDepth) {
    // A zero normal makes every hit a grazing one, whose depth comes from the corners and the
    // line's span in the corner box, not from a plane: the BVH culls boxes by where the line
    // enters and leaves them, and must still find each such hit, at the same t.
    Scene scene = test::make_triangle_soup(300, 31);
    for (Polygon& p : scene.polygons) {
        p.normal = Vec3{0, 0, 0};
    }
    const Bvh bvh(scene);
    std::vector<RayQuery> queries;
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 3000; ++i) {
        // Aimed at a corner's neighbourhood, so that many rays hit something.
        const Vec3 target = scene.positions[random() % scene.positions.size()] +
                            Vec3{unit(random), unit(random), unit(random)} * 0.01;
        const Vec3 origin{unit(random) * 3, unit(random) * 3, unit(random) * 3};
        queries.push_back({{origin, target - origin}, Interval{}});
        queries.push_back({{origin, target - origin}, Interval{0.5, 0.999}});
    }
    int hits = 0;
    const BruteForce brute(scene);
    TraceCounters counters;
    for (const RayQuery& q : queries) {
        hits += brute.closest_hit(q.ray, q.t, counters).has_value();
    }
    EXPECT_GT(hits, 500) << "the test would prove little";
    expect_same_answers(scene, bvh, queries);
}

// The rays scale with the scene, and at least a fifth of them hit at every scale: with a fixed
// padding the 1e-30 soup was a speck in the rays' box and none did.
TEST(BvhEdgeCases, CoordinatesBeyondTheFloatTests) {
    for (const double scale : {1e-30, 1e15, 1e200}) {
        SCOPED_TRACE(scale);
        Scene scene = test::make_triangle_soup(200, 9);
        for (Vec3& p : scene.positions) {
            p = p * scale;
        }
        test::compare_with_brute_force(scene, Bvh(scene), 1000, 23, 0.2);
    }
    // The rays come from the finite corners' box, so they are finite and a fifth hit; a few aim
    // at the broken polygons' corners.
    Scene with_nan = test::make_triangle_soup(100, 10);
    with_nan.positions[5].y = std::numeric_limits<double>::quiet_NaN();
    with_nan.positions[9].x = std::numeric_limits<double>::infinity();
    test::compare_with_brute_force(with_nan, Bvh(with_nan), 1000, 24, 0.2);
}

TEST(BvhEdgeCases, EmptyScenesAndInvalidRays) {
    const Scene empty;
    const Bvh bvh(empty);
    TraceCounters counters;
    EXPECT_FALSE(bvh.closest_hit({{0, 0, 0}, {0, 0, 1}}, Interval{}, counters));
    EXPECT_FALSE(bvh.occluded({{0, 0, 0}, {0, 0, 1}}, Interval{}, counters));
    const Scene one = test::make_box({0, 0, 0}, {1, 1, 1}, false);
    const Bvh box(one);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const Ray& ray : {Ray{{0.5, 0.5, -1}, {0, 0, 0}}, Ray{{0.5, 0.5, -1}, {nan, 0, 1}},
                           Ray{{nan, 0.5, -1}, {0, 0, 1}},
                           Ray{{0.5, 0.5, -1}, {0, 0, std::numeric_limits<double>::infinity()}}}) {
        EXPECT_FALSE(box.closest_hit(ray, Interval{}, counters));
        EXPECT_FALSE(box.occluded(ray, Interval{}, counters));
    }
    SceneBuilder b;
    b.add_polygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    test::compare_with_brute_force(b.scene(), Bvh(b.scene()), 2000, 25);
}

TEST(BvhEdgeCases, ConcurrentQueriesGiveTheSameAnswers) {
    const Scene scene = test::make_triangle_soup(5000, 11);
    const Bvh bvh(scene);
    const std::vector<RayQuery> queries = test::random_queries(scene, 4000, 26);
    std::vector<std::optional<Hit>> sequential;
    TraceCounters counters;
    for (const RayQuery& q : queries) {
        sequential.push_back(bvh.closest_hit(q.ray, q.t, counters));
    }
    std::vector<std::optional<Hit>> parallel(queries.size());
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t) {
        threads.emplace_back([&, t] {
            TraceCounters own;
            for (std::size_t i = t; i < queries.size(); i += 4) {
                parallel[i] = bvh.closest_hit(queries[i].ray, queries[i].t, own);
            }
        });
    }
    for (std::thread& t : threads) {
        t.join();
    }
    for (std::size_t i = 0; i < queries.size(); ++i) {
        ASSERT_EQ(parallel[i].has_value(), sequential[i].has_value()) << i;
        if (parallel[i]) {
            EXPECT_EQ(parallel[i]->t, sequential[i]->t);
            EXPECT_EQ(parallel[i]->polygon, sequential[i]->polygon);
        }
    }
}

}  // namespace
}  // namespace rt
