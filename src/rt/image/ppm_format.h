// Binary PPM (P6) pictures: the simplest 8-bit RGB file, written and read without a library.
#pragma once

#include <filesystem>

#include "rt/image/image8.h"

namespace rt {

/// Writes image as a P6 file with maxval 255, atomically. Throws rt::IoError on I/O failure.
void write_ppm(const Image8& image, const std::filesystem::path& path);

/// Reads a P6 file with maxval 255 ('#' comments allowed in the header). Throws rt::InputError
/// for a malformed file, rt::IoError if it cannot be read.
Image8 read_ppm(const std::filesystem::path& path);

}  // namespace rt
