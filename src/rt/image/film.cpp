#include "rt/image/film.h"

#include <cstddef>
#include <string>

#include "rt/core/error.h"

namespace rt {

Film::Film(int view_width, int view_height, PixelRect window)
    : view_width_(view_width),
      view_height_(view_height),
      window_(window),
      first_finished_row_(window.bottom + 1),
      data_(
          static_cast<std::size_t>(window.width()) * static_cast<std::size_t>(window.height()) * 3,
          0.0F) {}

namespace {
std::size_t offset_of(const PixelRect& w, int x, int y) {
    return (static_cast<std::size_t>(y - w.top) * static_cast<std::size_t>(w.width()) +
            static_cast<std::size_t>(x - w.left)) *
           3;
}
}  // namespace

Rgb Film::pixel(int x, int y) const {
    const std::size_t i = offset_of(window_, x, y);
    return {data_[i], data_[i + 1], data_[i + 2]};
}

void Film::set_pixel(int x, int y, const Rgb& value) {
    const std::size_t i = offset_of(window_, x, y);
    data_[i] = static_cast<float>(value.r);
    data_[i + 1] = static_cast<float>(value.g);
    data_[i + 2] = static_cast<float>(value.b);
}

void Film::check_consistent() const {
    if (window_.width() <= 0 || window_.height() <= 0) {
        throw Error("the film's window is empty");
    }
    const std::size_t expected =
        static_cast<std::size_t>(window_.width()) * static_cast<std::size_t>(window_.height()) * 3;
    if (data_.size() != expected) {
        throw Error("the film holds " + std::to_string(data_.size()) +
                    " values, but its window needs " + std::to_string(expected));
    }
}

}  // namespace rt
