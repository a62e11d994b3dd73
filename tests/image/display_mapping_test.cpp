#include "rt/image/display_mapping.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

namespace rt {
namespace {

using Bytes = std::array<std::uint8_t, 3>;

TEST(DisplayMapping, ScalesIntensityBy255AndRounds) {
    EXPECT_EQ(to_display(Rgb{0.0, 0.5, 1.0}, DisplayMapping{}), (Bytes{0, 128, 255}));
    EXPECT_EQ(to_display(Rgb{0.1, 0.2, 0.3}, DisplayMapping{}), (Bytes{26, 51, 77}));
}

TEST(DisplayMapping, MultiplierBrightens) {
    const DisplayMapping twice{2.0, true};
    EXPECT_EQ(to_display(Rgb{0.25, 0.1, 0.0}, twice), (Bytes{128, 51, 0}));
}

TEST(DisplayMapping, ClippingScalesThePixelDownKeepingItsHue) {
    // 510, 255, 127.5 scaled by 1/2: the ratios 4 : 2 : 1 survive.
    EXPECT_EQ(to_display(Rgb{2.0, 1.0, 0.5}, DisplayMapping{}), (Bytes{255, 128, 64}));
    // Only the largest channel decides the scale.
    EXPECT_EQ(to_display(Rgb{0.5, 4.0, 0.0}, DisplayMapping{}), (Bytes{32, 255, 0}));
}

TEST(DisplayMapping, WithoutClippingValuesWrapLikeAnEightBitFrameBuffer) {
    const DisplayMapping no_clip{1.0, false};
    // 510 -> 254, 255 stays, 127.5 rounds to 128.
    EXPECT_EQ(to_display(Rgb{2.0, 1.0, 0.5}, no_clip), (Bytes{254, 255, 128}));
    // 256 wraps to 0, 300 to 44.
    EXPECT_EQ(to_display(Rgb{256.0 / 255.0, 300.0 / 255.0, 0.0}, no_clip), (Bytes{0, 44, 0}));
}

TEST(DisplayMapping, NegativeAndNanShowAsBlack) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(to_display(Rgb{-1.0, nan, 0.5}, DisplayMapping{}), (Bytes{0, 0, 128}));
    EXPECT_EQ(to_display(Rgb{-1.0, nan, 0.5}, DisplayMapping{1.0, false}), (Bytes{0, 0, 128}));
}

TEST(DisplayMapping, InfinityStaysWithinRange) {
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(to_display(Rgb{inf, 1.0, 0.0}, DisplayMapping{}), (Bytes{255, 0, 0}));
}

TEST(DisplayMapping, FilmBecomesTheWindowsPictureWithUnfinishedRowsBlack) {
    Film film(8, 6, PixelRect{2, 1, 4, 3});  // 3 x 3 window
    for (int y = 1; y <= 3; ++y) {
        for (int x = 2; x <= 4; ++x) {
            film.set_pixel(x, y, Rgb{1.0, 0.5, 0.0});
        }
    }
    film.set_first_finished_row(2);  // row 1 is not done
    const Image8 image = to_display(film, DisplayMapping{});
    ASSERT_EQ(image.width, 3);
    ASSERT_EQ(image.height, 3);
    ASSERT_EQ(image.rgb.size(), 27U);
    for (std::size_t i = 0; i < 9; ++i) {
        EXPECT_EQ(image.rgb[i], 0) << i;
    }
    for (std::size_t p = 3; p < 9; ++p) {
        EXPECT_EQ(image.rgb[p * 3], 255);
        EXPECT_EQ(image.rgb[p * 3 + 1], 128);
        EXPECT_EQ(image.rgb[p * 3 + 2], 0);
    }
}

TEST(DisplayMapping, FilmUsesItsStoredMappingByDefault) {
    Film film(1, 1, PixelRect{0, 0, 0, 0});
    film.set_pixel(0, 0, Rgb{0.25, 0.25, 0.25});
    film.set_first_finished_row(0);
    film.mapping.multiplier = 2.0;
    EXPECT_EQ(to_display(film).rgb, (std::vector<std::uint8_t>{128, 128, 128}));
}

}  // namespace
}  // namespace rt
