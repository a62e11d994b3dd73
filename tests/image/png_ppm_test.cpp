#include <cstdint>
#include <filesystem>
#include <string>

#include "rt/core/error.h"
#include "rt/image/png_format.h"
#include "rt/image/ppm_format.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace rt {
namespace {

Image8 gradient(int width, int height) {
    Image8 image{width, height, {}};
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            image.rgb.push_back(static_cast<std::uint8_t>(x * 17));
            image.rgb.push_back(static_cast<std::uint8_t>(y * 29));
            image.rgb.push_back(static_cast<std::uint8_t>((x + y) * 5));
        }
    }
    return image;
}

TEST(Png, WriteThenReadGivesTheSamePicture) {
    test::TempDir dir;
    const Image8 image = gradient(13, 7);
    write_png(image, dir.path() / "g.png");
    EXPECT_EQ(read_png(dir.path() / "g.png"), image);
}

TEST(Png, EncodedBytesStartWithThePngSignature) {
    const std::vector<std::uint8_t> bytes = encode_png(gradient(2, 2));
    ASSERT_GE(bytes.size(), 8U);
    EXPECT_EQ(bytes[0], 0x89);
    EXPECT_EQ(bytes[1], 'P');
}

TEST(Png, ANonPngFileIsBadInput) {
    test::TempDir dir;
    EXPECT_THROW(read_png(dir.write("x.png", "not a png at all")), InputError);
    EXPECT_THROW(read_png(dir.write("empty.png", "")), InputError);
    EXPECT_THROW(read_png(dir.path() / "missing.png"), IoError);
}

TEST(Png, ATruncatedFileIsBadInput) {
    test::TempDir dir;
    const std::vector<std::uint8_t> bytes = encode_png(gradient(40, 40));
    const std::string half(bytes.begin(),
                           bytes.begin() + static_cast<std::ptrdiff_t>(bytes.size() / 2));
    EXPECT_THROW(read_png(dir.write("half.png", half)), InputError);
}

TEST(Ppm, WriteThenReadGivesTheSamePicture) {
    test::TempDir dir;
    const Image8 image = gradient(5, 9);
    write_ppm(image, dir.path() / "g.ppm");
    EXPECT_EQ(read_ppm(dir.path() / "g.ppm"), image);
    const std::string bytes = test::read_text(dir.path() / "g.ppm");
    EXPECT_EQ(bytes.substr(0, 11), "P6\n5 9\n255\n");
    EXPECT_EQ(bytes.size(), 11U + 5 * 9 * 3);
}

TEST(Ppm, CommentsInTheHeaderAreSkipped) {
    test::TempDir dir;
    const Image8 image = read_ppm(dir.write("c.ppm", "P6\n# made by hand\n1 1 # size\n255\nabc"));
    EXPECT_EQ(image, (Image8{1, 1, {'a', 'b', 'c'}}));
}

struct BadPpm {
    std::string name;
    std::string content;
    std::string message;
};

// Names the case in test output instead of dumping its bytes.
// NOLINTNEXTLINE(readability-identifier-naming): the name GoogleTest looks for
void PrintTo(const BadPpm& bad, std::ostream* os) {
    *os << bad.name;
}

class PpmMalformed : public testing::TestWithParam<BadPpm> {};

TEST_P(PpmMalformed, IsRejectedWithItsMessage) {
    test::TempDir dir;
    const std::filesystem::path file = dir.write(GetParam().name + ".ppm", GetParam().content);
    try {
        read_ppm(file);
        FAIL() << "read_ppm accepted " << GetParam().name;
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), file.string() + ":" + GetParam().message);
    }
}

INSTANTIATE_TEST_SUITE_P(
    AllCases, PpmMalformed,
    testing::Values(
        BadPpm{"ascii_ppm", "P3\n1 1\n255\n0 0 0\n",
               "1: expected 'P6' (a binary PPM picture), found 'P3'"},
        BadPpm{"empty", "", "1: expected 'P6' (a binary PPM picture), found the end of the file"},
        BadPpm{"too_wide", "P6\n20000 1\n255\n",
               "2: expected a width from 1 to 16384, found '20000'"},
        BadPpm{"zero_height", "P6\n1 0\n255\n", "2: expected a height from 1 to 16384, found '0'"},
        BadPpm{"maxval", "P6\n1 1\n65535\n", "3: expected maxval 255, found '65535'"},
        BadPpm{"truncated", "P6\n2 1\n255\nabc",
               "4: expected 6 bytes of pixel data (2 x 1 pixels), found 3"},
        BadPpm{"trailing", "P6\n1 1\n255\nabcd",
               "4: expected 3 bytes of pixel data (1 x 1 pixels), found 4"}),
    [](const testing::TestParamInfo<BadPpm>& param_info) { return param_info.param.name; });

}  // namespace
}  // namespace rt
