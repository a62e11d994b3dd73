// Boxes and pixel rectangles against values worked out by hand.
#include "rt/core/bounds.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(Box3, StartsEmptyAndBoundsWhatIsAdded) {
    Box3 box;
    EXPECT_TRUE(box.empty());
    EXPECT_FALSE(box.contains({0, 0, 0}));
    box.add(Vec3{1, -2, 3});
    EXPECT_FALSE(box.empty());
    EXPECT_EQ(box, Box3::around({1, -2, 3}));
    box.add(Vec3{-1, 4, 3});
    EXPECT_EQ(box.lo, (Vec3{-1, -2, 3}));
    EXPECT_EQ(box.hi, (Vec3{1, 4, 3}));
    EXPECT_EQ(box.extent(), (Vec3{2, 6, 0}));
    EXPECT_EQ(box.largest_extent(), 6.0);
    box.add(Box3{{0, 0, -5}, {0, 0, 0}});
    EXPECT_EQ(box.lo, (Vec3{-1, -2, -5}));
    EXPECT_EQ(box.hi, (Vec3{1, 4, 3}));
    Box3 unchanged = box;
    unchanged.add(Box3{});  // an empty box adds nothing
    EXPECT_EQ(unchanged, box);
}

TEST(Box3, ContainsItsClosedFaces) {
    const Box3 box{{0, 0, 0}, {1, 2, 3}};
    EXPECT_TRUE(box.contains({0, 0, 0}));
    EXPECT_TRUE(box.contains({1, 2, 3}));
    EXPECT_TRUE(box.contains({0.5, 2, 1}));
    EXPECT_FALSE(box.contains({1.0000001, 1, 1}));
    EXPECT_FALSE(box.contains({0.5, 1, -1e-300}));
}

TEST(Box3, GrowsOnEverySide) {
    const Box3 box{{0, 0, 0}, {1, 2, 3}};
    EXPECT_EQ(box.grown(0.5), (Box3{{-0.5, -0.5, -0.5}, {1.5, 2.5, 3.5}}));
    EXPECT_EQ(box.grown(Vec3{1, 0, 2}), (Box3{{-1, 0, -2}, {2, 2, 5}}));
}

TEST(Box3, CornersMagnitudeAndDistance) {
    const Box3 box{{-4, 0, 1}, {2, 3, 5}};
    EXPECT_EQ(box.corner(0), box.lo);
    EXPECT_EQ(box.corner(7), box.hi);
    EXPECT_EQ(box.corner(1), (Vec3{2, 0, 1}));
    EXPECT_EQ(box.corner(6), (Vec3{-4, 3, 5}));
    EXPECT_EQ(box.magnitude(), 5.0);
    EXPECT_EQ(box.centre(), (Vec3{-1, 1.5, 3}));
    EXPECT_EQ(distance_to(box, {0, 1, 2}), 0.0);
    EXPECT_EQ(distance_to(box, {5, 7, 5}), 5.0);  // 3 and 4 beyond hi.x and hi.y
    EXPECT_EQ(distance_to(box, {-4, 0, -1}), 2.0);
}

TEST(Box3, IntersectionIsTheCommonPart) {
    const Box3 a{{0, 0, 0}, {2, 2, 2}};
    const Box3 b{{1, -1, 1}, {3, 1, 4}};
    EXPECT_EQ(intersection(a, b), (Box3{{1, 0, 1}, {2, 1, 2}}));
    EXPECT_TRUE(intersection(a, Box3{{3, 0, 0}, {4, 1, 1}}).empty());
}

TEST(PixelRect, IsInclusive) {
    const PixelRect r{2, 1, 4, 3};
    EXPECT_EQ(r.width(), 3);
    EXPECT_EQ(r.height(), 3);
    EXPECT_EQ((PixelRect{0, 0, 0, 0}).width(), 1);
    EXPECT_EQ((PixelRect{5, 0, 4, 0}).width(), 0);
    EXPECT_NE(r, (PixelRect{2, 1, 4, 4}));
}

}  // namespace
}  // namespace rt
