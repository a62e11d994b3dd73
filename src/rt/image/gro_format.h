// The .gro picture file `rt` writes and `show` reads (manual 1.2). The manual never gives its
// layout, so this one is ours: a text header, then the window's pixels as little-endian float32
// RGB. docs/formats.md describes it in full.
#pragma once

#include <filesystem>
#include <string_view>

#include "rt/image/film.h"
#include "rt/image/gro_header.h"

namespace rt {

/// The first line of every .gro file; the number is the format version.
inline constexpr std::string_view kGroMagic = "GRO rt 1";
/// The only pixel encoding so far: linear RGB intensities, IEEE float32, little-endian.
inline constexpr std::string_view kGroPixelEncoding = "rgb-float32-le";

/// Writes film (every window pixel, finished or not, plus its header) to path, atomically: an
/// existing file is replaced only by a complete one. Throws rt::Error if the film cannot be
/// represented (window outside the view, a non-finite pixel, ...) and rt::IoError on I/O failure.
void write_gro(const Film& film, const std::filesystem::path& path);

/// Throws rt::Error saying what a picture file could not hold: an empty or oversized view, a
/// window outside it, a first finished row outside the window, a negative or non-finite display
/// multiplier, a non-finite pixel. Every writer of linear pictures (.gro, .exr) calls it, so that
/// what is written reads back.
void check_storable(const Film& film);

/// Reads a .gro file, validating it strictly. Throws rt::InputError ("file:line: expected ...,
/// found ...") for a malformed file and rt::IoError if it cannot be read.
Film read_gro(const std::filesystem::path& path);

/// Reads and validates a .gro file's header, and checks that the file holds its pixels, without
/// reading or storing them: what `show --info` needs, at any picture size.
GroHeader read_gro_header_only(const std::filesystem::path& path);

}  // namespace rt
