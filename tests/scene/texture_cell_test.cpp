// The normal a texture cell's cylindrical element gives (-V): against the normals of a sphere and
// a cylinder worked out here from their radii, exactly, not paraxially.
#include "rt/scene/texture_cell.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace rt {
namespace {

// A cell in the plane z = 0, outward +z, u along +x and v along +y, centred on the origin.
TextureCell cell(double sphere, double cylinder, double axis_degrees) {
    TextureCell c;
    c.tangent_u = {1, 0, 0};
    c.tangent_v = {0, 1, 0};
    const double a = axis_degrees * std::numbers::pi / 180.0;
    c.across_axis = {-std::sin(a), std::cos(a), 0};
    c.sphere = sphere;
    c.cylinder = cylinder;
    return c;
}

constexpr Vec3 kUp{0, 0, 1};

void expect_near(const Vec3& got, const Vec3& want, double tolerance = 1e-12) {
    EXPECT_NEAR(got.x, want.x, tolerance);
    EXPECT_NEAR(got.y, want.y, tolerance);
    EXPECT_NEAR(got.z, want.z, tolerance);
}

TEST(TextureCell, AFlatElementGivesTheGeometricNormalBitForBit) {
    const Vec3 tilted = normalize(Vec3{0.1, 0.2, 0.97});
    EXPECT_EQ(element_normal(cell(0, 0, 30), tilted, {0.4, -0.3, 0}), tilted);
}

TEST(TextureCell, ASphereTurnsTheNormalAsTheSphereOfThatRadius) {
    // Radius 4, centre 4 below the plane's optical centre: at (x, y, 0) the sphere's own surface
    // point straight above has the normal (x, y, sqrt(16 - x^2 - y^2)) / 4.
    for (const Vec3 p : {Vec3{1, 0, 0}, Vec3{-1.5, 2, 0}, Vec3{0, 3.9, 0}, Vec3{0, 0, 0}}) {
        const double r2 = p.x * p.x + p.y * p.y;
        expect_near(element_normal(cell(0.25, 0, 0), kUp, p),
                    Vec3{p.x, p.y, std::sqrt(16 - r2)} / 4.0);
    }
    // Concave (negative curvature): the normal turns toward the centre.
    expect_near(element_normal(cell(-0.25, 0, 0), kUp, {2, 0, 0}),
                Vec3{-2, 0, std::sqrt(12.0)} / 4.0);
}

TEST(TextureCell, TheOpticalCentreAndTheCurvatureSetTheTilt) {
    TextureCell c = cell(0.5, 0, 0);  // radius 2
    c.optical_centre = {3, 1, 0};
    // One away from the centre along v: tilted asin(1/2) = 30 degrees toward +v.
    const Vec3 n = element_normal(c, kUp, {3, 2, 0});
    EXPECT_NEAR(std::asin(n.y), std::numbers::pi / 6, 1e-12);
    EXPECT_NEAR(n.x, 0.0, 1e-15);
}

TEST(TextureCell, ACylinderTurnsTheNormalAcrossItsAxisOnly) {
    // Axis at 30 degrees from u: moving along the axis changes nothing; across it, the normal is
    // the cylinder's of radius 5.
    const double a = std::numbers::pi / 6;
    const Vec3 along{std::cos(a), std::sin(a), 0};
    const Vec3 across{-std::sin(a), std::cos(a), 0};
    const TextureCell c = cell(0, 0.2, 30);
    for (const double t : {-3.0, 0.0, 2.0}) {
        for (const double s : {-4.0, 0.5, 3.0}) {
            expect_near(element_normal(c, kUp, along * t + across * s),
                        (across * s + kUp * std::sqrt(25 - s * s)) / 5.0);
        }
    }
}

TEST(TextureCell, SphereAndCylinderAddTheirSlopes) {
    // The height of the sum is the sum of the heights: the normal is (-grad h, 1), normalised.
    const TextureCell c = cell(0.1, 0.2, 90);  // axis along v: the cylinder bends across x
    const Vec3 p{1.5, -2, 0};
    const double r = std::hypot(p.x, p.y);
    const double sphere_slope = 0.1 / std::sqrt(1 - 0.01 * r * r);  // tan(tilt) / r
    const double cylinder_slope = 0.2 / std::sqrt(1 - 0.04 * p.x * p.x);
    const Vec3 want{p.x * (sphere_slope + cylinder_slope), p.y * sphere_slope, 1};
    expect_near(element_normal(c, kUp, p), normalize(want));
}

TEST(TextureCell, BeyondTheRadiusTheSlopeStaysAtItsSteepest) {
    const TextureCell c = cell(0.5, 0, 0);  // radius 2
    const double steepest = std::asin(kMaxElementTiltSine);
    for (const double x : {1.98, 2.0, 3.0, 100.0}) {
        const Vec3 n = element_normal(c, kUp, {x, 0, 0});
        EXPECT_NEAR(std::atan2(n.x, n.z), steepest, 1e-12) << x;
    }
    const Vec3 inside = element_normal(c, kUp, {1.9, 0, 0});
    EXPECT_NEAR(std::atan2(inside.x, inside.z), std::asin(0.95), 1e-12);
    EXPECT_TRUE(std::isfinite(element_slope(0.5, 2.0)));
    EXPECT_LT(element_slope(-0.5, 5.0), 0.0);
}

}  // namespace
}  // namespace rt
