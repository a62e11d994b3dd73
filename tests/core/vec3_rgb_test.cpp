// Vector and colour arithmetic against values worked out by hand.
#include <cmath>
#include <limits>

#include "rt/core/rgb.h"
#include "rt/core/vec3.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(Vec3, ArithmeticIsComponentWise) {
    const Vec3 a{1, 2, 3};
    const Vec3 b{-4, 0.5, 2};
    EXPECT_EQ(a + b, (Vec3{-3, 2.5, 5}));
    EXPECT_EQ(a - b, (Vec3{5, 1.5, 1}));
    EXPECT_EQ(-a, (Vec3{-1, -2, -3}));
    EXPECT_EQ(a * 2.0, (Vec3{2, 4, 6}));
    EXPECT_EQ(2.0 * a, a * 2.0);
    EXPECT_EQ(a / 4.0, (Vec3{0.25, 0.5, 0.75}));
    Vec3 c = a;
    c += b;
    c -= a;
    EXPECT_EQ(c, b);
}

TEST(Vec3, IndexingReadsAndWritesTheAxes) {
    Vec3 v{7, 8, 9};
    EXPECT_EQ(v[0], 7);
    EXPECT_EQ(v[1], 8);
    EXPECT_EQ(v[2], 9);
    v[1] = -1;
    EXPECT_EQ(v.y, -1);
}

TEST(Vec3, DotCrossAndLength) {
    const Vec3 x{1, 0, 0};
    const Vec3 y{0, 1, 0};
    EXPECT_EQ(cross(x, y), (Vec3{0, 0, 1}));  // right-handed
    EXPECT_EQ(cross(y, x), (Vec3{0, 0, -1}));
    EXPECT_EQ(dot(Vec3{1, 2, 3}, Vec3{4, -5, 6}), 12.0);
    const Vec3 a{1, 2, 3};
    const Vec3 b{-2, 0.5, 4};
    EXPECT_EQ(dot(cross(a, b), a), 0.0);
    EXPECT_EQ(dot(cross(a, b), b), 0.0);
    EXPECT_EQ(length(Vec3{3, 4, 12}), 13.0);
    const Vec3 n = normalize(Vec3{3, 4, 12});
    EXPECT_NEAR(length(n), 1.0, 1e-15);
    EXPECT_NEAR(n.z, 12.0 / 13.0, 1e-15);
}

TEST(Vec3, FinitenessAndComponentExtremes) {
    EXPECT_TRUE(is_finite(Vec3{1e308, -1e308, 0}));
    EXPECT_FALSE(is_finite(Vec3{0, std::numeric_limits<double>::infinity(), 0}));
    EXPECT_FALSE(is_finite(Vec3{0, 0, std::nan("")}));
    EXPECT_EQ(min_components(Vec3{1, 5, -2}, Vec3{3, -1, -2}), (Vec3{1, -1, -2}));
    EXPECT_EQ(max_components(Vec3{1, 5, -2}, Vec3{3, -1, -2}), (Vec3{3, 5, -2}));
}

TEST(Rgb, SumsScalesFiltersAndIndexes) {
    const Rgb light{1.0, 0.5, 0.25};
    const Rgb surface{0.5, 0.5, 2.0};
    EXPECT_EQ(light + surface, (Rgb{1.5, 1.0, 2.25}));
    EXPECT_EQ(light * 2.0, (Rgb{2.0, 1.0, 0.5}));
    EXPECT_EQ(2.0 * light, light * 2.0);
    EXPECT_EQ(light * surface, (Rgb{0.5, 0.25, 0.5}));
    Rgb c = light;
    c[2] = 3.0;
    EXPECT_EQ(c[0], 1.0);
    EXPECT_EQ(c[1], 0.5);
    EXPECT_EQ(c.b, 3.0);
    EXPECT_EQ(max_component(Rgb{0.1, 0.7, 0.3}), 0.7);
    EXPECT_EQ(max_component(Rgb{0.9, 0.7, 0.3}), 0.9);
    EXPECT_EQ(max_component(Rgb{0.1, 0.2, 0.3}), 0.3);
}

}  // namespace
}  // namespace rt
