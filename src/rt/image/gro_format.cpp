#include "rt/image/gro_format.h"

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include "rt/core/atomic_file.h"
#include "rt/core/error.h"
#include "rt/image/gro_header.h"
#include "rt/image/image8.h"

#include <fmt/format.h>

namespace rt {

namespace {

constexpr std::size_t kBytesPerValue = 4;

// Byte order is spelled out, so a file reads the same on any host.
void put_float_le(float value, std::uint8_t* out) {
    const auto bits = std::bit_cast<std::uint32_t>(value);
    for (std::size_t i = 0; i < kBytesPerValue; ++i) {
        out[i] = static_cast<std::uint8_t>(bits >> (8 * i));
    }
}

float get_float_le(const std::uint8_t* in) {
    std::uint32_t bits = 0;
    for (std::size_t i = 0; i < kBytesPerValue; ++i) {
        bits |= static_cast<std::uint32_t>(in[i]) << (8 * i);
    }
    return std::bit_cast<float>(bits);
}

}  // namespace

void check_storable(const Film& film) {
    film.check_consistent();
    const PixelRect& w = film.window();
    const auto fail = [](const std::string& why) { throw Error(why); };
    if (film.view_width() < 1 || film.view_height() < 1 || film.view_width() > kMaxImageSide ||
        film.view_height() > kMaxImageSide) {
        fail(fmt::format("the view is {} x {} pixels (at most {} a side)", film.view_width(),
                         film.view_height(), kMaxImageSide));
    }
    if (w.left < 0 || w.top < 0 || w.right >= film.view_width() || w.bottom >= film.view_height()) {
        fail(fmt::format("the window {} {} {} {} is outside the {} x {} view", w.left, w.top,
                         w.right, w.bottom, film.view_width(), film.view_height()));
    }
    if (film.first_finished_row() < w.top || film.first_finished_row() > w.bottom + 1) {
        fail(fmt::format("the first finished row {} is outside the window",
                         film.first_finished_row()));
    }
    if (!std::isfinite(film.mapping.multiplier) || film.mapping.multiplier < 0.0) {
        fail(fmt::format("the display multiplier {} is not a non-negative number",
                         film.mapping.multiplier));
    }
    const std::vector<float>& data = film.data();
    for (std::size_t i = 0; i < data.size(); ++i) {
        if (!std::isfinite(data[i])) {
            const std::size_t pixel = i / 3;
            fail(
                fmt::format("pixel ({}, {}) is not a finite number",
                            w.left + static_cast<int>(pixel % static_cast<std::size_t>(w.width())),
                            w.top + static_cast<int>(pixel / static_cast<std::size_t>(w.width()))));
        }
    }
}

namespace {

void write_pixels(const Film& film, std::ostream& out) {
    const std::size_t row_values = static_cast<std::size_t>(film.width()) * 3;
    std::vector<std::uint8_t> row(row_values * kBytesPerValue);
    const std::vector<float>& data = film.data();
    for (std::size_t start = 0; start < data.size(); start += row_values) {
        for (std::size_t i = 0; i < row_values; ++i) {
            put_float_le(data[start + i], &row[i * kBytesPerValue]);
        }
        out.write(reinterpret_cast<const char*>(row.data()),
                  static_cast<std::streamsize>(row.size()));
    }
}

std::uint64_t file_size_of(const std::filesystem::path& path) {
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) {
        throw IoError("cannot read " + path.string() + ": " + ec.message());
    }
    return size;
}

// Sizes are compared before the film is allocated, so a lying header cannot ask for memory the
// file does not back.
void check_pixel_bytes(const GroHeader& h, std::uint64_t file_size, const std::string& file) {
    const std::uint64_t expected = static_cast<std::uint64_t>(h.window.width()) *
                                   static_cast<std::uint64_t>(h.window.height()) * 3 *
                                   kBytesPerValue;
    const std::uint64_t found = file_size > h.bytes ? file_size - h.bytes : 0;
    const SourceLocation after_end{file, h.lines + 1, 0};
    if (found < expected) {
        throw expected_found(after_end,
                             fmt::format("{} bytes of pixel data after 'end' ({} x {} pixels)",
                                         expected, h.window.width(), h.window.height()),
                             fmt::format("{} (the file is truncated)", found));
    }
    if (found > expected) {
        throw expected_found(
            after_end, fmt::format("the end of the file after {} bytes of pixel data", expected),
            fmt::format("{} more byte{}", found - expected, found - expected == 1 ? "" : "s"));
    }
}

void read_pixels(std::istream& in, const GroHeader& h, Film& film, const std::string& file) {
    const PixelRect& w = h.window;
    const std::size_t row_values = static_cast<std::size_t>(w.width()) * 3;
    std::vector<std::uint8_t> row(row_values * kBytesPerValue);
    std::vector<float>& data = film.data();
    for (int y = w.top; y <= w.bottom; ++y) {
        if (!in.read(reinterpret_cast<char*>(row.data()),
                     static_cast<std::streamsize>(row.size()))) {
            throw IoError("cannot read " + file + ": the file changed while it was read");
        }
        const std::size_t start = static_cast<std::size_t>(y - w.top) * row_values;
        for (std::size_t i = 0; i < row_values; ++i) {
            const float v = get_float_le(&row[i * kBytesPerValue]);
            if (!std::isfinite(v)) {
                const std::uint64_t offset = h.bytes + (start + i) * kBytesPerValue;
                throw expected_found({file, h.lines + 1, 0}, "finite pixel values",
                                     fmt::format("{} in pixel ({}, {}) at byte {} of the file", v,
                                                 w.left + static_cast<int>(i / 3), y, offset));
            }
            data[start + i] = v;
        }
    }
}

// Opens the .gro for reading, with the reason in the error when it cannot be.
std::ifstream open_gro(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        throw IoError("cannot read " + file + ": it is a folder");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw IoError("cannot open " + file + ": " + std::generic_category().message(errno));
    }
    return in;
}

}  // namespace

void write_gro(const Film& film, const std::filesystem::path& path) {
    try {
        check_storable(film);
    } catch (const Error& e) {
        throw Error("cannot write " + path.string() + ": " + e.what());
    }
    const std::string header = format_gro_header(film);
    write_file_atomically(path, [&](std::ostream& out) {
        out.write(header.data(), static_cast<std::streamsize>(header.size()));
        write_pixels(film, out);
    });
}

GroHeader read_gro_header_only(const std::filesystem::path& path) {
    std::ifstream in = open_gro(path);
    GroHeader header = read_gro_header(in, path.string());  // not const: returned by a move
    check_pixel_bytes(header, file_size_of(path), path.string());
    return header;
}

Film read_gro(const std::filesystem::path& path) {
    const std::string file = path.string();
    std::ifstream in = open_gro(path);
    const GroHeader header = read_gro_header(in, file);
    check_pixel_bytes(header, file_size_of(path), file);
    Film film(header.view_width, header.view_height, header.window);
    read_pixels(in, header, film, file);
    film.set_first_finished_row(header.first_finished_row);
    film.mapping = header.mapping;
    film.provenance = header.provenance;
    film.part = header.part;
    return film;
}

}  // namespace rt
