// The normals inferred from the -M shapes: sphere, cylinder and cone (manual 2.4).
#include "rt/scene/shape_normal.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace rt {
namespace {

Shape sphere_at(const Vec3& centre) {
    Shape s;
    s.first = centre;
    s.radius_or_angle = 2.0;
    return s;
}

Shape along_axis(const Vec3& first, const Vec3& second, double radius_or_angle) {
    Shape s;
    s.first = first;
    s.second = second;
    s.radius_or_angle = radius_or_angle;
    return s;
}

void expect_unit_near(const Vec3& actual, const Vec3& expected) {
    EXPECT_NEAR(length(actual), 1.0, 1e-12);
    EXPECT_NEAR(length(actual - normalize(expected)), 0.0, 1e-12)
        << actual.x << " " << actual.y << " " << actual.z;
}

TEST(ShapeNormal, SphereIsRadialAndTurnedOutward) {
    const Shape s = sphere_at({1, 2, 3});
    const Vec3 point{1, 2, 3 + 2.0};
    expect_unit_near(shape_normal(s, PolygonMark::Sphere, point, {0, 0.1, 1}), {0, 0, 1});
    // A polygon facing inward (the inside of a dome) turns the shape normal with it.
    expect_unit_near(shape_normal(s, PolygonMark::Sphere, point, {0, 0.1, -1}), {0, 0, -1});
    const Vec3 oblique = Vec3{1, 2, 3} + normalize(Vec3{1, -1, 2}) * 2.0;
    expect_unit_near(shape_normal(s, PolygonMark::Sphere, oblique, {1, -1, 2}), {1, -1, 2});
}

TEST(ShapeNormal, CylinderIsPerpendicularToTheAxis) {
    const Shape s = along_axis({0, 0, 0}, {0, 0, 5}, 1.0);
    expect_unit_near(shape_normal(s, PolygonMark::Cylinder, {1, 0, 3.7}, {1, 0, 0.2}), {1, 0, 0});
    // A tilted axis: the normal is the radial part only.
    const Shape tilted = along_axis({1, 1, 1}, {2, 2, 2}, 1.0);
    const Vec3 point = Vec3{1.5, 1.5, 1.5} + normalize(Vec3{1, -1, 0}) * 1.0;
    const Vec3 n = shape_normal(tilted, PolygonMark::Cylinder, point, {1, -1, 0.3});
    expect_unit_near(n, {1, -1, 0});
    EXPECT_NEAR(dot(n, Vec3{1, 1, 1}), 0.0, 1e-12);
}

TEST(ShapeNormal, ConeIsPerpendicularToItsSurfaceLine) {
    const double half_angle = 30.0;
    const Shape s = along_axis({0, 0, 0}, {0, 0, 1}, half_angle);
    const double tan_a = std::tan(half_angle * std::numbers::pi / 180.0);
    for (const double height : {2.0, -2.0}) {  // both nappes
        for (const double phi : {0.0, 1.0, 2.5}) {
            const Vec3 point{height * tan_a * std::cos(phi), height * tan_a * std::sin(phi),
                             height};
            const Vec3 radial{std::cos(phi), std::sin(phi), 0};
            const Vec3 n = shape_normal(s, PolygonMark::Cone, point, radial);
            EXPECT_NEAR(length(n), 1.0, 1e-12);
            EXPECT_NEAR(dot(n, point), 0.0, 1e-12) << "not perpendicular to the surface line";
            EXPECT_GT(dot(n, radial), 0.0);
            // Its angle with the axis: 90 degrees plus or minus the half-angle.
            EXPECT_NEAR(std::fabs(dot(n, Vec3{0, 0, 1})),
                        std::sin(half_angle * std::numbers::pi / 180.0), 1e-12);
        }
    }
}

TEST(ShapeNormal, PolygonNormalWhereTheShapeGivesNone) {
    const Vec3 polygon_normal{0, 1, 0};
    // On the axis, at the apex, at a sphere's centre, with a zero axis.
    EXPECT_EQ(shape_normal(along_axis({0, 0, 0}, {0, 0, 1}, 1.0), PolygonMark::Cylinder, {0, 0, 3},
                           polygon_normal),
              polygon_normal);
    EXPECT_EQ(shape_normal(along_axis({0, 0, 0}, {0, 0, 1}, 30.0), PolygonMark::Cone, {0, 0, 0},
                           polygon_normal),
              polygon_normal);
    EXPECT_EQ(shape_normal(sphere_at({1, 1, 1}), PolygonMark::Sphere, {1, 1, 1}, polygon_normal),
              polygon_normal);
    EXPECT_EQ(shape_normal(along_axis({1, 1, 1}, {1, 1, 1}, 1.0), PolygonMark::Cylinder, {3, 1, 1},
                           polygon_normal),
              polygon_normal);
    // Ordinary and normal-interpolating polygons keep their own normal.
    EXPECT_EQ(shape_normal(sphere_at({0, 0, 0}), PolygonMark::Ordinary, {2, 0, 0}, polygon_normal),
              polygon_normal);
    EXPECT_EQ(shape_normal(sphere_at({0, 0, 0}), PolygonMark::InterpolatesNormals, {2, 0, 0},
                           polygon_normal),
              polygon_normal);
}

}  // namespace
}  // namespace rt
