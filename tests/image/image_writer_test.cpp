#include "rt/image/image_writer.h"

#include <filesystem>
#include <string>

#include "rt/core/atomic_file.h"
#include "rt/core/error.h"
#include "rt/image/display_mapping.h"
#include "rt/image/gro_format.h"
#include "rt/image/png_format.h"
#include "rt/image/ppm_format.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace rt {
namespace {

Film small_film() {
    Film film(6, 4, PixelRect{1, 0, 3, 2});
    for (int y = 0; y <= 2; ++y) {
        for (int x = 1; x <= 3; ++x) {
            film.set_pixel(x, y, Rgb{0.1 * x, 0.3 * y, 2.0});
        }
    }
    film.set_first_finished_row(1);
    film.mapping = {1.5, true};
    return film;
}

std::size_t files_in(const std::filesystem::path& dir) {
    return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir),
                                                  std::filesystem::directory_iterator()));
}

TEST(ImageWriter, ChoosesTheFormatByExtensionIgnoringCase) {
    EXPECT_EQ(image_format_for("a.gro"), ImageFormat::Gro);
    EXPECT_EQ(image_format_for("dir/a.PNG"), ImageFormat::Png);
    EXPECT_EQ(image_format_for("a.Ppm"), ImageFormat::Ppm);
}

TEST(ImageWriter, UnknownExtensionIsAUsageError) {
    try {
        image_format_for("x.jpg");
        FAIL();
    } catch (const UsageError& e) {
        EXPECT_STREQ(
            e.what(),
            "cannot write 'x.jpg': unknown image format '.jpg' (known: .gro, .exr, .png, .ppm)");
    }
    try {
        image_format_for("picture");
        FAIL();
    } catch (const UsageError& e) {
        EXPECT_STREQ(
            e.what(),
            "cannot write 'picture': no image format extension (known: .gro, .exr, .png, .ppm)");
    }
}

TEST(ImageWriter, WritesTheWindowInEachFormat) {
    test::TempDir dir;
    const Film film = small_film();
    const Image8 expected = to_display(film);
    write_image(film, dir.path() / "a.png");
    write_image(film, dir.path() / "a.PPM");
    write_image(film, dir.path() / "a.gro");
    EXPECT_EQ(read_png(dir.path() / "a.png"), expected);
    EXPECT_EQ(read_ppm(dir.path() / "a.PPM"), expected);
    EXPECT_EQ(read_gro(dir.path() / "a.gro").data(), film.data());
    EXPECT_EQ(expected.width, 3);
    EXPECT_EQ(expected.height, 3);
    EXPECT_EQ(expected.rgb[0], 0);  // row 0 is unfinished: black
}

TEST(ImageWriter, UnknownExtensionWritesNothing) {
    test::TempDir dir;
    EXPECT_THROW(write_image(small_film(), dir.path() / "x.jpg"), UsageError);
    EXPECT_EQ(files_in(dir.path()), 0U);
}

// A broken film makes every writer throw; the old file must survive untouched, with no
// temporary left beside it.
TEST(ImageWriter, AFailedWriteNeverReplacesAnExistingFile) {
    test::TempDir dir;
    Film broken = small_film();
    broken.data().pop_back();
    for (const char* name : {"old.gro", "old.png", "old.ppm"}) {
        const std::filesystem::path path = dir.write(name, "the previous picture");
        EXPECT_THROW(write_image(broken, path), Error) << name;
        EXPECT_EQ(test::read_text(path), "the previous picture") << name;
    }
    EXPECT_EQ(files_in(dir.path()), 3U);
}

TEST(ImageWriter, AWriterThrowingMidwayLeavesTheOldFile) {
    test::TempDir dir;
    const std::filesystem::path path = dir.write("p.gro", "old");
    EXPECT_THROW(write_file_atomically(path,
                                       [](std::ostream& out) {
                                           out << "half a picture";
                                           throw IoError("simulated failure");
                                       }),
                 IoError);
    EXPECT_EQ(test::read_text(path), "old");
    EXPECT_EQ(files_in(dir.path()), 1U);
}

TEST(ImageWriter, WritingOverAnExistingFileReplacesIt) {
    test::TempDir dir;
    const std::filesystem::path path = dir.write("p.ppm", "old");
    write_image(small_film(), path);
    EXPECT_EQ(read_ppm(path), to_display(small_film()));
    EXPECT_EQ(files_in(dir.path()), 1U);
}

TEST(ImageWriter, AMissingFolderIsAnIoError) {
    test::TempDir dir;
    EXPECT_THROW(write_image(small_film(), dir.path() / "no" / "such.png"), IoError);
}

}  // namespace
}  // namespace rt
