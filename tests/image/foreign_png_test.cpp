// PNG files made by another encoder than ours (tests/data/png/make_pngs.py, written from the PNG
// specification with Python's zlib alone) read with rt's reader and compared pixel for pixel with
// the plain-text picture they were made from: the reader and libpng's writer cannot agree on a
// shared bug here.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

#include "rt/image/png_format.h"

#include <gtest/gtest.h>

#include "support/hand_readers.h"
#include "support/temp_dir.h"

namespace rt::test {
namespace {

namespace fs = std::filesystem;

fs::path png_folder() {
    return source_dir() / "tests/data/png";
}

Image8 source_picture() {
    return parse_ppm(read_text(png_folder() / "source.ppm"));
}

// Where the alpha variants are transparent (make_pngs.py's transparent()); composited on black.
bool transparent(int x, int y) {
    return (x + 2 * y) % 7 == 0;
}

// The picture a variant must read as: each source pixel through `expected`.
using PixelRule = std::function<void(int x, int y, std::uint8_t* rgb)>;

struct ForeignPng {
    std::string file;
    PixelRule rule;
};

std::ostream& operator<<(std::ostream& out, const ForeignPng& c) {
    return out << c.file;
}

void same(int /*x*/, int /*y*/, std::uint8_t* /*rgb*/) {}

void black_where_transparent(int x, int y, std::uint8_t* rgb) {
    if (transparent(x, y)) {
        rgb[0] = rgb[1] = rgb[2] = 0;
    }
}

// Grey variants store the red channel; a grey sample of depth n and value v reads as
// v * 255 / (2^n - 1), replicated in the three channels (the PNG specification's scaling).
PixelRule grey(int depth, bool alpha = false) {
    return [depth, alpha](int x, int y, std::uint8_t* rgb) {
        const int top = (1 << depth) - 1;
        const int v = rgb[0] >> (8 - depth);
        rgb[0] = rgb[1] = rgb[2] = static_cast<std::uint8_t>(v * 255 / top);
        if (alpha) {
            black_where_transparent(x, y, rgb);
        }
    };
}

class ForeignPngRead : public ::testing::TestWithParam<ForeignPng> {};

TEST_P(ForeignPngRead, MatchesItsTextSourcePixelForPixel) {
    const ForeignPng& c = GetParam();
    Image8 want = source_picture();
    ASSERT_EQ(want.width, 11);
    ASSERT_EQ(want.height, 9);
    for (int y = 0; y < want.height; ++y) {
        for (int x = 0; x < want.width; ++x) {
            c.rule(x, y, &want.rgb[(static_cast<std::size_t>(y * want.width + x)) * 3]);
        }
    }
    const Image8 got = read_png(png_folder() / c.file);
    ASSERT_EQ(got.width, want.width);
    ASSERT_EQ(got.height, want.height);
    for (int y = 0; y < want.height; ++y) {
        for (int x = 0; x < want.width; ++x) {
            for (int k = 0; k < 3; ++k) {
                const std::size_t i =
                    static_cast<std::size_t>(y * want.width + x) * 3 + static_cast<std::size_t>(k);
                ASSERT_EQ(int{got.rgb[i]}, int{want.rgb[i]})
                    << c.file << " pixel (" << x << ", " << y << ") channel " << k;
            }
        }
    }
}

// Exact agreement: every variant stores the source's values losslessly (16-bit as v * 257, grey
// depths by the specification's scaling), so no rounding is left to tolerate.
INSTANTIATE_TEST_SUITE_P(
    MadeByMakePngsPy, ForeignPngRead,
    ::testing::Values(ForeignPng{"rgb8.png", same}, ForeignPng{"rgb8_adam7.png", same},
                      ForeignPng{"rgb16.png", same},
                      ForeignPng{"rgba8.png", black_where_transparent},
                      ForeignPng{"palette8.png", same}, ForeignPng{"grey8.png", grey(8)},
                      ForeignPng{"grey_alpha8_adam7.png", grey(8, true)},
                      ForeignPng{"grey4.png", grey(4)}, ForeignPng{"grey1.png", grey(1)}),
    [](const ::testing::TestParamInfo<ForeignPng>& case_info) {
        return case_info.param.file.substr(0, case_info.param.file.find('.'));
    });

}  // namespace
}  // namespace rt::test
