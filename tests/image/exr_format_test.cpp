#include "rt/image/exr_format.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "rt/core/error.h"
#include "rt/image/gro_format.h"
#include "rt/image/image_writer.h"

#include <gtest/gtest.h>

#include "image/sample_films.h"
#include "support/temp_dir.h"
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>

namespace rt {
namespace {

Film sample_film() {
    return test::sample_film(2);
}

using test::expect_same_film;

std::string input_error(const std::filesystem::path& path) {
    try {
        (void)read_exr(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no InputError";
}

// A picture from another program: half floats, no rt attributes, the whole view as data.
void write_half_picture(const std::filesystem::path& path, int width, int height,
                        const std::vector<float>& values) {
    std::vector<Imf::Rgba> pixels;
    for (std::size_t i = 0; i + 2 < values.size(); i += 3) {
        pixels.emplace_back(values[i], values[i + 1], values[i + 2], 1.0F);
    }
    Imf::RgbaOutputFile out(path.c_str(), width, height, Imf::WRITE_RGBA);
    out.setFrameBuffer(pixels.data(), 1, static_cast<std::size_t>(width));
    out.writePixels(height);
}

TEST(ExrFormat, RoundTripIsBitExactWithEverythingTheGroKeeps) {
    test::TempDir dir;
    const Film film = sample_film();
    write_exr(film, dir.path() / "p.exr");
    expect_same_film(film, read_exr(dir.path() / "p.exr"));
}

TEST(ExrFormat, GroToExrToGroGivesTheSameFile) {
    test::TempDir dir;
    write_gro(sample_film(), dir.path() / "a.gro");
    write_image(read_linear_image(dir.path() / "a.gro"), dir.path() / "b.exr");
    write_image(read_linear_image(dir.path() / "b.exr"), dir.path() / "c.gro");
    EXPECT_EQ(test::read_text(dir.path() / "a.gro"), test::read_text(dir.path() / "c.gro"));
}

TEST(ExrFormat, ReadsHalfFloatPicturesFromElsewhere) {
    test::TempDir dir;
    const std::vector<float> values = {0.1F,   1.0F / 3.0F, 1000.7F, 0.0F, 2.0F,  -0.25F,
                                       1e-3F,  65000.0F,    0.5F,    7.0F, 0.01F, 3.14159F,
                                       100.0F, 0.2F,        0.3F,    0.4F, 0.5F,  0.6F};
    write_half_picture(dir.path() / "h.exr", 3, 2, values);
    const Film film = read_exr(dir.path() / "h.exr");
    EXPECT_EQ(film.view_width(), 3);
    EXPECT_EQ(film.view_height(), 2);
    EXPECT_EQ(film.window(), (PixelRect{0, 0, 2, 1}));
    ASSERT_EQ(film.data().size(), values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        // Exactly the half nearest the value, and so within half-float rounding (2^-11).
        EXPECT_EQ(film.data()[i], static_cast<float>(Imath::half(values[i]))) << i;
        EXPECT_LE(std::fabs(film.data()[i] - values[i]), std::fabs(values[i]) * 0x1p-11F) << i;
    }
    // Without rt's attributes: the default mapping, every row finished, nothing recorded.
    EXPECT_EQ(film.mapping.multiplier, 1.0);
    EXPECT_TRUE(film.mapping.clip);
    EXPECT_TRUE(film.complete());
    EXPECT_EQ(film.provenance.scene, "");
}

TEST(ExrFormat, RefusesWhatAFilmCannotHold) {
    test::TempDir dir;
    {
        // Only a luminance channel.
        Imf::Header header(2, 2);
        header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
        std::vector<float> y(4, 0.5F);
        Imf::FrameBuffer buffer;
        buffer.insert("Y", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(y.data()), sizeof(float),
                                      2 * sizeof(float)));
        Imf::OutputFile out((dir.path() / "y.exr").c_str(), header);
        out.setFrameBuffer(buffer);
        out.writePixels(2);
    }
    EXPECT_EQ(
        input_error(dir.path() / "y.exr"),
        (dir.path() / "y.exr").string() + ": expected R, G and B channels, found no R channel");

    write_half_picture(dir.path() / "nan.exr", 1, 1, {0.0F, std::nanf(""), 0.0F});
    EXPECT_EQ(input_error(dir.path() / "nan.exr"),
              (dir.path() / "nan.exr").string() +
                  ": expected finite pixel values, found nan in pixel (0, 0)");

    const std::filesystem::path junk = dir.write("junk.exr", "not a picture\n");
    EXPECT_NE(input_error(junk).find("junk.exr: not an OpenEXR picture rt can read: "),
              std::string::npos)
        << input_error(junk);
    EXPECT_THROW((void)read_exr(dir.path() / "missing.exr"), IoError);
}

TEST(ExrFormat, AFailedWriteLeavesTheOldFile) {
    test::TempDir dir;
    const std::filesystem::path path = dir.write("p.exr", "the old picture");
    Film film = sample_film();
    film.data()[5] = std::numeric_limits<float>::infinity();
    EXPECT_THROW(write_exr(film, path), Error);
    EXPECT_EQ(test::read_text(path), "the old picture");
    EXPECT_THROW(write_exr(sample_film(), dir.path() / "no-such-folder" / "p.exr"), IoError);
    // Nothing but the old picture is left in the folder (no temporary file).
    int files = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) {
        ++files;
    }
    EXPECT_EQ(files, 1);
}

}  // namespace
}  // namespace rt
