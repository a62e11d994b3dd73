#include "rt/image/compare.h"

#include "rt/core/error.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(CompareImages, IdenticalImagesDifferByNothing) {
    const Image8 a{2, 1, {1, 2, 3, 4, 5, 6}};
    const ImageDifference d = compare_images(a, a, 0);
    EXPECT_EQ(d.max_channel_difference, 0);
    EXPECT_EQ(d.mean_absolute_difference, 0.0);
    EXPECT_EQ(d.fraction_over_threshold, 0.0);
}

TEST(CompareImages, ReportsMaxMeanAndFractionOverThreshold) {
    const Image8 a{2, 2, {10, 10, 10, 0, 0, 0, 100, 100, 100, 50, 50, 50}};
    const Image8 b{2, 2, {10, 10, 12, 0, 0, 0, 100, 90, 100, 50, 50, 50}};
    const ImageDifference d = compare_images(a, b, 2);
    EXPECT_EQ(d.max_channel_difference, 10);
    EXPECT_DOUBLE_EQ(d.mean_absolute_difference, 12.0 / 12.0);
    EXPECT_DOUBLE_EQ(d.fraction_over_threshold, 0.25);  // only the pixel off by 10
    EXPECT_DOUBLE_EQ(compare_images(a, b, 1).fraction_over_threshold, 0.5);
}

TEST(CompareImages, DifferentSizesAreAnError) {
    EXPECT_THROW(compare_images(Image8{1, 1, {0, 0, 0}}, Image8{1, 2, {0, 0, 0, 0, 0, 0}}, 0),
                 Error);
}

}  // namespace
}  // namespace rt
