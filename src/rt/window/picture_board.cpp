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
              0.0F),
      dirty_{0, view_height - 1} {}

void PictureBoard::show_film(const Film& film) {
    const PixelRect& w = film.window();
    const int top = std::max(w.top, film.first_finished_row());
    const auto row_floats = static_cast<std::size_t>(w.width()) * 3;
    // Under one lock, so that the window never draws a film half copied in (a wireframe whose
    // lower half is still black).
    const std::lock_guard lock(mutex_);
    for (int y = top; y <= w.bottom; ++y) {
        const auto start = static_cast<std::size_t>(y - w.top) * row_floats;
        copy_row(w.left, y, std::span<const float>(film.data()).subspan(start, row_floats));
    }
}

void PictureBoard::show_row(int left, int y, std::span<const float> pixels) {
    const std::lock_guard lock(mutex_);
    copy_row(left, y, pixels);
}

void PictureBoard::copy_row(int left, int y, std::span<const float> pixels) {
    if (y < 0 || y >= height_ || left < 0 || left + static_cast<int>(pixels.size() / 3) > width_) {
        throw std::out_of_range("a row outside the window's picture");
    }
    const auto at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                     static_cast<std::size_t>(left)) *
                    3;
    std::copy(pixels.begin(), pixels.end(), linear_.begin() + static_cast<std::ptrdiff_t>(at));
    dirty_ = dirty_.top > dirty_.bottom ? Rows{y, y}
                                        : Rows{std::min(dirty_.top, y), std::max(dirty_.bottom, y)};
}

DisplayMapping PictureBoard::mapping() const {
    const std::lock_guard lock(mutex_);
    return mapping_;
}

void PictureBoard::set_mapping(const DisplayMapping& mapping) {
    const std::lock_guard lock(mutex_);
    mapping_ = mapping;
    dirty_ = {0, height_ - 1};
}

Rgb PictureBoard::pixel(int x, int y) const {
    const auto at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                     static_cast<std::size_t>(x)) *
                    3;
    const std::lock_guard lock(mutex_);
    return {linear_[at], linear_[at + 1], linear_[at + 2]};
}

PictureBoard::Rows PictureBoard::update(std::vector<std::uint8_t>& rgb) {
    const auto row_floats = static_cast<std::size_t>(width_) * 3;
    std::vector<float> linear;
    DisplayMapping mapping;
    Rows rows;
    {
        const std::lock_guard lock(mutex_);
        rows = dirty_;
        if (rows.top > rows.bottom) {
            return rows;
        }
        dirty_ = {};
        // Copied out, to be mapped outside the lock the renderer's rows wait for.
        linear.assign(
            linear_.begin() + static_cast<std::ptrdiff_t>(rows.top * row_floats),
            linear_.begin() + static_cast<std::ptrdiff_t>((rows.bottom + 1) * row_floats));
        mapping = mapping_;
    }
    rgb.resize(linear_.size());
    const std::size_t start = static_cast<std::size_t>(rows.top) * row_floats;
    for (std::size_t i = 0; i < linear.size(); i += 3) {
        const std::array<std::uint8_t, 3> d =
            to_display(Rgb{linear[i], linear[i + 1], linear[i + 2]}, mapping);
        std::copy(d.begin(), d.end(), rgb.begin() + static_cast<std::ptrdiff_t>(start + i));
    }
    return rows;
}

}  // namespace rt
