// What the picture writers refuse to write and the readers refuse to read, with their messages:
// a writer never leaves a file it would not read back, and a refused write leaves the old file.
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "rt/core/error.h"
#include "rt/image/film.h"
#include "rt/image/gro_format.h"
#include "rt/image/png_format.h"
#include "rt/image/ppm_format.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

// A 2 x 2 window at the top left of a view, every pixel grey.
Film grey_film(int view_width = 4, int view_height = 3) {
    Film film(view_width, view_height, {0, 0, 1, 1});
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 2; ++x) {
            film.set_pixel(x, y, {0.5, 0.5, 0.5});
        }
    }
    return film;
}

// Calls write on a path holding "old", expecting rt::Error with "cannot write PATH: why" and the
// old file left as it was.
template <typename Write>
void expect_refused(const test::TempDir& dir, const std::string& name, Write write,
                    const std::string& why) {
    const fs::path path = dir.write(name, "old");
    try {
        write(path);
        ADD_FAILURE() << name << " was written";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write " + path.string() + ": " + why);
    }
    EXPECT_EQ(test::read_text(path), "old");
}

TEST(GroWriter, RefusesWhatTheReaderWouldRefuse) {
    const test::TempDir dir;
    const auto gro = [](const Film& film) {
        return [&film](const fs::path& path) { write_gro(film, path); };
    };
    const Film too_wide = grey_film(20000, 3);
    expect_refused(dir, "too_wide.gro", gro(too_wide),
                   "the view is 20000 x 3 pixels (at most 16384 a side)");
    Film unfinished = grey_film();
    unfinished.set_first_finished_row(3);  // the window holds rows 0 and 1: at most 2
    expect_refused(dir, "row.gro", gro(unfinished),
                   "the first finished row 3 is outside the window");
    Film negative = grey_film();
    negative.mapping.multiplier = -1.0;
    expect_refused(dir, "negative.gro", gro(negative),
                   "the display multiplier -1 is not a non-negative number");
    const Film empty(4, 3, {2, 0, 1, 0});
    expect_refused(dir, "empty.gro", gro(empty), "the film's window is empty");
}

TEST(GroWriter, AcceptsEveryLimitItChecks) {
    // The edges of the checks above: a finished row one past the window, a zero multiplier.
    const test::TempDir dir;
    Film film = grey_film();
    film.set_first_finished_row(2);
    film.mapping.multiplier = 0.0;
    write_gro(film, dir.path() / "edge.gro");
    const Film back = read_gro(dir.path() / "edge.gro");
    EXPECT_EQ(back.first_finished_row(), 2);
    EXPECT_EQ(back.mapping.multiplier, 0.0);
}

TEST(GroReader, HeaderMustEndWithinAThousandLines) {
    const test::TempDir dir;
    std::string text = "GRO rt 1\n";
    for (int i = 2; i <= 1001; ++i) {
        text += "note_" + std::to_string(i) + " a key a newer writer might add\n";
    }
    const fs::path path = dir.write("long.gro", text + "end\n");
    try {
        read_gro(path);
        FAIL() << "read_gro accepted a header of 1002 lines";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  path.string() + ":1001: expected 'end' within 1000 header lines, found more");
    }
}

TEST(GroReader, AFolderOrAMissingFileIsAnIoError) {
    const test::TempDir dir;
    EXPECT_THROW(read_gro(dir.path()), IoError);
    EXPECT_THROW(read_gro(dir.path() / "missing.gro"), IoError);
}

std::string ppm_error(const test::TempDir& dir, const std::string& name,
                      const std::string& content) {
    const fs::path path = dir.write(name, content);
    try {
        read_ppm(path);
    } catch (const InputError& e) {
        const std::string what = e.what();
        return what.rfind(path.string() + ":", 0) == 0 ? what.substr(path.string().size() + 1)
                                                       : "wrong file in: " + what;
    }
    return "accepted";
}

TEST(PpmReader, HeaderEdgeCasesNameTheLine) {
    const test::TempDir dir;
    // A field is cut at 21 characters, enough to show it is not a number.
    EXPECT_EQ(ppm_error(dir, "long.ppm", "P6\n" + std::string(30, '7') + " 1\n255\n"),
              "2: expected a width from 1 to 16384, found '" + std::string(21, '7') + "'");
    EXPECT_EQ(ppm_error(dir, "cut.ppm", "P6\n1 1\n255"),
              "3: expected one whitespace character after maxval, found the end of the file");
    EXPECT_EQ(ppm_error(dir, "glued.ppm", "P6\n1 1\n255#abc"),
              "3: expected one whitespace character after maxval, found binary data");
    EXPECT_EQ(ppm_error(dir, "decimal.ppm", "P6\n1.0 1\n255\nabc"),
              "2: expected a width from 1 to 16384, found '1.0'");
}

TEST(PpmReader, AFolderOrAMissingFileIsAnIoError) {
    const test::TempDir dir;
    EXPECT_THROW(read_ppm(dir.path()), IoError);
    EXPECT_THROW(read_ppm(dir.path() / "missing.ppm"), IoError);
}

TEST(PpmWriter, RefusesAnInconsistentImage) {
    const test::TempDir dir;
    const Image8 short_of_bytes{2, 2, std::vector<std::uint8_t>(11)};
    expect_refused(
        dir, "short.ppm", [&](const fs::path& path) { write_ppm(short_of_bytes, path); },
        "the image is empty or inconsistent");
    const Image8 empty{0, 0, {}};
    expect_refused(
        dir, "empty.ppm", [&](const fs::path& path) { write_ppm(empty, path); },
        "the image is empty or inconsistent");
}

TEST(PngWriter, RefusesAnInconsistentImage) {
    const test::TempDir dir;
    const Image8 short_of_bytes{2, 2, std::vector<std::uint8_t>(11)};
    EXPECT_THROW(encode_png(short_of_bytes), Error);
    expect_refused(
        dir, "short.png", [&](const fs::path& path) { write_png(short_of_bytes, path); },
        "cannot encode an empty or inconsistent image as PNG");
}

// The PNG checksum (ISO 3309 CRC-32), to forge a header that is valid but for its size.
std::uint32_t crc32(const std::uint8_t* bytes, std::size_t count) {
    std::uint32_t crc = 0xffffffffU;
    for (std::size_t i = 0; i < count; ++i) {
        crc ^= bytes[i];
        for (int bit = 0; bit < 8; ++bit) {
            crc = (crc >> 1) ^ (0xedb88320U & (0U - (crc & 1U)));
        }
    }
    return crc ^ 0xffffffffU;
}

void put_big_endian(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) {
        bytes[at + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(value >> (24 - 8 * i));
    }
}

TEST(PngReader, RefusesAPictureWiderThanTheLimitBeforeAllocatingIt) {
    // The IHDR chunk follows the 8-byte signature: length, "IHDR", width at 16, height at 20,
    // five one-byte fields, then its CRC at 29 over bytes 12 to 28.
    std::vector<std::uint8_t> bytes = encode_png(Image8{1, 1, {1, 2, 3}});
    ASSERT_EQ(std::string(bytes.begin() + 12, bytes.begin() + 16), "IHDR");
    put_big_endian(bytes, 16, 20000);
    put_big_endian(bytes, 29, crc32(&bytes[12], 17));
    const test::TempDir dir;
    const fs::path path = dir.write("wide.png", std::string(bytes.begin(), bytes.end()));
    try {
        read_png(path);
        FAIL() << "read_png accepted a 20000-pixel-wide picture";
    } catch (const InputError& e) {
        EXPECT_EQ(
            std::string(e.what()),
            path.string() + ": expected a PNG of at most 16384 pixels a side, found 20000 x 1");
    }
}

TEST(PngReader, RefusesAHeaderItsCompressedDataCannotHoldBeforeAllocating) {
    // 1 x 1 pixel data under a 16384 x 16384 header: 768 MiB claimed from a few bytes of IDAT.
    std::vector<std::uint8_t> bytes = encode_png(Image8{1, 1, {1, 2, 3}});
    put_big_endian(bytes, 16, 16384);
    put_big_endian(bytes, 20, 16384);
    put_big_endian(bytes, 29, crc32(&bytes[12], 17));
    const test::TempDir dir;
    const fs::path path = dir.write("claim.png", std::string(bytes.begin(), bytes.end()));
    const std::string text(bytes.begin(), bytes.end());
    const std::size_t at = text.find("IDAT") - 4;  // the one IDAT chunk's length
    const std::string idat = std::to_string((bytes[at + 2] << 8) | bytes[at + 3]);
    const std::string want = path.string() + ": expected a PNG picture whose compressed data (" +
                             idat +
                             " bytes) can hold its 16384 x 16384 pixels, found 805306368 bytes "
                             "of pixel rows to unpack from them (deflate unpacks at most 1032 "
                             "bytes from each)";
    for (const auto& read : {std::function<void()>([&] { read_png_header(path); }),
                             std::function<void()>([&] { read_png(path); })}) {
        try {
            read();
            FAIL() << "a 16384 x 16384 claim was taken from " << idat << " bytes";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()), want);
        }
    }
}

TEST(PngReader, AHeaderGivesTheSizeAndAPictureAsCompressedAsDeflateAllowsStillReads) {
    const test::TempDir dir;
    // A black picture compresses about as far as deflate goes, and is no bomb.
    const Image8 black{1000, 1000, std::vector<std::uint8_t>(3000000, 0)};
    const fs::path path = dir.path() / "black.png";
    write_png(black, path);
    const PngHeader header = read_png_header(path);
    EXPECT_EQ(header.width, 1000);
    EXPECT_EQ(header.height, 1000);
    EXPECT_EQ(header.decoded_bytes(), 3000000u);
    EXPECT_GT(header.compressed_bytes * kMaxDeflateRatio, 3000000u);
    EXPECT_LT(header.compressed_bytes, fs::file_size(path));
    EXPECT_EQ(read_png(path), black);
}

}  // namespace
}  // namespace rt
