#include "rt/geometry/camera.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace rt {
namespace {

CameraPlacement looking_along_z() {
    CameraPlacement v;
    v.eye = {0, 0, -10};
    v.look = {0, 0, 0};
    v.screen_distance = 2.0;
    v.view_angle_x_degrees = 90.0;
    v.view_angle_y_degrees = 60.0;
    v.width = 200;
    v.height = 100;
    return v;
}

double degrees_between(const Vec3& a, const Vec3& b) {
    return std::acos(dot(normalize(a), normalize(b))) * 180.0 / std::numbers::pi;
}

TEST(Camera, CentreRayLooksAtTheLookPoint) {
    const Camera c = Camera::placed(looking_along_z());
    const Ray r = c.primary_ray(100.0, 50.0);
    EXPECT_NEAR(r.direction.x, 0.0, 1e-12);
    EXPECT_NEAR(r.direction.y, 0.0, 1e-12);
    EXPECT_NEAR(r.direction.z, 1.0, 1e-12);
}

TEST(Camera, RaysStartOnTheScreen) {
    const Camera c = Camera::placed(looking_along_z());
    const Ray r = c.primary_ray(100.0, 50.0);
    EXPECT_NEAR(r.origin.z, -8.0, 1e-12);
    EXPECT_NEAR(length(r.direction), 1.0, 1e-12);
}

TEST(Camera, PlusXIsRightAndPlusYIsUpWhenLookingAlongZ) {
    const Camera c = Camera::placed(looking_along_z());
    EXPECT_GT(c.primary_ray(199.0, 50.0).direction.x, 0.0);  // right edge looks toward +x
    EXPECT_LT(c.primary_ray(1.0, 50.0).direction.x, 0.0);
    EXPECT_GT(c.primary_ray(100.0, 1.0).direction.y, 0.0);  // top row looks toward +y
    EXPECT_LT(c.primary_ray(100.0, 99.0).direction.y, 0.0);
}

TEST(Camera, ViewAnglesAreTheFullAnglesSubtended) {
    const Camera c = Camera::placed(looking_along_z());
    const Vec3 forward{0, 0, 1};
    EXPECT_NEAR(degrees_between(c.primary_ray(0.0, 50.0).direction, forward), 45.0, 1e-9);
    EXPECT_NEAR(degrees_between(c.primary_ray(200.0, 50.0).direction, forward), 45.0, 1e-9);
    EXPECT_NEAR(degrees_between(c.primary_ray(100.0, 0.0).direction, forward), 30.0, 1e-9);
}

TEST(Camera, LookingStraightDownStillHasAnUp) {
    CameraPlacement v = looking_along_z();
    v.eye = {0, 10, 0};
    const Camera c = Camera::placed(v);
    const Ray r = c.primary_ray(100.0, 50.0);
    EXPECT_NEAR(r.direction.y, -1.0, 1e-12);
    EXPECT_TRUE(is_finite(c.right));
    EXPECT_NEAR(length(c.up), 1.0, 1e-12);
}

}  // namespace
}  // namespace rt
