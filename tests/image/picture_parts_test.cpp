// rt --tile I/N's bands: read from the command line and the part header, and cut so that the N
// bands cover the window exactly once, as evenly as whole rows allow.
#include "rt/image/picture_parts.h"

#include <string>

#include "rt/core/error.h"

#include <gtest/gtest.h>

namespace rt {
namespace {

TEST(PictureParts, ReadsIOfN) {
    EXPECT_EQ(parse_picture_part("2/3"), (PicturePart{2, 3}));
    EXPECT_EQ(parse_picture_part("1/1"), (PicturePart{1, 1}));
    for (const std::string bad : {"0/3", "4/3", "3", "a/b", "1/0", "-1/2", "1/2/3", ""}) {
        EXPECT_THROW((void)parse_picture_part(bad), UsageError) << bad;
    }
    EXPECT_EQ(parse_part_line("2 3"), (PicturePart{2, 3}));
    EXPECT_FALSE(parse_part_line("3 2"));
    EXPECT_FALSE(parse_part_line("2"));
}

TEST(PictureParts, BandsCoverTheWindowOnceAndEvenly) {
    const PixelRect window{5, 10, 20, 109};  // 100 rows
    for (const int count : {1, 2, 3, 7, 99, 100}) {
        int next_top = window.top;
        for (int index = 1; index <= count; ++index) {
            const PixelRect band = part_window(window, {index, count});
            EXPECT_EQ(band.left, window.left);
            EXPECT_EQ(band.right, window.right);
            EXPECT_EQ(band.top, next_top) << index << "/" << count;
            const int rows = band.height();
            EXPECT_TRUE(rows == 100 / count || rows == 100 / count + 1) << index << "/" << count;
            next_top = band.bottom + 1;
        }
        EXPECT_EQ(next_top, window.bottom + 1) << count;
    }
    EXPECT_THROW((void)part_window(window, {1, 101}), SettingError);
}

}  // namespace
}  // namespace rt
