// Warn lights (-Wr -Wc -Wt) at angles worked out by hand.
#include "rt/shading/warn_light.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace rt {
namespace {

constexpr double kPi = std::numbers::pi;

// An emitter facing down (-y), as a ceiling light does, with pow 4.
WarnEmitter ceiling(bool both_sides = true) {
    return {{0.0, -1.0, 0.0}, 4.0, both_sides};
}

// Unit direction from the light, x radians away from straight down, in the x-y plane.
Vec3 down_at(double x) {
    return {std::sin(x), -std::cos(x), 0.0};
}

TEST(WarnLight, NoneLeavesTheLightAlone) {
    EXPECT_EQ(warn_factor({}, ceiling(), down_at(1.2)), 1.0);
    EXPECT_EQ(warn_factor({}, ceiling(false), down_at(2.5)), 1.0);
}

TEST(WarnLight, RogersIsCosToTheEmittersPow) {
    const WarnSettings rogers{WarnMode::Rogers, 0.0, 0.0};
    EXPECT_DOUBLE_EQ(warn_factor(rogers, ceiling(), down_at(0.0)), 1.0);
    EXPECT_NEAR(warn_factor(rogers, ceiling(), down_at(kPi / 3.0)), 1.0 / 16.0, 1e-15);  // 0.5^4
    EXPECT_NEAR(warn_factor(rogers, ceiling(), down_at(kPi / 4.0)), 0.25, 1e-15);
    EXPECT_NEAR(warn_factor(rogers, ceiling(), down_at(kPi / 2.0)), 0.0, 1e-15);
}

TEST(WarnLight, RogersOnTheBackSide) {
    const WarnSettings rogers{WarnMode::Rogers, 0.0, 0.0};
    // 60 degrees from the upward (back) normal: cos 120 degrees with the front normal.
    const Vec3 up_60 = down_at(kPi - kPi / 3.0);
    EXPECT_NEAR(warn_factor(rogers, ceiling(true), up_60), 1.0 / 16.0, 1e-15);
    EXPECT_EQ(warn_factor(rogers, ceiling(false), up_60), 0.0);  // -Db: the back is dark
}

TEST(WarnLight, ConicalCutsOffBeyondTheAngle) {
    const WarnSettings conical{WarnMode::Conical, 0.7, 0.0};
    EXPECT_NEAR(warn_factor(conical, ceiling(), down_at(0.69)), std::pow(std::cos(0.69), 4.0),
                1e-15);
    EXPECT_EQ(warn_factor(conical, ceiling(), down_at(0.71)), 0.0);
    EXPECT_NEAR(warn_factor(conical, ceiling(), down_at(kPi - 0.69)), std::pow(std::cos(0.69), 4.0),
                1e-15);  // back side, both sides emit
    EXPECT_EQ(warn_factor(conical, ceiling(false), down_at(kPi - 0.69)), 0.0);
}

TEST(WarnLight, ThibadeauDisplacesTheSourceBehindThePolygon) {
    const WarnSettings thibadeau{WarnMode::Thibadeau, 0.0, 1.5};
    const Vec3 light{1.0, 10.0, 2.0};
    const Vec3 below{3.0, 0.0, 2.0};
    const Vec3 above{3.0, 20.0, 2.0};
    // The normal points down: displaced along +y, away from a point below.
    EXPECT_EQ(warn_feeler_target(thibadeau, ceiling(), light, below), (Vec3{1.0, 11.5, 2.0}));
    EXPECT_EQ(warn_feeler_target(thibadeau, ceiling(false), light, below), (Vec3{1.0, 11.5, 2.0}));
    // A point above a two-sided emitter gets the source displaced downward, behind it.
    EXPECT_EQ(warn_feeler_target(thibadeau, ceiling(true), light, above), (Vec3{1.0, 8.5, 2.0}));
    // With -Db only the front emits: always along the negative normal (the point above gets 0).
    EXPECT_EQ(warn_feeler_target(thibadeau, ceiling(false), light, above), (Vec3{1.0, 11.5, 2.0}));
    // Other modes aim at the light itself.
    EXPECT_EQ(warn_feeler_target({WarnMode::Rogers, 0.0, 1.5}, ceiling(), light, below), light);
}

TEST(WarnLight, ThibadeauIsRogersWhenTheFeelerCrossesThePolygon) {
    const WarnSettings thibadeau{WarnMode::Thibadeau, 0.0, 1.0};
    EXPECT_NEAR(warn_factor(thibadeau, ceiling(), down_at(kPi / 3.0), true), 1.0 / 16.0, 1e-15);
    EXPECT_EQ(warn_factor(thibadeau, ceiling(), down_at(kPi / 3.0), false), 0.0);
    EXPECT_NEAR(thibadeau_factor(ceiling(), down_at(kPi / 4.0), true), 0.25, 1e-15);
    EXPECT_EQ(thibadeau_factor(ceiling(), down_at(0.0), false), 0.0);
}

}  // namespace
}  // namespace rt
