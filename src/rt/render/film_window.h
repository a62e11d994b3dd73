// The part of the output matrix a run draws. The scene file gives the window (manual 2.2); -L
// "draws only from line L up", and lines are drawn from the bottom up, so a start line cuts the
// window's lower rows away (row 0 is the top row).
#pragma once

#include <optional>

#include "rt/core/bounds.h"

namespace rt {

/// The scene's window, cut at `start_line` when there is one. Throws SettingError ("start
/// line") for a line above the window's top row, which would leave nothing to draw.
PixelRect film_window(const PixelRect& scene_window, std::optional<int> start_line);

}  // namespace rt
