// PNG pictures through libpng's simplified API (no setjmp crossing our C++ frames).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "rt/image/image8.h"

namespace rt {

/// image as the bytes of an 8-bit RGB PNG file. Throws rt::Error if libpng refuses.
std::vector<std::uint8_t> encode_png(const Image8& image);

/// Writes image as an 8-bit RGB PNG, atomically. Throws rt::IoError on I/O failure.
void write_png(const Image8& image, const std::filesystem::path& path);

/// Reads any PNG, converted to 8-bit RGB (alpha dropped, composited on black; 16-bit samples
/// scaled to 8 bits, taken as sRGB like 8-bit ones when the file has no gamma chunk). Throws
/// rt::InputError for a file that is not a readable PNG or is larger than kMaxImageSide a side,
/// rt::IoError if it cannot be opened.
Image8 read_png(const std::filesystem::path& path);

}  // namespace rt
