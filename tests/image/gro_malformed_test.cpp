// Every way a .gro file can be malformed, with the exact message the reader gives.
#include <string>
#include <vector>

#include "rt/core/error.h"
#include "rt/image/gro_format.h"

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace rt {
namespace {

// A valid 2 x 3 window (6 pixels, 72 bytes of pixel data) in a 4 x 3 view; 12 header lines.
std::vector<std::string> header_lines() {
    return {"GRO rt 1",
            "view 4 3",
            "window 1 0 2 2",
            "first_finished_row 0",
            "display_multiplier 1",
            "display_clip on",
            "scene twocubes",
            "switches -Dd",
            "program rt 0.1.0",
            "created 2024-01-01T00:00:00Z",
            "pixels rgb-float32-le",
            "end"};
}

std::string pixels(std::size_t bytes) {
    std::string out;
    for (std::size_t i = 0; i < bytes / 4; ++i) {
        out += std::string("\x00\x00\x00\x3f", 4);  // 0.5f
    }
    return out + std::string(bytes % 4, '\x01');
}

std::string file_with(const std::vector<std::string>& lines, const std::string& data) {
    std::string text;
    for (const std::string& line : lines) {
        text += line + "\n";
    }
    return text + data;
}

std::vector<std::string> replaced(std::size_t index, const std::string& line) {
    std::vector<std::string> lines = header_lines();
    lines[index] = line;
    return lines;
}

std::vector<std::string> without(std::size_t index) {
    std::vector<std::string> lines = header_lines();
    lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(index));
    return lines;
}

struct BadGro {
    std::string name;
    std::string content;
    std::string message;  ///< after "path:"
};

// Names the case in test output instead of dumping its bytes.
// NOLINTNEXTLINE(readability-identifier-naming): the name GoogleTest looks for
void PrintTo(const BadGro& bad, std::ostream* os) {
    *os << bad.name;
}

std::vector<BadGro> bad_files() {
    const std::string good = pixels(72);
    std::string nan_pixels = good;
    nan_pixels.replace(16, 4, std::string("\x00\x00\xc0\x7f", 4));  // value 4: pixel (2, 0) g
    std::string inf_pixels = good;
    inf_pixels.replace(68, 4, std::string("\x00\x00\x80\xff", 4));  // the last value
    return {
        {"empty", "", "1: expected 'GRO rt 1' (a .gro picture), found an empty file"},
        {"bad_magic", "P6\n2 2\n255\n", "1: expected 'GRO rt 1' (a .gro picture), found 'P6'"},
        {"binary_magic", std::string("\x89PNG\r\n", 6),
         "1: expected 'GRO rt 1' (a .gro picture), found '?PNG?'"},
        {"unknown_version", file_with(replaced(0, "GRO rt 2"), good),
         "1: expected .gro format version 1, found version '2'"},
        {"missing_window", file_with(without(2), good),
         "11: expected a 'window' line before 'end', found none"},
        {"missing_view", file_with(without(1), good),
         "11: expected a 'view' line before 'end', found none"},
        {"missing_pixels", file_with(without(10), good),
         "11: expected a 'pixels' line before 'end', found none"},
        {"no_end", file_with(without(11), ""),
         "12: expected 'end' closing the header, found the end of the file"},
        {"view_too_big", file_with(replaced(1, "view 20000 3"), good),
         "2: expected a view of 1 to 16384 pixels a side, found 20000 x 3"},
        {"view_zero", file_with(replaced(1, "view 0 3"), good),
         "2: expected a view of 1 to 16384 pixels a side, found 0 x 3"},
        {"view_one_number", file_with(replaced(1, "view 4"), good),
         "2: expected 2 whole numbers after 'view', found '4'"},
        {"view_not_a_number", file_with(replaced(1, "view 4 x"), good),
         "2: expected 2 whole numbers after 'view', found 'x'"},
        {"view_huge_number", file_with(replaced(1, "view 4 99999999999999"), good),
         "2: expected 2 whole numbers after 'view', found '99999999999999'"},
        {"window_outside_view", file_with(replaced(2, "window 1 0 4 2"), good),
         "3: expected a window 'left top right bottom' inside the 4 x 3 view (0 0 3 2), "
         "found 1 0 4 2"},
        {"window_reversed", file_with(replaced(2, "window 2 0 1 2"), good),
         "3: expected a window 'left top right bottom' inside the 4 x 3 view (0 0 3 2), "
         "found 2 0 1 2"},
        {"window_negative", file_with(replaced(2, "window -1 0 2 2"), good),
         "3: expected a window 'left top right bottom' inside the 4 x 3 view (0 0 3 2), "
         "found -1 0 2 2"},
        {"first_finished_row_too_big", file_with(replaced(3, "first_finished_row 4"), good),
         "4: expected a first finished row from 0 to 3 (the window's top row to one past its "
         "bottom row), found 4"},
        {"bad_multiplier", file_with(replaced(4, "display_multiplier nan"), good),
         "5: expected a non-negative number after 'display_multiplier', found 'nan'"},
        {"negative_multiplier", file_with(replaced(4, "display_multiplier -2"), good),
         "5: expected a non-negative number after 'display_multiplier', found '-2'"},
        {"bad_clip", file_with(replaced(5, "display_clip maybe"), good),
         "6: expected 'on' or 'off' after 'display_clip', found 'maybe'"},
        {"unknown_encoding", file_with(replaced(10, "pixels rgb-float16-le"), good),
         "11: expected pixel encoding 'rgb-float32-le', found 'rgb-float16-le'"},
        {"duplicate_key", file_with(replaced(6, "view 4 3"), good),
         "7: expected one 'view' line (the first is line 2), found a second"},
        {"bad_key", file_with(replaced(6, "Scene twocubes"), good),
         "7: expected a 'key value' header line, found 'Scene twocubes'"},
        {"blank_line", file_with(replaced(6, ""), good),
         "7: expected a 'key value' header line, found ''"},
        {"long_line", file_with(replaced(6, "scene " + std::string(5000, 'x')), good),
         "7: expected a header line of at most 4096 characters, found a longer one"},
        {"no_end_before_pixels", file_with(without(11), pixels(72)),
         "12: expected a header line, or 'end' closing the header, found binary data"},
        {"truncated", file_with(header_lines(), pixels(71)),
         "13: expected 72 bytes of pixel data after 'end' (2 x 3 pixels), found 71 (the file is "
         "truncated)"},
        {"no_pixels", file_with(header_lines(), ""),
         "13: expected 72 bytes of pixel data after 'end' (2 x 3 pixels), found 0 (the file is "
         "truncated)"},
        {"trailing_junk", file_with(header_lines(), pixels(73)),
         "13: expected the end of the file after 72 bytes of pixel data, found 1 more byte"},
        {"nan_pixel", file_with(header_lines(), nan_pixels),
         "13: expected finite pixel values, found nan in pixel (2, 0) at byte 207 of the file"},
        {"inf_pixel", file_with(header_lines(), inf_pixels),
         "13: expected finite pixel values, found -inf in pixel (2, 2) at byte 259 of the file"},
        {"huge_view_tiny_file",
         file_with({"GRO rt 1", "view 16384 16384", "window 0 0 16383 16383",
                    "first_finished_row 0", "pixels rgb-float32-le", "end"},
                   pixels(12)),
         "7: expected 3221225472 bytes of pixel data after 'end' (16384 x 16384 pixels), found 12 "
         "(the file is truncated)"},
    };
}

class GroMalformed : public testing::TestWithParam<BadGro> {};

TEST_P(GroMalformed, IsRejectedWithItsMessage) {
    test::TempDir dir;
    const std::filesystem::path file = dir.write(GetParam().name + ".gro", GetParam().content);
    try {
        read_gro(file);
        FAIL() << "read_gro accepted " << GetParam().name;
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), file.string() + ":" + GetParam().message);
    }
}

INSTANTIATE_TEST_SUITE_P(AllCases, GroMalformed, testing::ValuesIn(bad_files()),
                         [](const testing::TestParamInfo<BadGro>& param_info) {
                             return param_info.param.name;
                         });

TEST(GroMalformedBaseline, TheUnmodifiedFileIsValid) {
    test::TempDir dir;
    const Film film = read_gro(dir.write("good.gro", file_with(header_lines(), pixels(72))));
    EXPECT_EQ(film.width(), 2);
    EXPECT_EQ(film.height(), 3);
    EXPECT_EQ(film.pixel(2, 2), (Rgb{0.5, 0.5, 0.5}));
    EXPECT_EQ(film.provenance.switches, "-Dd");
}

}  // namespace
}  // namespace rt
