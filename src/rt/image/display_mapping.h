// Linear intensities to 8-bit display values: the -m multiplier and -c clipping (manual Appendix).
#pragma once

#include <array>
#include <cstdint>

#include "rt/core/rgb.h"
#include "rt/image/film.h"
#include "rt/image/image8.h"

namespace rt {

/// One pixel's display values. Each channel is intensity * 255 * multiplier; negative values
/// (and NaN) show as 0. With clipping on (the default), a pixel whose largest channel exceeds 255
/// is scaled down as a whole so that channel is 255, keeping its hue. With clipping off (-c) each
/// rounded value wraps modulo 256, as an 8-bit frame buffer would take its low byte: overexposed
/// pixels then "can give very strange colors".
std::array<std::uint8_t, 3> to_display(const Rgb& intensity, const DisplayMapping& m);

/// The film's window as an 8-bit picture under mapping m. Rows not finished yet
/// (y < film.first_finished_row()) are black.
Image8 to_display(const Film& film, const DisplayMapping& m);

/// The same, under the mapping stored in the film.
inline Image8 to_display(const Film& film) {
    return to_display(film, film.mapping);
}

}  // namespace rt
