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

/// What a PNG's header claims, read without decoding its pixels.
struct PngHeader {
    int width = 0;
    int height = 0;
    std::uint64_t compressed_bytes = 0;  ///< the data of its IDAT chunks, all of them
    /// The bytes read_png holds for it: three a pixel.
    std::uint64_t decoded_bytes() const {
        return static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) * 3;
    }
};

/// Deflate's largest ratio: a 258-byte match in 2 bits (RFC 1951), so no PNG unpacks more than
/// this many bytes from each byte of its IDAT chunks.
inline constexpr std::uint64_t kMaxDeflateRatio = 1032;

/// Reads a PNG's header and walks its chunks (without decompressing them). Throws rt::InputError
/// for a file that is not a PNG, is larger than kMaxImageSide a side, or whose pixel rows (at
/// their bit depth) are more than kMaxDeflateRatio times its IDAT bytes could unpack to;
/// rt::IoError if it cannot be opened.
PngHeader read_png_header(const std::filesystem::path& path);

/// Reads any PNG, converted to 8-bit RGB (alpha dropped, composited on black; 16-bit samples
/// scaled to 8 bits, taken as sRGB like 8-bit ones when the file has no gamma chunk). Throws
/// rt::InputError for a file that is not a readable PNG or that read_png_header refuses (checked
/// before the pixels are allocated), rt::IoError if it cannot be opened.
Image8 read_png(const std::filesystem::path& path);

}  // namespace rt
