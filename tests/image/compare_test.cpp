#include "rt/image/compare.h"

#include <cstdint>
#include <utility>
#include <vector>

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

// A w x h grey picture, with the pixels listed in `blots` turned white.
Image8 picture_with_blots(int w, int h, const std::vector<std::pair<int, int>>& blots) {
    Image8 image{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w * h * 3), 100)};
    for (const auto& [x, y] : blots) {
        for (int c = 0; c < 3; ++c) {
            image.rgb[static_cast<std::size_t>((y * w + x) * 3 + c)] = 255;
        }
    }
    return image;
}

TEST(CompareImages, LargestWrongSquareFindsABlotButNotScatteredPixels) {
    const Image8 clean = picture_with_blots(8, 6, {});
    EXPECT_EQ(compare_images(clean, clean, 2).largest_wrong_square, 0);
    // A checkerboard of wrong pixels and a one-pixel line: no 2 x 2 square among them.
    const Image8 scattered =
        picture_with_blots(8, 6, {{0, 0}, {2, 0}, {1, 1}, {3, 1}, {5, 0}, {5, 1}, {5, 2}, {5, 3}});
    EXPECT_EQ(compare_images(clean, scattered, 2).largest_wrong_square, 1);
    // A 3 x 3 blot touching the right and bottom edges, next to a stray pixel.
    const Image8 blot = picture_with_blots(
        8, 6, {{5, 3}, {6, 3}, {7, 3}, {5, 4}, {6, 4}, {7, 4}, {5, 5}, {6, 5}, {7, 5}, {0, 0}});
    EXPECT_EQ(compare_images(clean, blot, 2).largest_wrong_square, 3);
    // Under the threshold nothing counts as wrong.
    EXPECT_EQ(compare_images(clean, blot, 255).largest_wrong_square, 0);
}

TEST(CompareImages, DifferentSizesAreAnError) {
    EXPECT_THROW(compare_images(Image8{1, 1, {0, 0, 0}}, Image8{1, 2, {0, 0, 0, 0, 0, 0}}, 0),
                 Error);
}

}  // namespace
}  // namespace rt
