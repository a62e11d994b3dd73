// A PNG picture a texture map lays on its grid (-V: colour maps and normal maps), and how a point
// of the grid reads it (docs/formats.md, "Pictures on the grid").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rt/core/rgb.h"

namespace rt {

/// Row-major from the top row, three bytes (r, g, b) per pixel, as rt::read_png gives them.
struct TextureImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;
    std::string name;  ///< the file, as the texture map names it
};

/// The picture at (x, y), in pixels from its top left corner (pixel (i, j) covers [i, i + 1) x
/// [j, j + 1)): bilinear between the four nearest pixel centres, the border pixels continued
/// outward. Each channel is the byte over 255: 0 to 1.
Rgb sample_bilinear(const TextureImage& image, double x, double y);

}  // namespace rt
