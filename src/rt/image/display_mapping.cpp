#include "rt/image/display_mapping.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace rt {

namespace {

// Large enough to saturate any display, small enough that scaling stays finite.
constexpr double kLargestValue = 1.0e30;

double display_value(double intensity, double multiplier) {
    const double v = intensity * 255.0 * multiplier;
    if (!(v > 0.0)) {  // negative, zero or NaN
        return 0.0;
    }
    return std::min(v, kLargestValue);
}

// The low byte of the rounded value, as an 8-bit frame buffer register keeps it.
std::uint8_t wrapped(double v) {
    return static_cast<std::uint8_t>(std::fmod(std::round(v), 256.0));
}

}  // namespace

std::array<std::uint8_t, 3> to_display(const Rgb& intensity, const DisplayMapping& m) {
    std::array<double, 3> v{};
    for (int c = 0; c < 3; ++c) {
        v[static_cast<std::size_t>(c)] = display_value(intensity[c], m.multiplier);
    }
    std::array<std::uint8_t, 3> out{};
    if (!m.clip) {
        for (std::size_t c = 0; c < 3; ++c) {
            out[c] = wrapped(v[c]);
        }
        return out;
    }
    // Scaling the whole pixel (not clamping each channel) keeps its hue (manual, -m).
    const double largest = std::max({v[0], v[1], v[2]});
    const double scale = largest > 255.0 ? 255.0 / largest : 1.0;
    for (std::size_t c = 0; c < 3; ++c) {
        out[c] = static_cast<std::uint8_t>(std::min(255.0, std::round(v[c] * scale)));
    }
    return out;
}

Image8 to_display(const Film& film, const DisplayMapping& m) {
    film.check_consistent();
    const PixelRect& w = film.window();
    Image8 image;
    image.width = w.width();
    image.height = w.height();
    image.rgb.assign(image.pixel_count() * 3, 0);
    const int first_row = std::max(film.first_finished_row(), w.top);
    for (int y = first_row; y <= w.bottom; ++y) {
        for (int x = w.left; x <= w.right; ++x) {
            const std::array<std::uint8_t, 3> rgb = to_display(film.pixel(x, y), m);
            const std::size_t i =
                (static_cast<std::size_t>(y - w.top) * static_cast<std::size_t>(image.width) +
                 static_cast<std::size_t>(x - w.left)) *
                3;
            std::copy(rgb.begin(), rgb.end(), image.rgb.begin() + static_cast<std::ptrdiff_t>(i));
        }
    }
    return image;
}

}  // namespace rt
