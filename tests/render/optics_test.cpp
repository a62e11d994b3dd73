#include "rt/shading/optics.h"

#include <cmath>

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(Optics, MirrorReflectionKeepsTheAngle) {
    const Vec3 d = normalize(Vec3{1, -1, 0});
    const Vec3 r = reflect(d, {0, 1, 0});
    EXPECT_NEAR(r.x, d.x, 1e-15);
    EXPECT_NEAR(r.y, -d.y, 1e-15);
}

TEST(Optics, SnellsLawHolds) {
    const double incidence = 0.6;  // radians
    const Vec3 d{std::sin(incidence), -std::cos(incidence), 0};
    const std::optional<Vec3> t = refract(d, {0, 1, 0}, 1.0, 1.5);
    ASSERT_TRUE(t);
    const double sin_t = t->x / length(*t);
    EXPECT_NEAR(std::sin(incidence), 1.5 * sin_t, 1e-12);
    EXPECT_LT(t->y, 0.0);
}

TEST(Optics, TotalInternalReflectionGivesNothing) {
    const double incidence = 0.8;  // beyond asin(1/1.5) = 0.7297
    const Vec3 d{std::sin(incidence), -std::cos(incidence), 0};
    EXPECT_FALSE(refract(d, {0, 1, 0}, 1.5, 1.0));
    EXPECT_TRUE(refract(d, {0, 1, 0}, 1.5, 1.4));
}

}  // namespace
}  // namespace rt
