#include "rt/render/film_window.h"

#include <algorithm>
#include <string>

#include "rt/core/error.h"

namespace rt {

PixelRect film_window(const PixelRect& scene_window, std::optional<int> start_line) {
    PixelRect window = scene_window;
    if (!start_line) {
        return window;
    }
    if (*start_line < window.top) {
        throw SettingError("start line", "the start line " + std::to_string(*start_line) +
                                             " is above the window's top row " +
                                             std::to_string(window.top));
    }
    window.bottom = std::min(window.bottom, *start_line);
    return window;
}

}  // namespace rt
