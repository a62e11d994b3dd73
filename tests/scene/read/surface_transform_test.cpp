#include "rt/scene/read/surface_transform.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

void expect_near(const Vec3& a, const Vec3& b) {
    EXPECT_NEAR(a.x, b.x, 1e-12);
    EXPECT_NEAR(a.y, b.y, 1e-12);
    EXPECT_NEAR(a.z, b.z, 1e-12);
}

TEST(SurfaceTransform, RightHandRuleAboutEachAxis) {
    EXPECT_EQ(SurfaceTransform(1, {90, 0, 0}, {}).point({0, 1, 0}), (Vec3{0, 0, 1}));
    EXPECT_EQ(SurfaceTransform(1, {0, 90, 0}, {}).point({0, 0, 1}), (Vec3{1, 0, 0}));
    EXPECT_EQ(SurfaceTransform(1, {0, 0, 90}, {}).point({1, 0, 0}), (Vec3{0, 1, 0}));
    EXPECT_EQ(SurfaceTransform(1, {0, 0, -90}, {}).point({1, 0, 0}), (Vec3{0, -1, 0}));
    EXPECT_EQ(SurfaceTransform(1, {0, 0, 450}, {}).point({1, 0, 0}), (Vec3{0, 1, 0}));
}

TEST(SurfaceTransform, ScaleThenXThenYThenZThenTranslate) {
    // (1, 0, 0) scaled by 2 -> (2, 0, 0); about x: unchanged; about y by 90: (0, 0, -2);
    // about z: unchanged; then translated.
    EXPECT_EQ(SurfaceTransform(2, {90, 90, 90}, {10, 20, 30}).point({1, 0, 0}), (Vec3{10, 20, 28}));
    // (0, 1, 0): x by 90 -> (0, 0, 1); y by 90 -> (1, 0, 0); z by 90 -> (0, 1, 0).
    EXPECT_EQ(SurfaceTransform(1, {90, 90, 90}, {}).point({0, 1, 0}), (Vec3{0, 1, 0}));
    // An angle that is not a right angle: 30 degrees about z of (3, 0, 0), scale 0.5.
    expect_near(SurfaceTransform(0.5, {0, 0, 30}, {1, 1, 1}).point({3, 0, 0}),
                {1 + 1.5 * std::sqrt(3.0) / 2, 1 + 0.75, 1});
}

TEST(SurfaceTransform, NormalsRotateAndFlipUnderANegativeScale) {
    EXPECT_EQ(SurfaceTransform(3, {0, 0, 90}, {5, 5, 5}).normal({1, 0, 0}), (Vec3{0, 1, 0}));
    EXPECT_EQ(SurfaceTransform(-3, {0, 0, 90}, {5, 5, 5}).normal({1, 0, 0}), (Vec3{0, -1, 0}));
}

TEST(SinCosDegrees, ExactAtRightAngles) {
    double s = 0;
    double c = 0;
    sin_cos_degrees(-270, s, c);
    EXPECT_EQ(s, 1.0);
    EXPECT_EQ(c, 0.0);
    sin_cos_degrees(180, s, c);
    EXPECT_EQ(s, 0.0);
    EXPECT_EQ(c, -1.0);
    sin_cos_degrees(30, s, c);
    EXPECT_NEAR(s, 0.5, 1e-15);
}

}  // namespace
}  // namespace rt
