// An 8-bit RGB picture: what a display (or a PNG/PPM file) shows of a film.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rt {

/// The largest width or height any image reader or writer accepts; checked before allocating.
inline constexpr int kMaxImageSide = 16384;

/// Row-major from the top row, three bytes (r, g, b) per pixel.
struct Image8 {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;

    std::size_t pixel_count() const {
        return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    }
    friend bool operator==(const Image8&, const Image8&) = default;
};

}  // namespace rt
