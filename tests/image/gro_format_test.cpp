#include "rt/image/gro_format.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "rt/core/error.h"

#include <gtest/gtest.h>

#include "image/sample_films.h"
#include "support/temp_dir.h"

namespace rt {
namespace {

Film sample_film() {
    return test::sample_film(1);
}

using test::expect_same_film;

TEST(GroFormat, RoundTripIsBitExact) {
    test::TempDir dir;
    const Film film = sample_film();
    write_gro(film, dir.path() / "p.gro");
    expect_same_film(film, read_gro(dir.path() / "p.gro"));
}

TEST(GroFormat, RoundTripKeepsAPartialFilmsFinishedRows) {
    test::TempDir dir;
    Film film(10, 8, PixelRect{0, 2, 9, 7});
    film.set_pixel(3, 7, Rgb{0.25, 0.5, 0.75});
    film.set_first_finished_row(6);  // rows 6 and 7 done, interrupted
    write_gro(film, dir.path() / "partial.gro");
    const Film back = read_gro(dir.path() / "partial.gro");
    expect_same_film(film, back);
    EXPECT_FALSE(back.complete());
    EXPECT_EQ(back.pixel(3, 7), (Rgb{0.25, 0.5, 0.75}));
}

TEST(GroFormat, RoundTripOfAFilmWithNothingFinished) {
    test::TempDir dir;
    Film film(3, 3, PixelRect{0, 0, 2, 2});  // a new film: first_finished_row = bottom + 1
    write_gro(film, dir.path() / "empty.gro");
    expect_same_film(film, read_gro(dir.path() / "empty.gro"));
}

TEST(GroFormat, HeaderIsReadableTextAndPixelsAreLittleEndian) {
    test::TempDir dir;
    Film film(2, 1, PixelRect{0, 0, 1, 0});
    film.set_pixel(0, 0, Rgb{1.0, 0.0, -2.0});
    film.set_first_finished_row(0);
    film.provenance = {"a\nb", "", "rt", "t", "", "", ""};  // a newline must not break the header
    write_gro(film, dir.path() / "le.gro");
    const std::string bytes = test::read_text(dir.path() / "le.gro");
    const std::string header =
        "GRO rt 1\nview 2 1\nwindow 0 0 1 0\nfirst_finished_row 0\ndisplay_multiplier 1\n"
        "display_clip on\nscene a b\nswitches \nprogram rt\ncreated t\n"
        "pixels rgb-float32-le\nend\n";
    ASSERT_EQ(bytes.size(), header.size() + std::size_t{24});  // 2 pixels x 3 floats x 4 bytes
    EXPECT_EQ(bytes.substr(0, header.size()), header);
    // 1.0f is 0x3F800000, -2.0f is 0xC0000000, least significant byte first.
    EXPECT_EQ(bytes.substr(header.size(), 4), std::string("\x00\x00\x80\x3f", 4));
    EXPECT_EQ(bytes.substr(header.size() + 8, 4), std::string("\x00\x00\x00\xc0", 4));
}

TEST(GroFormat, WriterRefusesWhatTheReaderWouldRefuse) {
    test::TempDir dir;
    Film nan_film(2, 2, PixelRect{0, 0, 1, 1});
    nan_film.set_pixel(1, 0, Rgb{std::nan(""), 0.0, 0.0});
    EXPECT_THROW(write_gro(nan_film, dir.path() / "nan.gro"), Error);
    Film outside(2, 2, PixelRect{0, 0, 2, 1});  // window wider than the view
    EXPECT_THROW(write_gro(outside, dir.path() / "outside.gro"), Error);
    EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(GroFormat, MissingFileIsAnIoError) {
    test::TempDir dir;
    EXPECT_THROW(read_gro(dir.path() / "nothing.gro"), IoError);
    EXPECT_THROW(read_gro(dir.path()), IoError);
}

TEST(GroFormat, UnknownHeaderKeysAreIgnored) {
    test::TempDir dir;
    const std::string text =
        "GRO rt 1\nview 1 1\nfuture_key some value\nwindow 0 0 0 0\nfirst_finished_row 0\n"
        "pixels rgb-float32-le\nnotes\nend\n" +
        std::string("\x00\x00\x80\x3f\x00\x00\x00\x00\x00\x00\x00\x3f", 12);
    const Film film = read_gro(dir.write("f.gro", text));
    EXPECT_EQ(film.pixel(0, 0), (Rgb{1.0, 0.0, 0.5}));
    // Optional keys take the program's defaults.
    EXPECT_EQ(film.mapping.multiplier, 1.0);
    EXPECT_TRUE(film.mapping.clip);
    EXPECT_EQ(film.provenance.scene, "");
}

}  // namespace
}  // namespace rt
