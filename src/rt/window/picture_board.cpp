#include "rt/window/picture_board.h"

#include <algorithm>
#include <stdexcept>

#include "rt/image/display_mapping.h"

namespace rt {

PictureBoard::PictureBoard(int view_width, int view_height, DisplayMapping mapping)
    : width_(view_width),
      height_(view_height),
      mapping_(mapping),
      linear_(static_cast<std::size_t>(view_width) * static_cast<std::size_t>(view_height) * 3,
              0.0F) {}

void PictureBoard::show_film(const Film& film) {
    const PixelRect& w = film.window();
    const auto row_floats = static_cast<std::size_t>(w.width()) * 3;
    for (int y = std::max(w.top, film.first_finished_row()); y <= w.bottom; ++y) {
        const auto start = static_cast<std::size_t>(y - w.top) * row_floats;
        show_row(w.left, y, std::span<const float>(film.data()).subspan(start, row_floats));
    }
}

void PictureBoard::show_row(int left, int y, std::span<const float> pixels) {
    if (y < 0 || y >= height_ || left < 0 || left + static_cast<int>(pixels.size() / 3) > width_) {
        throw std::out_of_range("a row outside the window's picture");
    }
    const auto at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                     static_cast<std::size_t>(left)) *
                    3;
    const std::lock_guard lock(mutex_);
    std::copy(pixels.begin(), pixels.end(), linear_.begin() + static_cast<std::ptrdiff_t>(at));
    ++version_;
}

DisplayMapping PictureBoard::mapping() const {
    const std::lock_guard lock(mutex_);
    return mapping_;
}

void PictureBoard::set_mapping(const DisplayMapping& mapping) {
    const std::lock_guard lock(mutex_);
    mapping_ = mapping;
    ++version_;
}

Rgb PictureBoard::pixel(int x, int y) const {
    const auto at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                     static_cast<std::size_t>(x)) *
                    3;
    const std::lock_guard lock(mutex_);
    return {linear_[at], linear_[at + 1], linear_[at + 2]};
}

bool PictureBoard::copy_if_changed(std::uint64_t& version, std::vector<std::uint8_t>& rgb) const {
    std::vector<float> linear;
    DisplayMapping mapping;
    {
        const std::lock_guard lock(mutex_);
        if (version == version_) {
            return false;
        }
        version = version_;
        linear = linear_;  // mapped below, outside the lock the renderer's rows wait for
        mapping = mapping_;
    }
    rgb.resize(linear.size());
    for (std::size_t i = 0; i < linear.size(); i += 3) {
        const std::array<std::uint8_t, 3> d =
            to_display(Rgb{linear[i], linear[i + 1], linear[i + 2]}, mapping);
        std::copy(d.begin(), d.end(), rgb.begin() + static_cast<std::ptrdiff_t>(i));
    }
    return true;
}

}  // namespace rt
