// Brute force, the reference every other accelerator is compared with: the nearest hit, ties to
// the lowest polygon id, the open interval, occluded() agreeing with closest_hit(), and its
// answers against an independent long double computation (so a bug in intersect_polygon shows).
#include "rt/accel/brute_force.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

constexpr Interval kAhead{0.0, kBeyondAnyScene};

// Unit squares facing +z at the given heights, in the order given.
Scene squares_at(const std::vector<double>& heights) {
    test::SceneBuilder b;
    for (const double z : heights) {
        b.add_polygon({{-1, -1, z}, {1, -1, z}, {1, 1, z}, {-1, 1, z}}, {0, 0, 1});
    }
    return std::move(b.scene());
}

constexpr Ray kDown{{0.25, 0.5, 10}, {0, 0, -1}};

TEST(BruteForce, ReturnsTheNearestHitWhateverTheOrder) {
    const Scene scene = squares_at({-3, 4, 1, 7.5, -1});
    const BruteForce accel(scene);
    TraceCounters counters;
    const std::optional<Hit> hit = accel.closest_hit(kDown, kAhead, counters);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->polygon, 3u);
    EXPECT_DOUBLE_EQ(hit->t, 2.5);
    EXPECT_EQ(counters.polygon_tests, 5u);
}

// A ray leaving square 0 nearly along it, its origin a rounding below the plane: the exact test
// gives the square back at a grazing depth beyond the epsilon, unless the ray names the square
// as the one it leaves (Ray::leaves), which no test then asks about.
TEST(BruteForce, SkipsThePolygonTheRayLeaves) {
    const Scene scene = squares_at({0, 2});
    const BruteForce accel(scene);
    Ray grazing{{0.25, 0.5, -1e-12}, {1, 0, 1e-9}};
    constexpr Interval kBeyondEpsilon{1e-9, kBeyondAnyScene};
    TraceCounters counters;
    const std::optional<Hit> again = accel.closest_hit(grazing, kBeyondEpsilon, counters);
    ASSERT_TRUE(again);  // the premise: without leaves, the square it leaves is hit
    EXPECT_EQ(again->polygon, 0u);
    EXPECT_TRUE(accel.occluded(grazing, kBeyondEpsilon, counters));
    grazing.leaves = 0;
    TraceCounters skipping;
    EXPECT_FALSE(accel.closest_hit(grazing, kBeyondEpsilon, skipping));
    EXPECT_EQ(skipping.polygon_tests, 1u);
    EXPECT_FALSE(accel.occluded(grazing, kBeyondEpsilon, skipping));
    // The other square is still there for it.
    const Ray up{{0.25, 0.5, 0.0}, {0, 0, 1}, 0};
    const std::optional<Hit> above = accel.closest_hit(up, kBeyondEpsilon, skipping);
    ASSERT_TRUE(above);
    EXPECT_EQ(above->polygon, 1u);
}

TEST(BruteForce, RespectsTheOpenInterval) {
    const Scene scene = squares_at({-3, 4, 1, 7.5, -1});
    const BruteForce accel(scene);
    TraceCounters counters;
    // Starting exactly at the nearest square's t: that one no longer counts (open at min).
    const std::optional<Hit> past = accel.closest_hit(kDown, {2.5, kBeyondAnyScene}, counters);
    ASSERT_TRUE(past);
    EXPECT_EQ(past->polygon, 1u);
    // Ending exactly at a square's t: not hit (open at max).
    EXPECT_FALSE(accel.closest_hit(kDown, {0.0, 2.5}, counters));
    EXPECT_FALSE(accel.occluded(kDown, {0.0, 2.5}, counters));
    EXPECT_TRUE(accel.occluded(kDown, {0.0, std::nextafter(2.5, 3.0)}, counters));
}

TEST(BruteForce, TiesGoToTheLowestPolygonId) {
    // Polygons 1, 2 and 4 coincide; 0 and 3 are farther.
    const Scene scene = squares_at({-2, 1, 1, -5, 1});
    const BruteForce accel(scene);
    TraceCounters counters;
    const std::optional<Hit> hit = accel.closest_hit(kDown, kAhead, counters);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->polygon, 1u);
    EXPECT_DOUBLE_EQ(hit->t, 9.0);
}

TEST(BruteForce, TiesBetweenDifferentShapesAtOneDepth) {
    // A triangle and a quad touching the same point of the ray at the same t, given in both orders.
    const std::vector<Vec3> triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<Vec3> quad{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    const Ray ray{{0.2, 0.2, 3}, {0, 0, -1}};
    for (const bool triangle_first : {true, false}) {
        test::SceneBuilder b;
        b.add_polygon(triangle_first ? triangle : quad, {0, 0, 1});
        b.add_polygon(triangle_first ? quad : triangle, {0, 0, 1});
        const BruteForce accel(b.scene());
        TraceCounters counters;
        const std::optional<Hit> hit = accel.closest_hit(ray, kAhead, counters);
        ASSERT_TRUE(hit);
        EXPECT_EQ(hit->polygon, 0u);
    }
}

TEST(BruteForce, EmptySceneAndInvalidRaysHitNothing) {
    const Scene empty;
    const BruteForce none(empty);
    TraceCounters counters;
    EXPECT_FALSE(none.closest_hit(kDown, kAhead, counters));
    EXPECT_FALSE(none.occluded(kDown, kAhead, counters));

    const Scene scene = squares_at({0});
    const BruteForce accel(scene);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const Vec3& direction : {Vec3{0, 0, 0}, Vec3{0, 0, nan}, Vec3{0, 0, -HUGE_VAL}}) {
        const Ray ray{{0, 0, 5}, direction};
        EXPECT_FALSE(accel.closest_hit(ray, kAhead, counters));
        EXPECT_FALSE(accel.occluded(ray, kAhead, counters));
    }
}

TEST(BruteForce, OccludedStopsAtTheFirstHit) {
    const Scene scene = squares_at({1, 2, 3, 4});
    const BruteForce accel(scene);
    TraceCounters counters;
    EXPECT_TRUE(accel.occluded(kDown, kAhead, counters));
    EXPECT_EQ(counters.polygon_tests, 1u);
}

// A scene of closed meshes with shared edges: boxes of quads and triangles, a sphere, a fan.
Scene clutter() {
    test::SceneBuilder b;
    const auto append = [&](const Scene& part) {
        for (const Polygon& p : part.polygons) {
            std::vector<Vec3> loop;
            for (std::uint32_t k = 0; k < p.corner_count; ++k) {
                loop.push_back(part.corner_position(p, k));
            }
            b.add_polygon(loop, p.normal);
        }
    };
    append(test::make_box({-2, -2, -2}, {-0.5, 0, 1}, false));
    append(test::make_box({0.5, -1, -1}, {2, 2, 0.5}, true));
    append(test::make_sphere({0, 1.5, 1}, 0.8, 6, 10, false));
    append(test::make_fan(9, 1.2));
    return std::move(b.scene());
}

// An independent reference, sharing no code with intersect_polygon: in long double, the plane
// of the polygon's own Newell normal, the point where the ray meets it, and inside-ness by the
// point's side of every edge in 3D (so convex polygons only, which clutter() holds). Rays it
// cannot decide to within its tolerance are left out: those passing within 1e-9 of the
// polygon's size of an edge or a corner (where the exact test's watertight rule decides), within
// 1e-4 of a polygon's plane in angle (where it takes a grazing depth), with a hit within 1e-9 of
// an end of the interval, or with two hits that near each other.
using Real = long double;

struct RealVec {
    Real x = 0;
    Real y = 0;
    Real z = 0;
};

RealVec real(const Vec3& v) {
    return {v.x, v.y, v.z};
}
RealVec operator-(const RealVec& a, const RealVec& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
RealVec operator+(const RealVec& a, const RealVec& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
RealVec operator*(const RealVec& a, Real s) {
    return {a.x * s, a.y * s, a.z * s};
}
Real dot(const RealVec& a, const RealVec& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
RealVec cross(const RealVec& a, const RealVec& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Real norm(const RealVec& a) {
    return std::sqrt(dot(a, a));
}

struct ReferenceHit {
    std::optional<Hit> hit;
    bool undecided = false;
};

constexpr Real kEdgeTolerance = 1e-9L;
constexpr Real kGrazingTolerance = 1e-4L;
constexpr Real kDepthTolerance = 1e-9L;

ReferenceHit reference_nearest(const Scene& scene, const Ray& ray, Interval interval) {
    const RealVec o = real(ray.origin);
    const RealVec d = real(ray.direction);
    ReferenceHit result;
    Real best = 0;
    Real second = HUGE_VALL;
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        const Polygon& p = scene.polygons[id];
        std::vector<RealVec> c;
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            c.push_back(real(scene.corner_position(p, k)));
        }
        RealVec n;  // Newell's: along the loop's turning, so inside is left of every edge
        Real size = 0;
        for (std::size_t k = 0; k < c.size(); ++k) {
            n = n + cross(c[k], c[(k + 1) % c.size()]);
            size = std::max(size, norm(c[(k + 1) % c.size()] - c[k]));
        }
        const Real cosine = dot(n, d) / (norm(n) * norm(d));
        const Real t = dot(n, c[0] - o) / dot(n, d);
        const RealVec point = o + d * t;
        Real margin = HUGE_VALL;  // the point's least distance inside an edge (negative: outside)
        for (std::size_t k = 0; k < c.size(); ++k) {
            const RealVec edge = c[(k + 1) % c.size()] - c[k];
            margin = std::min(margin, dot(cross(edge, point - c[k]), n) / (norm(edge) * norm(n)));
        }
        if (std::fabs(cosine) < kGrazingTolerance) {
            // Nearly edge-on: decided only if the line stays far from the polygon.
            result.undecided = result.undecided || margin > -size;
            continue;
        }
        if (std::fabs(margin) < kEdgeTolerance * size) {
            result.undecided = true;
            continue;
        }
        if (margin < 0) {
            continue;
        }
        const Real near_end = kDepthTolerance * std::max<Real>(1, std::fabs(t));
        if (std::fabs(t - interval.min) < near_end || std::fabs(t - interval.max) < near_end) {
            result.undecided = true;
        }
        if (!(t > interval.min && t < interval.max)) {
            continue;
        }
        if (!result.hit || t < best) {
            second = result.hit ? best : second;
            best = t;
            result.hit = Hit{static_cast<double>(t), id};
        } else {
            second = std::min(second, t);
        }
    }
    if (result.hit && second - best < kDepthTolerance * std::max<Real>(1, std::fabs(best))) {
        result.undecided = true;
    }
    return result;
}

TEST(BruteForce, AgreesWithAnIndependentReference) {
    const Scene scene = clutter();
    const BruteForce accel(scene);
    std::mt19937_64 random(51);
    std::uniform_real_distribution<double> coordinate(-4.0, 4.0);
    std::normal_distribution<double> gauss;
    int hits = 0;
    int undecided = 0;
    constexpr int kRays = 4000;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    // Half the rays aimed at a random mixture of a polygon's corners, so that many hit.
    const auto point_on_a_polygon = [&] {
        const Polygon& p = scene.polygons[random() % scene.polygons.size()];
        Vec3 sum;
        double total = 0.0;
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            const double w = unit(random);
            sum += scene.corner_position(p, k) * w;
            total += w;
        }
        return sum / total;
    };
    for (int i = 0; i < kRays; ++i) {
        const Vec3 origin{coordinate(random), coordinate(random), coordinate(random)};
        const Vec3 direction = i % 2 == 0 ? Vec3{gauss(random), gauss(random), gauss(random)}
                                          : (point_on_a_polygon() - origin) * (0.5 + unit(random));
        const Ray ray{origin, direction};
        const Interval t{i % 3 == 0 ? 0.5 : 0.0, i % 5 == 0 ? 2.0 : kBeyondAnyScene};
        TraceCounters counters;
        const ReferenceHit expected = reference_nearest(scene, ray, t);
        const std::optional<Hit> hit = accel.closest_hit(ray, t, counters);
        EXPECT_EQ(accel.occluded(ray, t, counters), hit.has_value());
        if (hit) {
            EXPECT_GT(hit->t, t.min);
            EXPECT_LT(hit->t, t.max);
            // Shortened to end at the nearest hit, nothing is in the way.
            EXPECT_FALSE(accel.occluded(ray, {t.min, hit->t}, counters));
            EXPECT_FALSE(accel.closest_hit(ray, {t.min, hit->t}, counters));
        }
        if (expected.undecided) {
            ++undecided;
            continue;
        }
        ASSERT_EQ(hit.has_value(), expected.hit.has_value()) << "ray " << i;
        if (hit) {
            ++hits;
            EXPECT_EQ(hit->polygon, expected.hit->polygon) << "ray " << i;
            EXPECT_NEAR(hit->t, expected.hit->t, 1e-12 * std::max(1.0, hit->t)) << "ray " << i;
        }
    }
    EXPECT_LT(undecided, kRays / 100) << "the reference decides too few rays";
    EXPECT_GT(hits, kRays / 2 - 500);  // 2243 of 4000
    EXPECT_LT(hits, kRays - 500);
}

TEST(BruteForce, MakeBruteForceNamesItself) {
    const Scene scene = squares_at({0});
    const std::unique_ptr<Accelerator> accel = make_brute_force(scene);
    EXPECT_EQ(accel->name(), "brute force");
    TraceCounters counters;
    EXPECT_TRUE(accel->closest_hit(kDown, kAhead, counters));
}

}  // namespace
}  // namespace rt
