// Picture readers written in the tests from the format descriptions alone (Netpbm's PPM, and
// docs/formats.md for .gro), so that a test reading what rt wrote does not share a bug with rt's
// own readers.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "rt/image/image8.h"

namespace rt::test {

/// A plain (P3) or binary (P6) PPM with maxval 255; '#' comments allowed in the header. Any
/// departure from that fails the calling test and returns an empty picture.
Image8 parse_ppm(const std::string& bytes);

/// The linear intensities of a .gro file, as docs/formats.md lays it out: a text header ending in
/// "end", then the window's pixels from its top row, little-endian float32 red, green, blue.
struct GroPixels {
    std::map<std::string, std::string> header;  ///< key -> value, as written
    int left = 0;                               ///< the window, inclusive, in view pixels
    int top = 0;
    int right = -1;
    int bottom = -1;
    std::vector<std::array<double, 3>> pixels;  ///< row by row from the window's top

    /// The pixel at view coordinates (x, y), which must lie in the window.
    const std::array<double, 3>& at(int x, int y) const;
};

/// Fails the calling test (and returns an empty GroPixels) if the file does not follow the layout.
GroPixels parse_gro(const std::filesystem::path& path);

}  // namespace rt::test
