// Watertightness on closed meshes of shared vertices: every line meets a closed convex mesh an
// even number of times (0 or 2), exactly twice (once entering, once leaving) when it passes
// through the inside, whatever it grazes on the way: shared edges, shared corners, the planes of
// faces. Open fans around a shared corner are hit exactly once by a line through that corner.
// The rays are random and adversarial: exactly through corners (dyadic inputs, so the projection
// is exact), along edges, axis-parallel, nearly parallel to faces, in the planes of faces.
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "rt/geometry/ray_polygon.h"

#include <gtest/gtest.h>

#include "support/scene_builder.h"

namespace rt {
namespace {

constexpr Interval kWholeLine{-1e300, 1e300};

struct LineHits {
    int count = 0;
    int signed_winding = 0;  // entering and leaving cancel on a consistently oriented mesh
    std::vector<std::uint32_t> polygons;
    std::vector<double> depths;
};

LineHits hits_along(const Scene& scene, const Ray& ray) {
    const RaySpace space(ray);
    LineHits result;
    for (std::uint32_t id = 0; id < scene.polygons.size(); ++id) {
        const std::optional<double> t = intersect_polygon(space, scene, id, kWholeLine);
        const int winding = winding_number(space, scene, id);
        EXPECT_EQ(t.has_value(), winding != 0) << "hit and winding disagree on polygon " << id;
        if (t) {
            ++result.count;
            result.signed_winding += winding;
            result.polygons.push_back(id);
            result.depths.push_back(*t);
        }
    }
    return result;
}

std::string describe(const Ray& ray) {
    char text[200];
    std::snprintf(text, sizeof text, "ray from (%.17g, %.17g, %.17g) along (%.17g, %.17g, %.17g)",
                  ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y,
                  ray.direction.z);
    return text;
}

// A line meets a closed convex mesh 0 or 2 times; two hits are one entering and one leaving.
void expect_even_crossing(const Scene& scene, const Ray& ray) {
    const LineHits h = hits_along(scene, ray);
    ASSERT_TRUE(h.count == 0 || h.count == 2) << h.count << " hits, " << describe(ray);
    EXPECT_EQ(h.signed_winding, 0) << describe(ray);
    // Two hits at one depth (the line clipping an edge or corner, each face's plane giving its
    // own rounding of that depth) have no order to check.
    if (h.count == 2 &&
        std::fabs(h.depths[0] - h.depths[1]) > 1e-9 * (1.0 + std::fabs(h.depths[0]))) {
        const bool first_is_nearer = h.depths[0] <= h.depths[1];
        const Vec3& near_normal = scene.polygons[h.polygons[first_is_nearer ? 0 : 1]].normal;
        const Vec3& far_normal = scene.polygons[h.polygons[first_is_nearer ? 1 : 0]].normal;
        const double grazing = 1e-6 * length(ray.direction);
        const double entering = dot(near_normal, ray.direction);
        const double leaving = dot(far_normal, ray.direction);
        if (std::fabs(entering) > grazing && std::fabs(leaving) > grazing) {
            EXPECT_LT(entering, 0.0) << describe(ray);
            EXPECT_GT(leaving, 0.0) << describe(ray);
        }
    }
}

// A line through the inside of a closed convex mesh meets it exactly twice.
void expect_two_crossings(const Scene& scene, const Ray& ray) {
    EXPECT_EQ(hits_along(scene, ray).count, 2) << describe(ray);
    expect_even_crossing(scene, ray);
}

// The meshes must have consistently oriented loops, or the signed winding means nothing.
void expect_consistent_loops(const Scene& scene) {
    for (const Polygon& p : scene.polygons) {
        std::vector<Vec3> loop;
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            loop.push_back(scene.corner_position(p, k));
        }
        ASSERT_GT(dot(test::newell_normal(loop), p.normal), 0.0);
    }
}

Vec3 random_unit(std::mt19937_64& random) {
    std::normal_distribution<double> gauss;
    const Vec3 v{gauss(random), gauss(random), gauss(random)};
    return normalize(v);
}

// Ray through `through` along `direction`, starting 8 directions back: when every input is a
// small dyadic number, origin, corner - origin and the shear are exact, so the ray's line passes
// exactly through `through`.
Ray ray_through(const Vec3& through, const Vec3& direction) {
    return {through - direction * 8.0, direction};
}

// Directions whose components are small dyadic numbers (exact shears), in every octant, including
// axis-parallel and face-diagonal ones.
std::vector<Vec3> dyadic_directions() {
    constexpr double kParts[] = {-1.0, -0.5, -0.25, 0.0, 0.25, 0.5, 1.0};
    std::vector<Vec3> out;
    out.reserve(std::size(kParts) * std::size(kParts) * std::size(kParts));
    for (const double a : kParts) {
        for (const double b : kParts) {
            for (const double c : kParts) {
                if (a != 0.0 || b != 0.0 || c != 0.0) {
                    out.push_back({a, b, c});
                }
            }
        }
    }
    return out;
}

std::vector<Vec3> box_corners(const Vec3& lo, const Vec3& hi) {
    std::vector<Vec3> out;
    out.reserve(8);
    for (int i = 0; i < 8; ++i) {
        out.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
    }
    return out;
}

class ClosedBox : public ::testing::TestWithParam<bool> {
protected:
    const Vec3 lo_{-1, -2, -0.5};
    const Vec3 hi_{3, 1, 2.5};
    Scene box_ = test::make_box(lo_, hi_, GetParam());
    Vec3 centre() const { return (lo_ + hi_) * 0.5; }
};

TEST_P(ClosedBox, LoopsAreConsistent) {
    expect_consistent_loops(box_);
}

TEST_P(ClosedBox, RandomLinesThroughTheInside) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 3000; ++i) {
        const Vec3 inside{lo_.x + (hi_.x - lo_.x) * unit(random),
                          lo_.y + (hi_.y - lo_.y) * unit(random),
                          lo_.z + (hi_.z - lo_.z) * unit(random)};
        const Vec3 direction = random_unit(random);
        expect_two_crossings(box_, {inside - direction * 20.0, direction});
    }
}

TEST_P(ClosedBox, RandomLinesAnywhere) {
    std::mt19937_64 random(12);
    std::uniform_real_distribution<double> coordinate(-4.0, 4.0);
    for (int i = 0; i < 3000; ++i) {
        const Vec3 origin{coordinate(random), coordinate(random), coordinate(random)};
        expect_even_crossing(box_, {origin, random_unit(random)});
    }
}

TEST_P(ClosedBox, LinesExactlyThroughEveryCorner) {
    for (const Vec3& corner : box_corners(lo_, hi_)) {
        for (const Vec3& direction : dyadic_directions()) {
            const Ray ray = ray_through(corner, direction);
            expect_even_crossing(box_, ray);
            // Pointing strictly into the box (every component toward the centre): the inside.
            const Vec3 inward = centre() - corner;
            if (direction.x * inward.x > 0 && direction.y * inward.y > 0 &&
                direction.z * inward.z > 0) {
                expect_two_crossings(box_, ray);
            }
        }
    }
}

TEST_P(ClosedBox, LinesExactlyThroughEdgeMiddlesAndFaceCentres) {
    const std::vector<Vec3> corners = box_corners(lo_, hi_);
    std::vector<Vec3> points;
    for (std::size_t a = 0; a < corners.size(); ++a) {
        for (std::size_t b = a + 1; b < corners.size(); ++b) {
            points.push_back((corners[a] + corners[b]) * 0.5);  // edges, face diagonals, centre
        }
    }
    for (const Vec3& p : points) {
        for (const Vec3& direction : dyadic_directions()) {
            const Ray ray = ray_through(p, direction);
            expect_even_crossing(box_, ray);
            if ((p - centre()) == Vec3{}) {
                expect_two_crossings(box_, ray);
            }
        }
    }
}

TEST_P(ClosedBox, LinesAlongEdgesAndInFacePlanes) {
    // Axis-parallel lines on the grid of the box's own coordinates: along its 12 edges, in the
    // planes of its faces, through the middles of faces.
    const double xs[] = {lo_.x, 1.0, hi_.x};
    const double ys[] = {lo_.y, -0.5, hi_.y};
    const double zs[] = {lo_.z, 1.0, hi_.z};
    for (const double x : xs) {
        for (const double y : ys) {
            expect_even_crossing(box_, {{x, y, -10}, {0, 0, 1}});
            expect_even_crossing(box_, {{x, y, 10}, {0, 0, -1}});
        }
        for (const double z : zs) {
            expect_even_crossing(box_, {{x, -10, z}, {0, 1, 0}});
        }
    }
    for (const double y : ys) {
        for (const double z : zs) {
            expect_even_crossing(box_, {{-10, y, z}, {1, 0, 0}});
        }
    }
    expect_two_crossings(box_, {{1.0, -0.5, -10}, {0, 0, 1}});
}

TEST_P(ClosedBox, NearlyParallelToFaces) {
    std::mt19937_64 random(13);
    std::uniform_real_distribution<double> tilt(-1e-12, 1e-12);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        // Through a point of a face plane (z = lo.z), almost along it.
        const Vec3 on_face{lo_.x + (hi_.x - lo_.x) * unit(random),
                           lo_.y + (hi_.y - lo_.y) * unit(random), lo_.z};
        const Vec3 direction{1.0, tilt(random), tilt(random)};
        expect_even_crossing(box_, {on_face - direction * 10.0, direction});
        // Just inside: must get through.
        const Vec3 inside = on_face + Vec3{0, 0, 1e-3};
        expect_two_crossings(box_, {inside - direction * 10.0, direction});
    }
}

INSTANTIATE_TEST_SUITE_P(QuadsAndTriangles, ClosedBox, ::testing::Bool(),
                         [](const ::testing::TestParamInfo<bool>& param) {
                             return param.param ? "Triangles" : "Quads";
                         });

struct SphereMesh {
    int stacks;
    int slices;
    bool triangles;
};

class ClosedSphere : public ::testing::TestWithParam<SphereMesh> {
protected:
    const Vec3 centre_{0.1, -0.2, 0.3};  // not dyadic: projections round
    const double radius_ = 1.7;
    Scene sphere_ = test::make_sphere(centre_, radius_, GetParam().stacks, GetParam().slices,
                                      GetParam().triangles);
};

TEST_P(ClosedSphere, LoopsAreConsistent) {
    expect_consistent_loops(sphere_);
}

TEST_P(ClosedSphere, RandomLinesThroughTheMiddle) {
    std::mt19937_64 random(21);
    // Within 0.35 radius of the centre: inside even the coarsest mesh, the 2x3 bipyramid.
    std::uniform_real_distribution<double> offset(-0.2, 0.2);
    for (int i = 0; i < 1500; ++i) {
        const Vec3 inside =
            centre_ + Vec3{offset(random), offset(random), offset(random)} * radius_;
        const Vec3 direction = random_unit(random);
        expect_two_crossings(sphere_, {inside - direction * 5.0, direction});
    }
}

TEST_P(ClosedSphere, LinesThroughEveryCornerAndEdgeMiddle) {
    std::mt19937_64 random(22);
    for (const Polygon& p : sphere_.polygons) {
        for (std::uint32_t k = 0; k < p.corner_count; ++k) {
            const Vec3 a = sphere_.corner_position(p, k);
            const Vec3 b = sphere_.corner_position(p, (k + 1) % p.corner_count);
            for (const Vec3& through : {a, (a + b) * 0.5}) {
                // Toward the centre: through the inside.
                expect_two_crossings(sphere_, {through + (through - centre_), centre_ - through});
                // Any direction at all: grazing, tangent, along edges.
                expect_even_crossing(sphere_, {through, random_unit(random)});
            }
            expect_even_crossing(sphere_, {a, b - a});  // along the edge itself
        }
    }
}

TEST_P(ClosedSphere, AxisParallelLinesThroughThePoles) {
    // The poles are corners shared by a whole ring of triangles.
    const Vec3 north = centre_ + Vec3{0, radius_, 0};
    expect_two_crossings(sphere_, {north + Vec3{0, 3, 0}, {0, -1, 0}});
    std::mt19937_64 random(23);
    std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
    for (int i = 0; i < 1500; ++i) {
        const Vec3 origin =
            centre_ + Vec3{coordinate(random), coordinate(random), coordinate(random)};
        for (const Vec3& axis : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}) {
            expect_even_crossing(sphere_, {origin, axis});
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Meshes, ClosedSphere,
                         ::testing::Values(SphereMesh{2, 3, false}, SphereMesh{8, 12, false},
                                           SphereMesh{8, 12, true}, SphereMesh{16, 24, true}),
                         [](const ::testing::TestParamInfo<SphereMesh>& param) {
                             return std::to_string(param.param.stacks) + "x" +
                                    std::to_string(param.param.slices) +
                                    (param.param.triangles ? "Triangles" : "Quads");
                         });

// A flat fan: any line through its middle corner (not in its plane) hits exactly one triangle.
TEST(Fan, ExactlyOneHitThroughTheSharedCorner) {
    for (const int count : {3, 7, 16, 64}) {
        const Scene fan = test::make_fan(count, 2.0);
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
        const Scene fan = test::make_fan(count, 2.0);
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
        test::SceneBuilder builder;
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
        test::SceneBuilder builder;
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
}  // namespace rt
