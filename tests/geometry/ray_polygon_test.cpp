// intersect_polygon on single polygons: triangles, quads, concave and self-crossing loops, many
// corners; rays parallel to or in the polygon's plane; invalid rays; the open interval.
#include "rt/geometry/ray_polygon.h"

#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr Interval kWholeLine{-kBeyondAnyScene, kBeyondAnyScene};
constexpr Vec3 kUp{0, 0, 1};

// A ray straight down onto the point (x, y) of the plane z = 0, from z = 5.
Ray down_onto(double x, double y) {
    return {{x, y, 5.0}, {0, 0, -1}};
}

std::optional<double> hit_flat(const std::vector<Vec3>& corners, const Ray& ray,
                               Interval t = kWholeLine) {
    return intersect_polygon(ray, corners, kUp, t);
}

bool hits_flat(const std::vector<Vec3>& corners, double x, double y) {
    return hit_flat(corners, down_onto(x, y)).has_value();
}

// Corners on a circle (z = 0), counter-clockwise seen from +z; radius per corner alternating
// between `outer` and `inner` makes a concave star.
std::vector<Vec3> circle_loop(int count, double outer, double inner) {
    std::vector<Vec3> loop;
    for (int k = 0; k < count; ++k) {
        const double phi = 2.0 * std::numbers::pi * k / count;
        const double r = k % 2 == 0 ? outer : inner;
        loop.push_back({r * std::cos(phi), r * std::sin(phi), 0.0});
    }
    return loop;
}

// Reference: even-odd crossing test in the plane z = 0 (right for simple polygons away from the
// boundary, which is all it is asked about).
bool inside_by_crossings(const std::vector<Vec3>& loop, double x, double y) {
    bool inside = false;
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        const Vec3& a = loop[i];
        const Vec3& b = loop[j];
        if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (b.y - a.y) + a.x) {
            inside = !inside;
        }
    }
    return inside;
}

// Distance from (x, y) to the loop's boundary, to keep the reference away from its weak spot.
double distance_to_boundary(const std::vector<Vec3>& loop, double x, double y) {
    double nearest = kInf;
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
        const Vec3 p{x, y, 0};
        const Vec3 edge = loop[i] - loop[j];
        const double s = std::clamp(dot(p - loop[j], edge) / dot(edge, edge), 0.0, 1.0);
        nearest = std::min(nearest, length(p - (loop[j] + edge * s)));
    }
    return nearest;
}

const std::vector<Vec3> triangle_corners{{0, 0, 0}, {4, 0, 0}, {0, 3, 0}};
const std::vector<Vec3> square_corners{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
// An L: the square [0,2]^2 without its upper right quarter [1,2]x[1,2].
const std::vector<Vec3> l_shape_corners{{0, 0, 0}, {2, 0, 0}, {2, 1, 0},
                                        {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};

TEST(IntersectPolygon, TriangleHitAndDepth) {
    const std::optional<double> t = hit_flat(triangle_corners, down_onto(1, 1));
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ(*t, 5.0);
    EXPECT_FALSE(hits_flat(triangle_corners, 3, 2));  // beyond the hypotenuse
    EXPECT_FALSE(hits_flat(triangle_corners, -0.1, 1));
    EXPECT_FALSE(hits_flat(triangle_corners, 1, -0.1));
}

TEST(IntersectPolygon, DepthScalesWithTheDirectionsLength) {
    const Ray slow{{1, 1, 5}, {0, 0, -0.5}};
    const std::optional<double> t = hit_flat(triangle_corners, slow);
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ(*t, 10.0);
}

TEST(IntersectPolygon, EitherLoopOrientationAndEitherSideHit) {
    std::vector<Vec3> reversed(square_corners.rbegin(), square_corners.rend());
    EXPECT_TRUE(hits_flat(reversed, 1, 1));
    const Ray from_below{{1, 1, -5}, {0, 0, 1}};
    EXPECT_TRUE(hit_flat(square_corners, from_below));
    EXPECT_TRUE(hit_flat(reversed, from_below));
}

TEST(IntersectPolygon, ObliqueRayThroughATiltedQuad) {
    // The unit square tilted about the x axis; the ray aims at its centre from an angle.
    const double c = std::cos(0.7), s = std::sin(0.7);
    const std::vector<Vec3> quad{{0, 0, 0}, {1, 0, 0}, {1, c, s}, {0, c, s}};
    const Vec3 normal = test::newell_normal(quad);
    const Vec3 centre{0.5, 0.5 * c, 0.5 * s};
    const Vec3 direction{0.3, -0.4, -1.0};
    const Ray ray{centre - direction * 7.0, direction};
    const std::optional<double> t = intersect_polygon(ray, quad, normal, kWholeLine);
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 7.0, 1e-12);
    const Ray beside{centre + Vec3{1.2, 0, 0} - direction * 7.0, direction};
    EXPECT_FALSE(intersect_polygon(beside, quad, normal, kWholeLine));
}

TEST(IntersectPolygon, LShapeMissesItsNotch) {
    EXPECT_TRUE(hits_flat(l_shape_corners, 0.5, 0.5));
    EXPECT_TRUE(hits_flat(l_shape_corners, 1.5, 0.5));
    EXPECT_TRUE(hits_flat(l_shape_corners, 0.5, 1.5));
    EXPECT_FALSE(hits_flat(l_shape_corners, 1.5, 1.5));  // the notch
    EXPECT_FALSE(hits_flat(l_shape_corners, 1.01, 1.01));
    EXPECT_TRUE(hits_flat(l_shape_corners, 0.99, 0.99));
}

TEST(IntersectPolygon, ConcaveStarMissesBetweenItsPoints) {
    const std::vector<Vec3> star = circle_loop(10, 2.0, 0.5);
    EXPECT_TRUE(hits_flat(star, 0, 0));
    EXPECT_TRUE(hits_flat(star, 1.8, 0));  // near the tip at angle 0
    // Between two tips (angle 36 degrees, where the inner corner is at radius 0.5).
    const double phi = 2.0 * std::numbers::pi / 10;
    EXPECT_FALSE(hits_flat(star, 1.0 * std::cos(phi), 1.0 * std::sin(phi)));
    EXPECT_TRUE(hits_flat(star, 0.4 * std::cos(phi), 0.4 * std::sin(phi)));
}

TEST(IntersectPolygon, SelfCrossingPentagramCountsItsCentre) {
    // Corners 0, 2, 4, 1, 3 of a pentagon: the centre is wound twice, the points once.
    const std::vector<Vec3> pentagon = circle_loop(5, 1.0, 1.0);
    const std::vector<Vec3> pentagram{pentagon[0], pentagon[2], pentagon[4], pentagon[1],
                                      pentagon[3]};
    const RaySpace centre(down_onto(0, 0));
    EXPECT_EQ(std::abs(winding_number(centre, pentagram)), 2);
    EXPECT_TRUE(hits_flat(pentagram, 0, 0));
    EXPECT_TRUE(hits_flat(pentagram, 0.8, 0));  // inside the point at corner 0
    EXPECT_FALSE(hits_flat(pentagram, 0.7 * std::cos(0.63), 0.7 * std::sin(0.63)));  // a notch
}

TEST(IntersectPolygon, ManyCornersAgreeWithACrossingTest) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> coordinate(-2.2, 2.2);
    for (const int corners : {20, 21, 200}) {
        for (const double inner : {2.0, 1.2, 0.3}) {  // convex, then two concave stars
            const std::vector<Vec3> loop = circle_loop(corners, 2.0, inner);
            int hits = 0;
            for (int i = 0; i < 2000; ++i) {
                const double x = coordinate(random), y = coordinate(random);
                if (distance_to_boundary(loop, x, y) < 1e-9) {
                    continue;
                }
                const bool hit = hits_flat(loop, x, y);
                ASSERT_EQ(hit, inside_by_crossings(loop, x, y))
                    << corners << " corners, inner " << inner << " at " << x << "," << y;
                hits += hit ? 1 : 0;
            }
            EXPECT_GT(hits, 0);
            EXPECT_LT(hits, 2000);
        }
    }
}

TEST(IntersectPolygon, WindingNumberFollowsTheLoopsOrientation) {
    const RaySpace down(down_onto(1, 1));
    const std::vector<Vec3> reversed(square_corners.rbegin(), square_corners.rend());
    const int forward = winding_number(down, square_corners);
    EXPECT_EQ(std::abs(forward), 1);
    EXPECT_EQ(winding_number(down, reversed), -forward);
    const RaySpace up(Ray{{1, 1, -5}, {0, 0, 1}});
    EXPECT_EQ(std::abs(winding_number(up, square_corners)), 1);  // from the other side: hit too
    EXPECT_EQ(winding_number(RaySpace(down_onto(3, 3)), square_corners), 0);
    EXPECT_TRUE(ray_passes_through(down, square_corners));
}

TEST(IntersectPolygon, FewerThanThreeCornersNeverHit) {
    const std::vector<Vec3> two{{-1, -1, 0}, {1, 1, 0}};
    EXPECT_FALSE(hit_flat(two, down_onto(0, 0)));
    EXPECT_EQ(winding_number(RaySpace(down_onto(0, 0)), two), 0);
    EXPECT_FALSE(hit_flat({}, down_onto(0, 0)));
}

TEST(IntersectPolygon, RayParallelToThePlaneMisses) {
    EXPECT_FALSE(hit_flat(square_corners, Ray{{1, 1, 1}, {1, 0, 0}}));
    EXPECT_FALSE(hit_flat(square_corners, Ray{{-5, 1, 1e-9}, {1, 0.2, 0}}));
}

TEST(IntersectPolygon, RayInThePlaneMisses) {
    // Exactly in the plane, through the middle and along an edge: the projection has no area.
    EXPECT_FALSE(hit_flat(square_corners, Ray{{-5, 1, 0}, {1, 0, 0}}));
    EXPECT_FALSE(hit_flat(square_corners, Ray{{-5, 0, 0}, {1, 0, 0}}));
    EXPECT_FALSE(hit_flat(square_corners, Ray{{-5, -5, 0}, {1, 1, 0}}));  // the diagonal
    EXPECT_FALSE(hit_flat(l_shape_corners, Ray{{-5, 1.5, 0}, {1, 0, 0}}));
}

TEST(IntersectPolygon, NearlyParallelRayHitsWhereItCrossesThePlane) {
    // Dropping 1e-9 over 5 units: the plane z = 0 is met at x = 1, inside the square, by a ray
    // far below the grazing limit.
    const Ray ray{{-4, 1, 1e-9}, {1, 0, -2e-10}};
    const std::optional<double> t = hit_flat(square_corners, ray);
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 5.0, 1e-6);
    const Ray beside{{-4, 3, 1e-9}, {1, 0, -2e-10}};
    EXPECT_FALSE(hit_flat(square_corners, beside));
    const Ray short_of_it{{-4, 1, 1e-9}, {1, 0, -1e-10}};  // would meet the plane at x = 6
    EXPECT_FALSE(hit_flat(square_corners, short_of_it));
}

TEST(IntersectPolygon, GrazingDepthStaysWhereTheLineIsInTheCornerBox) {
    // A zero normal sends every ray down the grazing branch, whose depth starts at the nearest
    // corner's (t = 2.5 here, at x = 2.5 and z = 2.5, above the flat triangle's box). The line
    // is inside that box only at z = 0, t = 5, so that is the depth reported.
    const std::vector<Vec3> thin{{0, 0, 0}, {10, 1, 0}, {10, -1, 0}};
    const Ray oblique{{0, 0, 5}, {1, 0, -1}};
    const std::optional<double> t = intersect_polygon(oblique, thin, Vec3{0, 0, 0}, kWholeLine);
    ASSERT_TRUE(t);
    EXPECT_NEAR(*t, 5.0, 1e-9);
    // Where that span and the corners' depths overlap widely, the depth is still clamped into
    // both: a ray along the triangle's length meets its box over t in [0, 10].
    const Ray along{{-1, 0, 1e-12}, {1, 0, -1e-13}};
    const std::optional<double> u = intersect_polygon(along, thin, Vec3{0, 0, 0}, kWholeLine);
    ASSERT_TRUE(u);
    EXPECT_GE(*u, 1.0 - 1e-9);
    EXPECT_LE(*u, 11.0 + 1e-9);
}

TEST(IntersectPolygon, InvalidRaysMiss) {
    const Vec3 origin{1, 1, 5};
    for (const Vec3& direction : {Vec3{0, 0, 0}, Vec3{0, 0, kNaN}, Vec3{kNaN, kNaN, kNaN},
                                  Vec3{0, 0, -kInf}, Vec3{kInf, 0, -1}, Vec3{0, 0, -0.0}}) {
        const Ray ray{origin, direction};
        EXPECT_FALSE(RaySpace(ray).valid());
        EXPECT_FALSE(hit_flat(square_corners, ray));
        EXPECT_EQ(winding_number(RaySpace(ray), square_corners), 0);
    }
    // Finite components, but a length beyond the largest double.
    EXPECT_FALSE(RaySpace(Ray{origin, {1.5e308, 1.5e308, -1.5e308}}).valid());
    for (const Vec3& bad_origin : {Vec3{kNaN, 1, 5}, Vec3{1, kInf, 5}}) {
        EXPECT_FALSE(RaySpace(Ray{bad_origin, {0, 0, -1}}).valid());
        EXPECT_FALSE(hit_flat(square_corners, Ray{bad_origin, {0, 0, -1}}));
    }
}

// A direction's length is only a unit for t: scaled by 1e200 or 1e-200 (so that its squared
// length overflows or underflows) the ray meets the polygon at the same point, at t / scale.
TEST(IntersectPolygon, HugeAndTinyDirectionsHitAtScaledDepths) {
    for (const double scale : {1e200, 1e-200, 1e150, 1e-150}) {
        const Ray steep{{1, 1, 5}, Vec3{0.01, -0.02, -1} * scale};
        const std::optional<double> t = hit_flat(square_corners, steep);
        ASSERT_TRUE(t) << "scale " << scale;
        EXPECT_NEAR(*t * scale, 5.0, 1e-12) << "scale " << scale;
        // Nearly in the plane (the grazing case): depth between the corners' depths.
        const Ray grazing{{-4, 1, 1e-9}, Vec3{1, 0, -2e-10} * scale};
        const std::optional<double> g = hit_flat(square_corners, grazing);
        ASSERT_TRUE(g) << "scale " << scale;
        EXPECT_NEAR(*g * scale, 5.0, 1e-6) << "scale " << scale;
    }
}

TEST(IntersectPolygon, NonFiniteCornersMiss) {
    const std::vector<Vec3> broken{{0, 0, 0}, {2, 0, 0}, {kNaN, 2, 0}, {0, 2, 0}};
    const std::vector<Vec3> huge{{0, 0, 0}, {kInf, 0, 0}, {kInf, kInf, 0}, {0, kInf, 0}};
    EXPECT_FALSE(hit_flat(broken, down_onto(1.5, 0.5)));
    EXPECT_FALSE(hit_flat(huge, down_onto(1, 1)));
}

TEST(IntersectPolygon, IntervalIsOpenAtBothEnds) {
    const Ray ray = down_onto(1, 1);  // meets the square at t = 5 exactly
    EXPECT_TRUE(hit_flat(square_corners, ray, {4.0, 6.0}));
    EXPECT_FALSE(hit_flat(square_corners, ray, {5.0, 6.0}));
    EXPECT_FALSE(hit_flat(square_corners, ray, {4.0, 5.0}));
    EXPECT_TRUE(
        hit_flat(square_corners, ray, {std::nextafter(5.0, 0.0), std::nextafter(5.0, 6.0)}));
    EXPECT_FALSE(
        hit_flat(square_corners, Ray{{1, 1, -5}, {0, 0, -1}}, {0.0, kBeyondAnyScene}));  // behind
}

// The question asked before a ray's RaySpace is made: never "missed" where the exact test hits.
// Rays start on the plane (a reflection beside coplanar neighbours), end on it (a feeler on its
// light), cross it obliquely or nearly edge-on (around the grazing limit, where the exact test
// switches to corner depths), at huge and tiny direction lengths.
TEST(PlaneCertainlyMissed, OnlyWhereTheExactTestMisses) {
    std::mt19937_64 random(15);
    std::uniform_real_distribution<double> any(-10.0, 10.0);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double cosines[] = {0.0, 0.5e-6, 1e-6, 1.2e-6, 1.73e-6, 1.75e-6, 1.8e-6, 3e-6, 1e-3, 0.3};
    int missed = 0;
    int cases = 0;
    for (int i = 0; i < 40000; ++i) {
        const Vec3 a{any(random), any(random), any(random)};
        const Vec3 b{any(random), any(random), any(random)};
        const Vec3 c{any(random), any(random), any(random)};
        const Vec3 normal = normalize(cross(b - a, c - a));
        const std::vector<Vec3> corners{a, b, c};
        // A point of the plane, inside the triangle or outside it.
        const double u = unit(random) * 1.4 - 0.2;
        const double v = unit(random) * (1.2 - u);
        const Vec3 on_plane = a + (b - a) * u + (c - a) * v;
        // A direction at a chosen |cos| with the normal.
        const Vec3 side = normalize(cross(normal, Vec3{any(random), any(random), any(random)}));
        const double cosine = cosines[i % std::size(cosines)] * (i % 3 == 0 ? -1.0 : 1.0);
        const Vec3 unit_direction =
            normalize(side * std::sqrt(1.0 - cosine * cosine) + normal * cosine);
        const double scale = (i % 7 == 0) ? 1e150 : ((i % 11 == 0) ? 1e-150 : 1.0 + unit(random));
        Ray ray{};
        Interval t{};
        switch (i % 4) {
            case 0:  // leaving the plane, as a reflection does
                ray = {on_plane, unit_direction * scale};
                t = {1e-9 / scale, kBeyondAnyScene};
                break;
            case 1: {  // ending on it, as a feeler on its light
                const Vec3 from = on_plane - unit_direction * (1.0 + unit(random) * 5.0);
                ray = {from, (on_plane - from) * scale};
                t = {1e-9, 1.0 / scale * (1.0 - 1e-9)};
                break;
            }
            case 2: {  // a hair off the plane, crossing the triangle nearly edge-on
                const double hair = (i % 5 + 1) * 1e-9 * (i % 2 == 0 ? 1.0 : -1.0);
                const Vec3 from = on_plane - side * 30.0 + normal * hair;
                ray = {from, unit_direction * scale};
                t = {0.0, kBeyondAnyScene};
                break;
            }
            default: {  // from anywhere, either way
                const Vec3 from{any(random), any(random), any(random)};
                ray = {from, unit_direction * scale};
                t = i % 2 == 0 ? Interval{0.0, kBeyondAnyScene} : Interval{-kBeyondAnyScene, 0.0};
            }
        }
        ++cases;
        if (plane_certainly_missed(ray, normal, a, t)) {
            ++missed;
            ASSERT_FALSE(intersect_polygon(ray, corners, normal, t)) << "case " << i;
        }
    }
    EXPECT_GT(missed, cases / 4) << "the question answers \"missed\" too rarely to matter";
}

TEST(PlaneCertainlyMissed, NeverForNaNOrEdgeOn) {
    const Vec3 a{0, 0, 0};
    EXPECT_FALSE(plane_certainly_missed(Ray{{0, 0, 5}, {1, 0, 0}}, kUp, a, kWholeLine));
    EXPECT_FALSE(plane_certainly_missed(Ray{{0, 0, 5}, {0, 0, kNaN}}, kUp, a, {0.0, 1.0}));
    EXPECT_FALSE(plane_certainly_missed(Ray{{0, 0, kNaN}, {0, 0, -1}}, kUp, a, {0.0, 1.0}));
    // Edge-on within the limit: the exact test takes corner depths, so no answer here.
    EXPECT_FALSE(plane_certainly_missed(Ray{{-1, 0, 1e-9}, {1, 0, -1e-7}}, kUp, a, {0.0, 1.0}));
    // Crossing the plane behind the interval: missed.
    EXPECT_TRUE(plane_certainly_missed(Ray{{0, 0, 5}, {0, 0, 1}}, kUp, a, {0.0, kBeyondAnyScene}));
    EXPECT_TRUE(plane_certainly_missed(Ray{{0, 0, 5}, {0, 0, -1}}, kUp, a, {0.0, 5.0}));
    EXPECT_FALSE(plane_certainly_missed(Ray{{0, 0, 5}, {0, 0, -1}}, kUp, a, {0.0, 6.0}));
}

// A plane group (one normal, corners 0 in the plane within in_plane_group's tolerance): when the
// question says a ray misses the group, the exact test misses every member. Rays leave a member
// (on its plane, or a hair off it) in any direction, nearly edge-on too, with the renderer's
// t_min and with ones far below the plane's rounding.
TEST(PlaneGroupCertainlyMissed, OnlyWhereTheExactTestMissesEveryMember) {
    std::mt19937_64 random(41);
    std::uniform_real_distribution<double> any(-1.0, 1.0);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int skipped = 0;
    int cases = 0;
    for (int group = 0; group < 200; ++group) {
        const double size = std::pow(10.0, any(random) * 3.0);
        const Vec3 centre = Vec3{any(random), any(random), any(random)} * size;
        const Vec3 e1 = normalize(Vec3{any(random), any(random), any(random)});
        const Vec3 e2 = normalize(cross(e1, Vec3{any(random), any(random), any(random)}));
        const Vec3 normal = normalize(cross(e1, e2));
        std::vector<std::vector<Vec3>> members;
        double scale = 0.0;
        for (int k = 0; k < 12; ++k) {
            const auto point = [&] {
                return centre + e1 * (any(random) * size) + e2 * (any(random) * size);
            };
            std::vector<Vec3> corners{point(), point(), point()};
            if (k % 3 == 2) {
                // Off the plane by up to the group's tolerance, parallel to it.
                const double n1 = std::fabs(normal.x) + std::fabs(normal.y) + std::fabs(normal.z);
                const double shift = 0x1p-41 * n1 * std::fabs(centre.x + size) * any(random);
                for (Vec3& c : corners) {
                    c = c + normal * shift;
                }
            }
            if (!members.empty() && !in_plane_group(normal, members[0][0], corners[0])) {
                continue;
            }
            for (const Vec3& c : corners) {
                scale = std::max({scale, std::fabs(c.x), std::fabs(c.y), std::fabs(c.z)});
            }
            members.push_back(corners);
        }
        ASSERT_GE(members.size(), 6u) << "the group's tolerance takes too few of its polygons";
        for (int r = 0; r < 200; ++r) {
            const std::vector<Vec3>& from = members[static_cast<std::size_t>(r) % members.size()];
            const double a = unit(random);
            const double b = unit(random) * (1.0 - a);
            Vec3 origin = from[0] + (from[1] - from[0]) * a + (from[2] - from[0]) * b;
            if (r % 5 == 0) {
                origin = origin + normal * (1e-13 * size * any(random));
            }
            const Vec3 side = normalize(cross(normal, Vec3{any(random), any(random), any(random)}));
            const double cosines[] = {1e-7, 1e-6, 1.8e-6, 1e-4, 0.1, 0.7, 1.0};
            const double cosine = cosines[r % 7] * (r % 2 == 0 ? 1.0 : -1.0);
            const Vec3 direction =
                (side * std::sqrt(1.0 - cosine * cosine) + normal * cosine) * (0.5 + unit(random));
            const double epsilon = (r % 3 == 0 ? 1e-20 : 1e-9) * size;
            const Interval t{epsilon / length(direction), kBeyondAnyScene};
            const Ray ray{origin, direction};
            ++cases;
            if (!plane_group_certainly_missed(ray, normal, members[0][0],
                                              static_cast<double>(static_cast<float>(scale)),
                                              t.min)) {
                continue;
            }
            ++skipped;
            for (const std::vector<Vec3>& member : members) {
                ASSERT_FALSE(intersect_polygon(ray, member, normal, t))
                    << "group " << group << ", ray " << r;
            }
        }
    }
    EXPECT_GT(skipped, cases / 5) << "the question almost never answers";
}

TEST(PlaneHit, DepthOfThePlane) {
    const std::optional<double> t = plane_hit(Ray{{0, 0, 5}, {0, 0, -2}}, {7, 8, 1}, kUp);
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ(*t, 2.0);
    EXPECT_FALSE(plane_hit(Ray{{0, 0, 5}, {1, 0, 0}}, {0, 0, 0}, kUp));
    EXPECT_FALSE(plane_hit(Ray{{0, 0, 5}, {0, 0, kNaN}}, {0, 0, 0}, kUp));
    EXPECT_FALSE(plane_hit(Ray{{0, 0, 1e300}, {0, 0, -1e-300}}, {0, 0, 0}, kUp));  // t overflows
}

TEST(RaySpace, ProjectsTheRayToTheOrigin) {
    std::mt19937_64 random(8);
    std::uniform_real_distribution<double> any(-10.0, 10.0);
    for (int i = 0; i < 1000; ++i) {
        const Ray ray{{any(random), any(random), any(random)},
                      {any(random), any(random), any(random)}};
        const RaySpace space(ray);
        ASSERT_TRUE(space.valid());
        double x = 1.0, y = 1.0;
        space.project(ray.origin, x, y);
        EXPECT_EQ(x, 0.0);
        EXPECT_EQ(y, 0.0);
        space.project(ray.at(3.0), x, y);
        EXPECT_NEAR(x, 0.0, 1e-12);
        EXPECT_NEAR(y, 0.0, 1e-12);
        // A point off the line projects off the origin.
        space.project(ray.origin + cross(ray.direction, Vec3{1, 2, 3}), x, y);
        EXPECT_GT(std::hypot(x, y), 1e-9);
    }
}

// The exact test projects corners with the axes fixed when compiled; every bit must be
// project()'s, or neighbouring polygons tested by different paths could disagree on an edge.
TEST(RaySpace, ProjectingWithFixedAxesGivesTheSameBits) {
    std::mt19937_64 random(10);
    std::uniform_real_distribution<double> any(-10.0, 10.0);
    std::uniform_int_distribution<int> exponent(-30, 30);
    int by_axis[3] = {0, 0, 0};
    for (int i = 0; i < 3000; ++i) {
        const double scale = std::ldexp(1.0, exponent(random));
        const RaySpace space(Ray{{any(random), any(random), any(random)},
                                 {any(random) * scale, any(random) * scale, any(random)}});
        ASSERT_TRUE(space.valid());
        ++by_axis[space.dropped_axis()];
        for (int c = 0; c < 4; ++c) {
            const Vec3 corner{any(random) * scale, any(random), any(random) / scale};
            double x = 0.0;
            double y = 0.0;
            space.project(corner, x, y);
            double fx = 1.0;
            double fy = 1.0;
            switch (space.dropped_axis()) {
                case 0:
                    space.project_dropping<0>(corner, fx, fy);
                    break;
                case 1:
                    space.project_dropping<1>(corner, fx, fy);
                    break;
                default:
                    space.project_dropping<2>(corner, fx, fy);
            }
            ASSERT_EQ(std::bit_cast<std::uint64_t>(x), std::bit_cast<std::uint64_t>(fx));
            ASSERT_EQ(std::bit_cast<std::uint64_t>(y), std::bit_cast<std::uint64_t>(fy));
        }
    }
    for (const int n : by_axis) {
        EXPECT_GT(n, 300);
    }
}

// RaySpace's set-up, written out here with the axes chosen at run time as the watertight test's
// paper does: the projection and the lengths must come out with the same bits.
TEST(RaySpace, SetsUpAsTheFormulasSay) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> any(-10.0, 10.0);
    std::uniform_int_distribution<int> exponent(-300, 300);
    for (int i = 0; i < 3000; ++i) {
        const double scale = std::ldexp(1.0, exponent(random));
        Vec3 d{any(random) * scale, any(random) * scale, any(random) * scale};
        if (i % 7 == 0) {
            d.x = 0.0;
        }
        const Ray ray{{any(random), any(random), any(random)}, d};
        const RaySpace space(ray);
        ASSERT_TRUE(space.valid());
        const double a[3] = {std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)};
        const int kz = (a[0] > a[1]) ? (a[0] > a[2] ? 0 : 2) : (a[1] > a[2] ? 1 : 2);
        const int kx = (kz + 1) % 3;
        const int ky = (kx + 1) % 3;
        ASSERT_EQ(space.dropped_axis(), kz);
        const double shear_x = d[kx] / d[kz];
        const double shear_y = d[ky] / d[kz];
        const double sign = d[kz] < 0.0 ? -1.0 : 1.0;
        Vec3 scaled;
        scaled[kx] = shear_x * sign;
        scaled[ky] = shear_y * sign;
        scaled[kz] = sign;
        EXPECT_EQ(space.direction_length(), std::fabs(d[kz]) * length(scaled));
        EXPECT_EQ(space.grazing_limit(), 1e-6 * (std::fabs(d[kz]) * length(scaled)));
        const Vec3 corner{any(random), any(random), any(random)};
        const Vec3 c = corner - ray.origin;
        const double along_x = shear_x * c[kz];
        const double along_y = shear_y * c[kz];
        double x = 0.0;
        double y = 0.0;
        space.project(corner, x, y);
        EXPECT_EQ(x, c[kx] - along_x);
        EXPECT_EQ(y, c[ky] - along_y);
    }
}

}  // namespace
}  // namespace rt
