// show NAME without --output or --info: the picture in a window (docs/window.md).
#pragma once

#include <filesystem>
#include <string>

#include "rt/image/film.h"

namespace rt::show {

/// The picture show reads, for its window, --info or --output: a .gro or .exr as read, a .png or
/// .ppm as intensities v / 255 (so that at -m1 it looks, and converts, as the file does).
Film read_shown_picture(const std::filesystem::path& path);

/// Shows the film until the window is closed (Esc too) or, on a terminal, Enter is pressed. +
/// and - change the exposure, 0 restores it; the title gives the value under the cursor. Without
/// a display, prints the picture's summary and a hint instead. Returns the exit code: 1 when
/// the display went away under the window, else 0.
int show_in_window(const Film& film, const std::string& name);

}  // namespace rt::show
