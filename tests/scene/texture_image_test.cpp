// How a point of a grid reads a picture (-V colour and normal maps): bilinear between pixel
// centres, the border pixels continued outward, bytes over 255.
#include "rt/scene/texture_image.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

// Two pixels side by side over two rows: black and white on top, red and blue below.
TextureImage two_by_two() {
    return {2, 2, {0, 0, 0, 255, 255, 255, 255, 0, 0, 0, 0, 255}, ""};
}

void expect_near(const Rgb& got, const Rgb& want) {
    EXPECT_NEAR(got.r, want.r, 1e-12);
    EXPECT_NEAR(got.g, want.g, 1e-12);
    EXPECT_NEAR(got.b, want.b, 1e-12);
}

TEST(TextureImage, PixelCentresGiveTheirOwnColour) {
    const TextureImage image = two_by_two();
    expect_near(sample_bilinear(image, 0.5, 0.5), {0, 0, 0});
    expect_near(sample_bilinear(image, 1.5, 0.5), {1, 1, 1});
    expect_near(sample_bilinear(image, 0.5, 1.5), {1, 0, 0});
    expect_near(sample_bilinear(image, 1.5, 1.5), {0, 0, 1});
}

TEST(TextureImage, BetweenCentresTheColoursBlend) {
    const TextureImage image = two_by_two();
    expect_near(sample_bilinear(image, 1.0, 0.5), {0.5, 0.5, 0.5});
    expect_near(sample_bilinear(image, 1.0, 1.0), {0.5, 0.25, 0.5});
    expect_near(sample_bilinear(image, 0.75, 1.5), {0.75, 0, 0.25});
}

TEST(TextureImage, BeyondTheBorderPixelsTheBorderStays) {
    const TextureImage image = two_by_two();
    expect_near(sample_bilinear(image, 0.0, 0.0), {0, 0, 0});
    expect_near(sample_bilinear(image, 2.0, 0.2), {1, 1, 1});
    expect_near(sample_bilinear(image, -5.0, 9.0), {1, 0, 0});
    const TextureImage one{1, 1, {51, 102, 204}, ""};
    expect_near(sample_bilinear(one, 0.9, 0.1), {0.2, 0.4, 0.8});
}

}  // namespace
}  // namespace rt
